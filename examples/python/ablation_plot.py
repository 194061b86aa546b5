"""A small ablation from Python: MIT* against EIT* and two of MIT*'s ablations on PDT's
dividing walls in R^4, a few seeds each; plots the median cost over time (a PNG).

    pip install "./python[examples]"     # the package and matplotlib
    python examples/python/ablation_plot.py --seeds 5 --time 1.0 --output target/ablation.png
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import mit_star  # noqa: E402

PLANNERS = ["mit-star", "eit-star", "mit-star-as", "mit-star-sc"]


def cost_at(trace: list[tuple[float, float]], t: float) -> float:
    """The best cost at time ``t`` of an anytime trace (``inf`` before the first solution)."""
    best = math.inf
    for time, cost in trace:
        if time > t:
            break
        best = cost
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--problem", default="dividing-walls")
    parser.add_argument("--dim", type=int, default=4)
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--time", type=float, default=1.0, help="seconds per run")
    parser.add_argument("--output", type=Path, default=Path("target/python-ablation.png"))
    args = parser.parse_args()

    problem = mit_star.Problem(args.problem, args.dim)
    times = np.geomspace(args.time / 1000, args.time, 200)
    figure, axes = plt.subplots(figsize=(7, 4.5))
    for name in PLANNERS:
        curves = []
        for seed in range(args.seeds):
            planner = mit_star.Planner(name, problem, seed=seed)
            planner.solve(time=args.time)
            curves.append([cost_at(planner.trace, t) for t in times])
            label = planner.name
        median = np.median(np.array(curves), axis=0)  # inf until half the runs solved
        final = median[-1]
        print(f"{label:10} median final cost {final:.4f} over {args.seeds} seeds")
        axes.step(times, np.where(np.isfinite(median), median, np.nan), where="post", label=label)
    if problem.optimum is not None:
        axes.axhline(problem.optimum, color="grey", linestyle=":", label="optimum")
    axes.set_xscale("log")
    axes.set_xlabel("time [s]")
    axes.set_ylabel("median cost")
    axes.set_title(f"{problem.id}: median of {args.seeds} seeds")
    axes.legend()
    args.output.parent.mkdir(parents=True, exist_ok=True)
    figure.tight_layout()
    figure.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
