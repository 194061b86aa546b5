"""Problems: PDT families, problem files, box worlds from numpy arrays, MotionBenchMaker."""

from __future__ import annotations

import numpy as np
import pytest

import mit_star
from conftest import REPOSITORY


def test_listings_name_every_planner_and_family() -> None:
    assert mit_star.planners()[:2] == ["mit-star", "eit-star"]
    assert len(mit_star.planners()) == 13
    assert "fcit-star" in mit_star.planners()
    names = [name for name, _ in mit_star.problem_families()]
    assert "dividing-walls" in names and "goal-enclosure" in names
    assert "panda" in mit_star.robots()
    assert "smoke" in [name for name, _ in mit_star.experiments()]


def test_a_family_by_name_and_dimension(walls4: mit_star.Problem) -> None:
    assert walls4.dimension == 4
    assert walls4.start.shape == (4,)
    assert walls4.goals.shape == (1, 4)
    lower, upper = walls4.bounds
    assert np.all(lower < upper)
    assert walls4.optimum is not None and walls4.optimum > 0
    assert walls4.resolution == pytest.approx(1e-4)
    assert not walls4.is_arm
    assert walls4.is_valid(walls4.start)


def test_problem_files() -> None:
    files = sorted((REPOSITORY / "problems" / "examples").glob("*.toml"))
    assert files
    problem = mit_star.Problem.from_file(files[0])
    assert problem.dimension >= 2
    assert mit_star.Problem(str(files[0])).id == problem.id


def test_a_box_world_from_numpy_arrays() -> None:
    problem = mit_star.Problem.boxes(
        lower=np.array([-1.0, -1.0]),
        upper=np.array([1.0, 1.0]),
        start=np.array([-0.8, 0.0]),
        goal=np.array([0.8, 0.0]),
        centers=np.array([[0.0, -0.2]]),
        widths=np.array([[0.2, 1.6]]),
        resolution=1e-3,
    )
    assert problem.dimension == 2
    assert not problem.is_valid(np.array([0.0, 0.0]))
    assert problem.is_valid(np.array([0.0, 0.9]))
    result = mit_star.MitStar(problem, seed=1).solve(time=0.2)
    assert result.solved and result.cost > 1.6


def test_lists_and_integer_arrays_are_taken_wherever_arrays_are() -> None:
    # Before, a list or an integer array raised TypeError ("argument 'lower': ... cannot be
    # converted to 'PyArray<f64, ...>'").
    from_lists = mit_star.Problem.boxes(
        lower=[-1, -1], upper=np.array([1, 1]), start=(-0.8, 0.0), goal=[0.8, 0],
        centers=[[0, -0.2]], widths=np.array([[0.2, 1.6]], dtype=np.float32),
        resolution=1e-3,
    )
    assert from_lists.dimension == 2
    assert not from_lists.is_valid([0, 0]) and from_lists.is_valid(np.array([0, 1]) * 0.9)
    several = mit_star.Problem.boxes([-1, -1], [1, 1], [-0.8, 0], [[0.8, 0], [0.8, 0.5]])
    assert mit_star.RrtConnect(several, seed=1).solve(time=1.0).solved
    with pytest.raises(TypeError, match="lower must be an array of numbers"):
        mit_star.Problem.boxes(["a", "b"], [1, 1], [0, 0], [0.5, 0.5])
    with pytest.raises(ValueError, match=r"start must have shape \(d,\)"):
        mit_star.Problem.boxes([-1, -1], [1, 1], [[0, 0]], [0.5, 0.5])


def test_bad_inputs_raise_python_exceptions() -> None:
    with pytest.raises(ValueError, match="dividing-wall"):
        mit_star.Problem("dividing-wall", 4)
    with pytest.raises(ValueError):
        mit_star.Problem("dividing-walls", 4, resolution=2.0)
    with pytest.raises(ValueError, match="shape"):
        mit_star.Problem.boxes(
            np.zeros(2) - 1, np.ones(2), np.zeros(2), np.ones(2) * 0.5,
            centers=np.zeros((1, 3)), widths=np.ones((1, 3)),
        )
    with pytest.raises(ValueError):  # the start inside an obstacle
        mit_star.Problem.boxes(
            np.zeros(2) - 1, np.ones(2), np.zeros(2), np.ones(2) * 0.5,
            centers=np.zeros((1, 2)), widths=np.ones((1, 2)) * 0.1,
        )
    with pytest.raises(TypeError):
        mit_star.Problem.boxes(np.zeros(2) - 1, np.ones(2), np.zeros(2), "goal")
    with pytest.raises(ValueError):
        mit_star.Problem.mbm("/nonexistent/folder")


def test_a_motionbenchmaker_problem(box_panda) -> None:
    problem = mit_star.Problem.mbm(box_panda, 1)
    assert problem.is_arm and problem.dimension == 7
    assert mit_star.Problem(f"mbm:{box_panda}", instance=1, robot="panda").id == problem.id
    result = mit_star.RrtConnect(problem, seed=2).solve(time=5.0)
    assert result.solved
    assert result.path.shape[1] == 7
    np.testing.assert_array_equal(result.path[0], problem.start)
    with pytest.raises(ValueError, match="robot"):
        mit_star.Problem.mbm(box_panda, 1, robot="no-such-robot")
