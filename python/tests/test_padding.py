"""`padding=`: a distance kept between the robot's spheres and every obstacle, from Python."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mit_star

PADDING = 0.01


def test_padding_only_removes_states(box_panda) -> None:
    plain = mit_star.Problem.mbm(box_panda, 1)
    padded = mit_star.Problem.mbm(box_panda, 1, padding=PADDING)
    low, high = plain.bounds
    states = np.random.default_rng(3).uniform(low, high, size=(3000, plain.dimension))
    plain_valid = np.array([plain.is_valid(q) for q in states])
    padded_valid = np.array([padded.is_valid(q) for q in states])
    # Padding grows the spheres against obstacles: it never makes an invalid state valid, and
    # among random arm states some lie within 10 mm of the box or table.
    assert not np.any(padded_valid & ~plain_valid)
    assert np.count_nonzero(plain_valid & ~padded_valid) > 0


def test_a_padded_plan_is_valid_for_the_padded_problem_along_its_motion(box_panda) -> None:
    padded = mit_star.Problem.mbm(box_panda, 1, padding=PADDING)
    result = mit_star.RrtConnect(padded, seed=2).solve(time=5.0, first_solution=True)
    assert result.solved
    path = result.path
    assert np.allclose(path[0], padded.start)
    # Every state on a fine interpolation of each edge keeps the padding (the planner's own
    # guarantee is continuous; this samples it at a step far below the padding's reach).
    for a, b in zip(path[:-1], path[1:]):
        steps = max(2, math.ceil(np.linalg.norm(b - a) / 0.005))
        for t in np.linspace(0.0, 1.0, steps + 1):
            assert padded.is_valid(a + t * (b - a)), (a, b, t)


@pytest.mark.parametrize("value", [-0.01, 1.5, float("nan")])
def test_a_padding_out_of_range_names_padding(box_panda, value) -> None:
    with pytest.raises(ValueError, match="padding"):
        mit_star.Problem.mbm(box_panda, 1, padding=value)


def test_a_box_world_refuses_padding() -> None:
    with pytest.raises(ValueError, match="padding"):
        mit_star.Problem("dividing-walls", 4, padding=PADDING)
