"""mit-star from Python: MIT*, EIT*, their ablations and the comparison planners (AIT*, BIT*,
ABIT*, RRT-Connect, AORRTC, Informed RRT*), planning at Rust speed.

>>> import mit_star
>>> problem = mit_star.Problem("dividing-walls", 4)
>>> planner = mit_star.MitStar(problem, seed=7, batch_size=100)
>>> result = planner.solve(time=0.3)
>>> result.path.shape[1], result.cost >= problem.optimum
(4, True)

A validity checker written in Python replaces the problem's own (the problem still gives the
bounds, start, goals and resolution)::

    def valid(state):            # state: float array of shape (d,)
        return abs(state[0]) > 0.1 or abs(state[1]) < 0.2
    planner = mit_star.Planner("eit-star", problem, validity=valid)

Planning releases the GIL; Ctrl-C stops a solve (``KeyboardInterrupt``); an exception raised
by the checker stops the planner and is raised from ``solve``.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from typing import Any

from ._native import (
    ExperimentResults,
    Planner,
    PlanningError,
    Problem,
    SolveResult,
    __version__,
    experiments,
    planner_parameters,
    planners,
    problem_families,
    read_results,
    robots,
    run_experiment,
    time_parameterise,
    write_view,
)

__all__ = [
    "AbitStar",
    "AitStar",
    "Aorrtc",
    "BitStar",
    "EitStar",
    "ExperimentResults",
    "FcitStar",
    "InformedRrtStar",
    "MitStar",
    "MitStarAs",
    "MitStarEis",
    "MitStarSc",
    "MitStarSr",
    "Planner",
    "PlanningError",
    "Problem",
    "RrtConnect",
    "SolveResult",
    "__version__",
    "experiments",
    "planner_parameters",
    "planners",
    "problem_families",
    "read_results",
    "robots",
    "run_experiment",
    "time_parameterise",
    "write_view",
]


def _configuration(name: str, label: str) -> Callable[..., Planner]:
    read = planner_parameters(name)

    def build(problem: Problem, **params: Any) -> Planner:
        return Planner(name, problem, **params)

    # help() and inspect show the keywords this planner reads; each defaults to None, which
    # keeps the planner's own default (listed in the docstring).
    keyword = inspect.Parameter.KEYWORD_ONLY
    fixed = [
        inspect.Parameter("problem", inspect.Parameter.POSITIONAL_OR_KEYWORD),
        inspect.Parameter("seed", keyword, default=0),
        inspect.Parameter("validity", keyword, default=None),
        inspect.Parameter("vectorized", keyword, default=None),
        inspect.Parameter("batch", keyword, default=64),
    ]
    own = [inspect.Parameter(key, keyword, default=None) for key, _ in read if key != "seed"]
    build.__signature__ = inspect.Signature(fixed + own, return_annotation=Planner)  # type: ignore[attr-defined]
    build.__name__ = build.__qualname__ = label
    defaults = "\n".join(f"    {key} = {value}" for key, value in read if key != "seed")
    build.__doc__ = (
        f"The ``{name}`` planner for ``problem``: ``Planner({name!r}, problem, **params)``.\n\n"
        "``seed``, ``validity``, ``vectorized`` and ``batch`` as ``Planner`` takes them; the "
        "planner's own parameters, with their defaults (None keeps the default; a parameter "
        "this planner does not read is refused with ValueError):\n\n" + defaults
    )
    return build


MitStar = _configuration("mit-star", "MitStar")
EitStar = _configuration("eit-star", "EitStar")
MitStarAs = _configuration("mit-star-as", "MitStarAs")
MitStarEis = _configuration("mit-star-eis", "MitStarEis")
MitStarSc = _configuration("mit-star-sc", "MitStarSc")
MitStarSr = _configuration("mit-star-sr", "MitStarSr")
RrtConnect = _configuration("rrt-connect", "RrtConnect")
Aorrtc = _configuration("aorrtc", "Aorrtc")
BitStar = _configuration("bit-star", "BitStar")
AbitStar = _configuration("abit-star", "AbitStar")
AitStar = _configuration("ait-star", "AitStar")
InformedRrtStar = _configuration("informed-rrt-star", "InformedRrtStar")
FcitStar = _configuration("fcit-star", "FcitStar")
