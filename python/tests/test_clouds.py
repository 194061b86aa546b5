"""Point clouds from numpy arrays and files as obstacles of an arm problem."""

from __future__ import annotations

import numpy as np
import pytest

import mit_star


def cube(center, side: float, n: int) -> np.ndarray:
    axis = np.linspace(-side / 2, side / 2, n)
    grid = np.stack(np.meshgrid(axis, axis, axis), axis=-1).reshape(-1, 3)
    return grid + np.asarray(center)


def test_a_numpy_cloud_on_the_robot_is_named(box_panda) -> None:
    # Points through the Panda's base, where every configuration keeps it.
    points = cube([0.0, 0.0, 0.1], 0.08, 5).astype(np.float32)
    with pytest.raises(ValueError, match="cloud point"):
        mit_star.Problem.mbm(box_panda, 1, cloud=points)
    # NaN rows are dropped; far points leave the problem as it was.
    far = np.vstack([cube([0.0, 0.0, 3.0], 0.1, 3), [[np.nan, 0.0, 0.0]]])
    problem = mit_star.Problem.mbm(box_panda, 1, cloud=far)
    assert problem.is_arm
    # Lists and integer arrays are converted.
    high = [[0, 0, 3], [1, 1, 3]]
    assert mit_star.Problem.mbm(box_panda, 1, cloud=high).is_arm
    assert mit_star.Problem.mbm(box_panda, 1, cloud=np.array(high)).is_arm


def test_the_scene_seen_as_a_cloud_is_planned_in(box_panda, tmp_path) -> None:
    saved = tmp_path / "scene.npy"
    problem = mit_star.Problem.mbm(
        box_panda, 1, scene_as_cloud=2000, crop_reach=True, voxel=0.02, save_cloud=saved
    )
    result = mit_star.RrtConnect(problem, seed=2).solve(time=5.0)
    assert result.solved
    np.testing.assert_array_equal(result.path[0], problem.start)
    # The saved cloud, alone, as a numpy array and as a file.
    points = np.load(saved)
    assert points.ndim == 2 and points.shape[1] == 3 and points.dtype == np.float32
    alone = mit_star.Problem.mbm(box_panda, 1, cloud=points, drop_primitives=True)
    assert mit_star.RrtConnect(alone, seed=2).solve(time=5.0).solved
    again = mit_star.Problem.mbm(box_panda, 1, cloud_files=[saved], drop_primitives=True)
    assert mit_star.RrtConnect(again, seed=2).solve(time=5.0).solved


def test_bad_clouds_are_refused(box_panda) -> None:
    with pytest.raises(ValueError, match=r"\(N, 3\)"):
        mit_star.Problem.mbm(box_panda, 1, cloud=np.zeros((4, 2)))
    with pytest.raises(ValueError):
        mit_star.Problem.mbm(box_panda, 1, cloud=[["a", "b", "c"]])
    with pytest.raises(ValueError, match="cloud"):
        mit_star.Problem.mbm(box_panda, 1, cloud=np.full((2, 3), np.nan))
    with pytest.raises(ValueError, match="voxel"):
        mit_star.Problem.mbm(box_panda, 1, scene_as_cloud=100, voxel=-1.0)
