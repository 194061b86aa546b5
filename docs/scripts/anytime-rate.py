#!/usr/bin/env python3
"""Work rate of whole anytime runs of `mit-star bench` (runs.csv): per instance and planner,
iterations and batches per second of run time (sums over the runs), and the median final cost.

Usage: anytime-rate.py RESULTS_FOLDER [RESULTS_FOLDER ...]
"""
import csv
import sys
from collections import defaultdict
from pathlib import Path

print("| folder | problem | planner | runs | iterations/s | batches/s | median final cost |")
print("|---|---|---|---|---|---|---|")
for folder in sys.argv[1:]:
    groups = defaultdict(list)
    with open(Path(folder) / "runs.csv", newline="") as f:
        for r in csv.DictReader(f):
            groups[(r["instance"], r["planner"])].append(r)
    for (instance, planner), runs in sorted(groups.items()):
        seconds = sum(float(r["run_time"]) for r in runs)
        iterations = sum(int(r["iterations"]) for r in runs)
        batches = sum(int(r["batches"]) for r in runs)
        costs = sorted(float(r["final_cost"]) if r["final_cost"] else float("inf") for r in runs)
        print(
            f"| {Path(folder).name} | {instance} | {planner} | {len(runs)} | {iterations / seconds:,.0f} "
            f"| {batches / seconds:,.1f} | {costs[len(costs) // 2]:.4f} |"
        )
