"""Planners by name with keyword parameters; solve and what it returns."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mit_star


@pytest.mark.parametrize("name", mit_star.planners())
def test_every_planner_solves_and_reports(walls4: mit_star.Problem, name: str) -> None:
    planner = mit_star.Planner(name, walls4, seed=3)
    result = planner.solve(time=1.0, first_solution=True)
    assert result.solved, name
    assert result.path.shape[1] == 4 and result.path.dtype == np.float64
    np.testing.assert_array_equal(result.path[0], walls4.start)
    np.testing.assert_array_equal(result.path[-1], walls4.goals[0])
    assert result.cost >= walls4.optimum - 1e-9
    assert result.trace and result.trace[-1][1] == pytest.approx(result.cost)
    assert isinstance(result.counters, dict) and result.counters["iterations"] > 0
    assert result.planner == planner.name


def test_configuration_constructors_and_parameters(walls4: mit_star.Problem) -> None:
    planner = mit_star.MitStar(walls4, seed=7, batch_size=50, rewire_factor=1.2)
    assert planner.name == "MIT*" and planner.configuration == "mit-star"
    settings = dict(planner.settings)
    assert settings["batch_size"] == "50"
    assert mit_star.EitStar(walls4).name == "EIT*"
    assert mit_star.Planner("mit_star_sc", walls4).name == "MIT*-SC"


def test_anytime_improves_across_calls_and_clear_restarts(walls4: mit_star.Problem) -> None:
    planner = mit_star.MitStar(walls4, seed=1)
    first = planner.solve(first_solution=True, time=1.0)
    later = planner.solve(time=0.3)
    assert later.cost <= first.cost
    assert planner.best_cost == later.cost
    costs = [c for _, c in planner.trace]
    assert all(b < a for a, b in zip(costs, costs[1:]))
    planner.clear()
    assert math.isinf(planner.best_cost) and planner.trace == []


def test_same_seed_same_path(walls4: mit_star.Problem) -> None:
    a = mit_star.MitStar(walls4, seed=5).solve(iterations=3000)
    b = mit_star.MitStar(walls4, seed=5).solve(iterations=3000)
    np.testing.assert_array_equal(a.path, b.path)


def test_no_solution_is_not_an_error() -> None:
    problem = mit_star.Problem("dividing-walls", 8)
    result = mit_star.MitStar(problem).solve(iterations=1)
    assert not result.solved and result.path is None and math.isinf(result.cost)


def test_bad_planner_arguments(walls4: mit_star.Problem) -> None:
    with pytest.raises(ValueError, match="unknown planner"):
        mit_star.Planner("rrt", walls4)
    with pytest.raises(ValueError, match="batch_size"):
        mit_star.MitStar(walls4, batch_size=0)
    with pytest.raises(ValueError, match="unknown parameter"):
        mit_star.MitStar(walls4, no_such_parameter=1)
    with pytest.raises(TypeError):
        mit_star.MitStar(walls4, batch_size=[1])
    # A parameter the planner does not read is refused, naming those that read it (before, MIT*
    # took `range` and ignored it).
    with pytest.raises(ValueError, match=r"MIT\* does not read the parameter `range`.*RRT-Connect"):
        mit_star.MitStar(walls4, range=0.5)
    with pytest.raises(ValueError, match="RRT-Connect does not read the parameter `batch_size`"):
        mit_star.RrtConnect(walls4, batch_size=10)
    assert mit_star.RrtConnect(walls4, range=0.5).solve(time=1.0).solved
    with pytest.raises(TypeError):
        mit_star.MitStar(walls4, validity=3)
    planner = mit_star.MitStar(walls4)
    with pytest.raises(ValueError, match="never returns"):
        planner.solve()
    with pytest.raises(ValueError, match="time"):
        planner.solve(time=-1.0)
    with pytest.raises(ValueError, match="time"):
        planner.solve(time=float("nan"))


def test_version_and_planner_signatures() -> None:
    import importlib.metadata
    import inspect

    assert mit_star.__version__ == importlib.metadata.version("mit-star")
    # help() shows the parameters the planner reads, not **params (before: `build(problem,
    # **params)` for every planner).
    mit = inspect.signature(mit_star.MitStar).parameters
    assert {"problem", "seed", "batch_size", "rewire_factor", "eis_batch_size"} <= set(mit)
    assert "range" not in mit
    rrt = inspect.signature(mit_star.RrtConnect).parameters
    assert "range" in rrt and "batch_size" not in rrt
    assert "batch_size = " in (mit_star.MitStar.__doc__ or "")
    assert dict(mit_star.planner_parameters("rrt-connect"))["rrt_balance"] in ("true", "false")

