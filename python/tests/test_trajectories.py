"""Planned arm paths timed under the robot's limits, returned as numpy arrays."""

from __future__ import annotations

import numpy as np
import pytest

import mit_star
from conftest import REPOSITORY

LIMITS = REPOSITORY / "robot" / "data" / "panda" / "joint_limits.yaml"


def test_a_planned_path_timed_within_the_limits(box_panda) -> None:
    problem = mit_star.Problem.mbm(box_panda, 1)
    result = mit_star.RrtConnect(problem, seed=4).solve(time=1.0)
    assert result.solved
    timed = mit_star.time_parameterise(problem, result.path, joint_limits=LIMITS)
    t, q, qd, qdd = timed["time"], timed["position"], timed["velocity"], timed["acceleration"]
    assert len(timed["joints"]) == problem.dimension == q.shape[1]
    assert np.all(np.diff(t) > 0) and t[0] == 0.0
    assert timed["duration"] == pytest.approx(t[-1])
    np.testing.assert_allclose(q[0], problem.start)
    np.testing.assert_allclose(q[-1], result.path[-1])
    np.testing.assert_array_equal(qd[0], 0.0)
    np.testing.assert_array_equal(qd[-1], 0.0)
    assert qdd.shape == q.shape
    # Half the velocity, a period: slower, sampled evenly.
    slow = mit_star.time_parameterise(
        problem,
        result.path.tolist(),
        corners="stop",
        joint_limits=LIMITS,
        velocity_scaling=0.5,
        sample_period=0.01,
    )
    assert slow["duration"] > timed["duration"]
    assert slow["corners"] is None
    np.testing.assert_allclose(np.diff(slow["time"])[:-1], 0.01, atol=1e-12)


def test_bad_requests_are_named(box_panda, walls4) -> None:
    problem = mit_star.Problem.mbm(box_panda, 1)
    path = np.vstack([problem.start, problem.goals[0]])
    with pytest.raises(ValueError, match="acceleration"):
        mit_star.time_parameterise(problem, path)  # the URDF has no accelerations
    with pytest.raises(ValueError, match="scaling"):
        mit_star.time_parameterise(problem, path, max_acceleration=5.0, velocity_scaling=0.0)
    with pytest.raises(ValueError, match="corners"):
        mit_star.time_parameterise(problem, path, max_acceleration=5.0, corners="round")
    with pytest.raises(ValueError, match="arm problems"):
        mit_star.time_parameterise(walls4, [[0.0] * 4, [0.1] * 4], max_acceleration=5.0)
    with pytest.raises(ValueError):
        mit_star.time_parameterise(problem, path[:1], max_acceleration=5.0)
