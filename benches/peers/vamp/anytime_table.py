#!/usr/bin/env python3
"""Per-scene anytime table: VAMP's AORRTC (vamp_anytime's CSV) beside mit-star's planners
(anytime_arm's CSV, `csv=FILE`), on the problems both ran.

Usage: python3 anytime_table.py [--digits=N] [--first-paths=FIRST.csv] VAMP.csv OURS.csv [OURS.csv ...]

Each of our files may be given as `LABEL=OURS.csv`: its planners are then shown as LABEL (for
runs of one configuration with different parameters, e.g. `"MIT* + warm + simplify=mit.csv"`).

Per scene and planner: problems, median time to the first solution (ms), and median best cost
(joint-space path length) at 10 ms, 100 ms and 1 s, a run without a path by then counting as
infinitely long. VAMP's cost at time T is the cost of its run with the largest iteration limit
that ended within T (see vamp_anytime.cc); its first-solution time is that of the smallest
iteration limit that solved.

`--digits=N` prints the costs with N decimals (2 by default). `--first-paths=FIRST.csv`
(vamp_anytime's output with `VAMP_FIRST_PATHS=1`: the time VAMP's default simplification takes
on RRT-Connect's first path, per problem) adds, per scene, VAMP's median first-solution time,
the median of that simplification, and the median per problem of the first-solution time less
the simplification: VAMP's AORRTC simplifies a path before returning it, so its first-solution
time includes that simplification.
"""
import csv
import math
import statistics
import sys
from collections import defaultdict

MOMENTS_US = [10_000, 100_000, 1_000_000]


def median(values):
    values = sorted(values)
    return values[len(values) // 2] if values else math.nan


def vamp_rows(path):
    runs = defaultdict(list)
    for row in csv.DictReader(open(path)):
        scene = row["scene"].removesuffix("_panda")
        runs[(scene, int(row["index"]))].append(
            (float(row["time_us"]), float(row["cost"]), row["solved"] == "1")
        )
    out = {}
    for key, rs in runs.items():
        # Runs in order of their iteration limit: the first that solved gives the time to a
        # first solution; the cost at T is that of the run with the largest limit that ended
        # within T (a run the caller could have made), infinite if it found no path.
        solved = [(t, c) for t, c, s in rs if s]
        first = (solved[0][0] if solved else math.inf) / 1e3
        costs = []
        for m in MOMENTS_US:
            within = [(c if s else math.inf) for t, c, s in rs if t <= m]
            costs.append(within[-1] if within else math.inf)
        out[key] = (first, *costs)
    return out


def our_rows(arguments):
    out = defaultdict(dict)
    for argument in arguments:
        label, _, path = argument.rpartition("=")
        for row in csv.DictReader(open(path)):
            key = (row["scene"].removesuffix("_panda"), int(row["index"]))
            values = [float(row[k]) for k in ("first_ms", "cost_10ms", "cost_100ms", "cost_1s")]
            out[label or row["planner"]][key] = tuple(values)
    return out


def first_paths(path, vamp, scenes):
    """Per scene: VAMP's first-solution time, its simplification's, and the first less it."""
    simplify = {}
    for row in csv.DictReader(open(path)):
        key = (row["scene"].removesuffix("_panda"), int(row["index"]))
        simplify[key] = float(row["simplify_us"]) / 1e3
    keys = [k for k in vamp if k in simplify and math.isfinite(vamp[k][0])]
    print("\n| scene | VAMP AORRTC t_first (ms) | its simplification (ms) | t_first less it (ms) |")
    print("|---|---|---|---|")
    for scene in scenes + ["all"]:
        ks = [k for k in keys if scene in ("all", k[0])]
        cols = (
            median([vamp[k][0] for k in ks]),
            median([simplify[k] for k in ks]),
            median([vamp[k][0] - simplify[k] for k in ks]),
        )
        print(f"| {scene} | " + " | ".join(f"{c:.2f}" for c in cols) + " |")


def main():
    options = {}
    arguments = []
    for argument in sys.argv[1:]:
        name, _, value = argument.partition("=")
        if name in ("--digits", "--first-paths"):
            options[name] = value
        else:
            arguments.append(argument)
    digits = int(options.get("--digits", 2))
    vamp = vamp_rows(arguments[0])
    ours = our_rows(arguments[1:])
    planners = {"VAMP AORRTC": vamp, **ours}
    common = set(vamp).intersection(*[set(v) for v in ours.values()])
    scenes = sorted({s for s, _ in common})
    print("| scene | planner | problems | median t_first (ms) | cost at 10 ms | at 100 ms | at 1 s |")
    print("|---|---|---|---|---|---|---|")
    for scene in scenes + ["all"]:
        keys = sorted(k for k in common if scene in ("all", k[0]))
        for name, rows in planners.items():
            cols = [median([rows[k][i] for k in keys]) for i in range(4)]
            print(
                f"| {scene} | {name} | {len(keys)} | {cols[0]:.2f} | "
                + " | ".join(f"{c:.{digits}f}" for c in cols[1:])
                + " |"
            )
    # Paired: per problem, ours / VAMP's cost at each moment, for each of our planners.
    for name, rows in ours.items():
        ratios = []
        for i in range(1, 4):
            r = [rows[k][i] / vamp[k][i] for k in common if math.isfinite(vamp[k][i])]
            ratios.append(median(r))
        better = [sum(rows[k][3] < vamp[k][3] - 1e-6 for k in common),
                  sum(rows[k][3] > vamp[k][3] + 1e-6 for k in common)]
        print(
            f"\n{name} / VAMP AORRTC, median per-problem cost ratio at 10 ms, 100 ms, 1 s: "
            + ", ".join(f"{r:.3f}" for r in ratios)
            + f"; at 1 s better on {better[0]}, worse on {better[1]} of {len(common)}"
        )
    if "--first-paths" in options:
        first_paths(options["--first-paths"], vamp, scenes)


if __name__ == "__main__":
    main()
