"""A hand pose as an arm problem's goal: inverse kinematics draws the goal configurations."""

from __future__ import annotations

import numpy as np
import pytest

import mit_star


def test_a_planner_reaches_the_hand_pose_of_the_goal(box_panda) -> None:
    problem = mit_star.Problem.mbm(box_panda, 1).with_goal_pose("panda_hand")
    for planner in ("rrt-connect", "aorrtc"):
        result = mit_star.Planner(planner, problem, seed=1).solve(time=1.0)
        assert result.solved, planner
        np.testing.assert_array_equal(result.path[0], problem.start)
    settings = dict(mit_star.Planner("rrt-connect", problem).settings)
    assert settings["max_goals"] == "8"


def test_a_pose_with_tolerances_from_numbers(box_panda) -> None:
    # Above the box, pointing down, within 2 cm, turning freely about the approach axis.
    problem = mit_star.Problem.mbm(box_panda, 1).with_goal_pose(
        "panda_hand",
        np.array([0.3, 0.0, 0.8, 1.0, 0.0, 0.0, 0.0]),
        position_tolerance=0.02,
        orientation_tolerance="axis:z",
        ik_goals=2,
    )
    result = mit_star.Planner("rrt-connect", problem, seed=3).solve(time=1.0)
    assert result.solved


def test_bad_pose_goals_are_named(box_panda, walls4) -> None:
    problem = mit_star.Problem.mbm(box_panda, 1)
    with pytest.raises(ValueError, match="panda_nose"):
        problem.with_goal_pose("panda_nose")
    with pytest.raises(ValueError, match="norm 0"):
        problem.with_goal_pose("panda_hand", [0, 0, 0.5, 0, 0, 0, 0])
    with pytest.raises(TypeError, match="sequence of numbers"):
        problem.with_goal_pose("panda_hand", 3.0)
    with pytest.raises(ValueError, match="box world"):
        walls4.with_goal_pose("panda_hand")
    with pytest.raises(ValueError, match="validity"):
        mit_star.Planner(
            "rrt-connect", problem.with_goal_pose("panda_hand"), validity=lambda q: True
        )
