#!/usr/bin/env python3
"""Compare two runs of one experiment (same seeds): per problem and planner, success, median
time to the first solution, median final cost and median grid points tested, before → after.

Usage: before-after.py BEFORE_FOLDER AFTER_FOLDER [--pool-layouts]

Medians are the KPI tables' (`MedianEstimate`: the value at index n/2 of the sorted runs,
unsolved runs counting as +inf for times and costs). With --pool-layouts, the instances of a
problem family and dimension (random rectangles' layouts) are pooled into one row. The last
columns are before/after ratios of the median t_init, and the count of solved runs whose path
failed the harness's independent validation (after).
"""
import csv
import math
import sys
from collections import defaultdict
from pathlib import Path


def median(values):
    v = sorted(values)
    return v[len(v) // 2] if v else math.nan


def load(folder, pool):
    rows = defaultdict(list)
    with open(Path(folder) / "runs.csv", newline="") as f:
        for r in csv.DictReader(f):
            key = (f"{r['problem']} R^{r['dimension']}" if pool else r["instance"], r["planner"])
            rows[key].append(r)
    return rows


def number(r, field):
    value = r[field]
    return float(value) if value not in ("", None) else math.inf


def summary(runs):
    solved = [r for r in runs if r["success"] == "true"]
    return {
        "solved": len(solved),
        "runs": len(runs),
        "t_init": median(number(r, "initial_time") if r["success"] == "true" else math.inf for r in runs),
        "final": median(number(r, "final_cost") if r["success"] == "true" else math.inf for r in runs),
        "points": median(float(r["points_tested"]) for r in runs),
        "invalid": sum(1 for r in solved if r["valid_path"] != "true"),
    }


def ms(x):
    return "∞" if x == math.inf else f"{1e3 * x:.2f}"


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    pool = "--pool-layouts" in sys.argv
    if len(args) != 2:
        sys.exit(__doc__)
    before, after = load(args[0], pool), load(args[1], pool)
    print("| problem | planner | solved before → after | median t_init (ms) before → after | speed-up | median final cost before → after | median points before → after | invalid paths after |")
    print("|---|---|---|---|---|---|---|---|")
    for key in sorted(before, key=lambda k: (k[0], k[1])):
        if key not in after:
            continue
        b, a = summary(before[key]), summary(after[key])
        ratio = b["t_init"] / a["t_init"] if a["t_init"] not in (0, math.inf) and b["t_init"] != math.inf else math.nan
        print(
            f"| {key[0]} | {key[1]} | {b['solved']}/{b['runs']} → {a['solved']}/{a['runs']} "
            f"| {ms(b['t_init'])} → {ms(a['t_init'])} | {ratio:.1f}× "
            f"| {b['final']:.4f} → {a['final']:.4f} | {b['points']:.0f} → {a['points']:.0f} | {a['invalid']} |"
        )


if __name__ == "__main__":
    main()
