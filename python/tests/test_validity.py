"""Validity checkers written in Python: scalar, vectorised, and their exceptions."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest

import mit_star


def test_a_python_checker_is_what_the_planner_obeys(walls4: mit_star.Problem) -> None:
    calls = []

    def valid(state: np.ndarray) -> bool:
        calls.append(state.shape)
        return walls4.is_valid(state)

    for name in mit_star.planners():
        calls.clear()
        result = mit_star.Planner(name, walls4, seed=2, validity=valid).solve(
            time=2.0, first_solution=True
        )
        assert result.solved, name
        assert calls and all(shape == (4,) for shape in calls)
        assert all(walls4.is_valid(s) for s in result.path)


def test_a_python_checker_forbids_what_the_world_allows() -> None:
    # An empty square; the checker adds a wall at x = 0 with a gap above y = 0.5.
    problem = mit_star.Problem.boxes(
        np.array([-1.0, -1.0]), np.array([1.0, 1.0]), np.array([-0.5, 0.0]),
        np.array([0.5, 0.0]), resolution=1e-3,
    )

    def valid(state: np.ndarray) -> bool:
        return not (abs(state[0]) < 0.1 and state[1] < 0.5)

    result = mit_star.MitStar(problem, seed=4, validity=valid).solve(time=0.5)
    assert result.solved
    assert all(valid(s) for s in result.path)
    assert result.cost > 2 * np.hypot(0.4, 0.5)  # around the wall, not through it


def sizes_recorded(problem: mit_star.Problem) -> tuple[list[int], Callable[[np.ndarray], np.ndarray]]:
    """A vectorised checker of `problem` that records how many states each call got."""
    sizes: list[int] = []

    def valid_many(states: np.ndarray) -> np.ndarray:
        assert states.ndim == 2 and states.shape[1] == 4
        sizes.append(len(states))
        return np.array([problem.is_valid(s) for s in states])

    return sizes, valid_many


def test_a_vectorised_checker_gets_batches(walls4: mit_star.Problem) -> None:
    sizes, valid_many = sizes_recorded(walls4)
    planner = mit_star.MitStar(walls4, seed=3, vectorized=valid_many, batch=32)
    result = planner.solve(time=2.0, first_solution=True)
    assert result.solved
    assert max(sizes) > 1 and max(sizes) <= 32


def test_a_batch_is_never_exceeded(walls4: mit_star.Problem) -> None:
    # With a batch of two segment searches' points (2 x 8) the adaptive sampler searches the
    # segments of all its candidates' failed repairs together; the checker still gets them
    # at most `batch` at a time.
    sizes, valid_many = sizes_recorded(walls4)
    planner = mit_star.MitStar(walls4, seed=3, vectorized=valid_many, batch=16)
    # Seed 3 meets a lookahead batch with three failed repairs within 5 000 iterations: 23
    # points, once, before each call was cut to the batch.
    assert planner.solve(iterations=5000).solved
    assert max(sizes) == 16


def test_a_batch_wider_than_the_poll_period_is_handed_whole(walls4: mit_star.Problem) -> None:
    sizes, valid_many = sizes_recorded(walls4)
    planner = mit_star.MitStar(walls4, seed=3, vectorized=valid_many, batch=100)
    assert planner.solve(time=2.0, first_solution=True).solved
    assert max(sizes) > 32 and max(sizes) <= 100
    with pytest.raises(ValueError, match="batch"):
        mit_star.MitStar(walls4, vectorized=valid_many, batch=2000)


def test_vectorised_and_scalar_agree(walls4: mit_star.Problem) -> None:
    def one(state: np.ndarray) -> bool:
        return walls4.is_valid(state)

    def many(states: np.ndarray) -> list:
        return [walls4.is_valid(s) for s in states]  # a list is accepted too

    a = mit_star.EitStar(walls4, seed=9, validity=one).solve(iterations=2000)
    # One state per call: the sampler draws as it does for the scalar checker, so the same
    # answers give the same plan.
    b = mit_star.EitStar(walls4, seed=9, validity=one, vectorized=many, batch=1)
    b = b.solve(iterations=2000)
    assert a.cost == b.cost
    np.testing.assert_array_equal(a.path, b.path)
    # Wider batches: the sampler draws a batch of candidates ahead (another random sequence of
    # the same law), and the plan is as valid.
    c = mit_star.EitStar(walls4, seed=9, vectorized=many).solve(iterations=2000)
    assert c.solved and all(walls4.is_valid(s) for s in c.path)


class Boom(Exception):
    pass


@pytest.mark.parametrize("name", ["mit-star", "rrt-connect", "informed-rrt-star"])
def test_an_exception_in_the_checker_stops_the_planner(walls4, name) -> None:
    calls = [0]

    def valid(state: np.ndarray) -> bool:
        calls[0] += 1
        if calls[0] == 500:
            raise Boom("at call 500")
        return walls4.is_valid(state)

    planner = mit_star.Planner(name, walls4, seed=1, validity=valid)
    with pytest.raises(Boom, match="at call 500"):
        planner.solve(time=10.0)
    # Stopped cleanly: a handful of calls after the exception at most, none after returning.
    after = calls[0]
    assert after < 600
    # The planner can go on (the checker no longer raises after call 500).
    assert planner.solve(time=0.5).solved
    assert calls[0] > after


def test_an_exception_in_the_vectorised_checker(walls4: mit_star.Problem) -> None:
    def many(states: np.ndarray) -> np.ndarray:
        raise ZeroDivisionError("vectorised")

    with pytest.raises(ZeroDivisionError, match="vectorised"):
        mit_star.MitStar(walls4, vectorized=many).solve(time=5.0)


def test_a_wrong_answer_shape_is_a_value_error(walls4: mit_star.Problem) -> None:
    def many(states: np.ndarray) -> np.ndarray:
        return np.ones(len(states) + 1, dtype=bool)

    with pytest.raises(ValueError, match="answers"):
        mit_star.MitStar(walls4, vectorized=many).solve(time=5.0)


def test_a_start_the_checker_refuses_is_a_planning_error(walls4: mit_star.Problem) -> None:
    # The query is checked when the planner is built.
    with pytest.raises(mit_star.PlanningError, match="start"):
        mit_star.MitStar(walls4, validity=lambda s: s[0] > -0.4)


def test_a_python_checker_on_an_arm(box_panda) -> None:
    problem = mit_star.Problem.mbm(box_panda, 1)
    calls = [0]

    def valid(q: np.ndarray) -> bool:
        calls[0] += 1
        return problem.is_valid(q)

    result = mit_star.RrtConnect(problem, seed=2, validity=valid).solve(time=10.0)
    assert result.solved and calls[0] > 0
    assert all(problem.is_valid(q) for q in result.path)
