"""Time to a first solution with a validity checker written in Python: mit_star (MIT*, EIT*)
against OMPL's Python bindings (the `ompl` 2.0.1 wheel: BIT* and RRT-Connect; the wheel binds
no EIT*) on the same problem — PDT's dividing walls in R^4 at the same resolution — with the
same pure-Python checker (OMPL's states are indexed the same way).

    pip install ompl
    python python/benchmarks/vs_ompl.py --runs 10 --resolution 1e-3 --time 30
"""

from __future__ import annotations

import argparse
import statistics
import time

import mit_star
from dw_checker import check_agreement, scalar_checker
from ompl import base as ob
from ompl import geometric as og
from ompl import util as ou


def ours(problem, name, seed, budget, valid):
    started = time.perf_counter()
    planner = mit_star.Planner(name, problem, seed=seed, validity=valid)
    result = planner.solve(time=budget, first_solution=True)
    return time.perf_counter() - started, result.solved, result.cost


def ompl_plan(problem, name, budget, valid):
    started = time.perf_counter()
    d = problem.dimension
    lower, upper = problem.bounds
    space = ob.RealVectorStateSpace(d)
    bounds = ob.RealVectorBounds(d)
    for i in range(d):
        bounds.setLow(i, float(lower[i]))
        bounds.setHigh(i, float(upper[i]))
    space.setBounds(bounds)
    setup = og.SimpleSetup(space)
    setup.setStateValidityChecker(valid)
    info = setup.getSpaceInformation()
    info.setStateValidityCheckingResolution(problem.resolution)
    start, goal = space.allocState(), space.allocState()
    for i in range(d):
        start[i] = float(problem.start[i])
        goal[i] = float(problem.goals[0][i])
    setup.setStartAndGoalStates(start, goal)
    objective = ob.PathLengthOptimizationObjective(info)
    objective.setCostThreshold(ob.Cost(float("inf")))  # any solution satisfies: stop at the first
    setup.setOptimizationObjective(objective)
    planner = {"bit-star": og.BITstar, "rrt-connect": og.RRTConnect}[name](info)
    setup.setPlanner(planner)
    stop = ob.plannerOrTerminationCondition(
        ob.timedPlannerTerminationCondition(budget),
        ob.exactSolnPlannerTerminationCondition(setup.getProblemDefinition()),
    )
    setup.solve(stop)
    solved = setup.haveExactSolutionPath()
    cost = setup.getSolutionPath().length() if solved else float("inf")
    return time.perf_counter() - started, solved, cost


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--resolution", type=float, default=1e-3)
    parser.add_argument("--time", type=float, default=30.0, help="budget per run, seconds")
    args = parser.parse_args()
    ou.setLogLevel(ou.LogLevel.LOG_WARN)
    problem = mit_star.Problem("dividing-walls", 4, resolution=args.resolution)
    check_agreement(problem)
    valid = scalar_checker(problem)
    rows = {}
    for run in range(args.runs):
        for label, plan in (
            ("mit_star MIT*", lambda s: ours(problem, "mit-star", s, args.time, valid)),
            ("mit_star EIT*", lambda s: ours(problem, "eit-star", s, args.time, valid)),
            ("mit_star RRT-Connect", lambda s: ours(problem, "rrt-connect", s, args.time, valid)),
            ("OMPL BIT*", lambda s: ompl_plan(problem, "bit-star", args.time, valid)),
            ("OMPL RRT-Connect", lambda s: ompl_plan(problem, "rrt-connect", args.time, valid)),
        ):
            rows.setdefault(label, []).append(plan(run))
    print(
        f"time to first solution, {problem.id} at resolution {args.resolution:g}, pure-Python "
        f"checker, {args.runs} runs, budget {args.time:g} s (unsolved runs count as inf):"
    )
    for label, results in rows.items():
        times = [t if solved else float("inf") for t, solved, _ in results]
        costs = [c for _, solved, c in results if solved]
        print(
            f"  {label:22} median {statistics.median(times) * 1000:9.1f} ms, solved "
            f"{sum(s for _, s, _ in results)}/{len(results)}, median first cost "
            f"{statistics.median(costs) if costs else float('inf'):.3f}"
        )


if __name__ == "__main__":
    main()
