#!/usr/bin/env python3
"""Per-scene time to a first solution from `arm_profile` CSVs, one column per CSV.

`arm_profile` with `ARM_PROFILE_CSV=FILE` writes one row per solve (scene, problem, seed, time in
µs, solved, counters). This takes, per problem, the median time over its seeds (an unsolved
solve counts as infinite), then per scene and over all scenes ("all") the median, the 95th
percentile and the mean of those per-problem medians, and prints them as `median / p95 / mean`
in µs, one column per CSV (the tables of the guide's "RRT-Connect's switches"). The 95th
percentile is the nearest rank, as the shared side-by-side summary takes it
(`pooled_rounds.py` takes the value at index ⌊0.95 n⌋, one rank higher for 100 problems).

Usage:
    ARM_PROFILE_CSV=k0.csv ARM_PROFILE_NO_CHECKS=1 arm_profile target 100 rrt-connect 5 \\
        rrt_forced_redraws=0
    ARM_PROFILE_CSV=k4.csv ARM_PROFILE_NO_CHECKS=1 arm_profile target 100 rrt-connect 5
    python3 benches/tools/arm_profile_table.py k0.csv k4.csv

Standard library only.
"""

import csv
import math
import statistics
import sys


def per_problem(path):
    """{(scene, problem): median solve time in µs over the seeds, unsolved as infinite}."""
    times = {}
    with open(path, newline="") as handle:
        for row in csv.DictReader(handle):
            t = float(row["solve_us"]) if row["solved"] == "1" else math.inf
            times.setdefault((row["scene"], int(row["index"])), []).append(t)
    return {key: statistics.median(values) for key, values in times.items()}


def percentile(values, p):
    """The nearest-rank `p`-th percentile (0 < p < 1) of `values`."""
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, max(0, math.ceil(p * len(ordered)) - 1))]


def cell(values):
    """`median / p95 / mean` of `values` (the mean over finite values)."""
    finite = [v for v in values if math.isfinite(v)]
    mean = sum(finite) / len(finite) if finite else math.inf
    return f"{statistics.median(values):.0f} / {percentile(values, 0.95):.0f} / {mean:.0f}"


def main(paths):
    if not paths:
        sys.exit(__doc__)
    columns = [per_problem(path) for path in paths]
    scenes = sorted({scene for column in columns for scene, _ in column})
    print("| scene | " + " | ".join(paths) + " |")
    print("|---|" + "---|" * len(paths))
    for scene in scenes + ["all"]:
        cells = [
            cell([t for (s, _), t in column.items() if scene in ("all", s)])
            for column in columns
        ]
        print(f"| {scene} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
