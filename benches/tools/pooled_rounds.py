#!/usr/bin/env python3
"""Two builds' time to the first solution, each measured in several rounds of `mit-star bench`.

Each side is one or more results folders (one per round, the sides alternated). Per run (the
instance and seed of a `runs.csv` row), the median over that side's rounds of `initial_time`
(a failed run counts as infinite) and of the solve time without construction
(`initial_time - setup_time`); then, per problem and pooled, the median and 95th percentile of
those, and before / after. Also counts failed runs and runs whose path failed the harness's
audit.

Usage:
    python3 benches/tools/pooled_rounds.py BEFORE_1,BEFORE_2 AFTER_1,AFTER_2

Standard library only.
"""

import csv
import math
import statistics
import sys


def side(folders):
    """(problem, instance, seed) -> (median t_init, median solve) over the rounds in `folders`."""
    times = {}
    failed = invalid = 0
    for folder in folders.split(","):
        with open(f"{folder}/runs.csv") as handle:
            for row in csv.DictReader(handle):
                solved = row["success"] == "true"
                failed += not solved
                invalid += row["status"] == "invalid-path"
                t = float(row["initial_time"]) if solved else math.inf
                solve = t - float(row["setup_time"] or 0) if solved else math.inf
                key = (row["problem"], row["instance"], row["seed"])
                times.setdefault(key, []).append((t, solve))
    medians = {
        k: tuple(statistics.median(r[i] for r in rounds) for i in (0, 1))
        for k, rounds in times.items()
    }
    return medians, failed, invalid


def p95(values):
    values = sorted(values)
    return values[min(len(values) - 1, int(0.95 * len(values)))]


before, failed_b, invalid_b = side(sys.argv[1])
after, failed_a, invalid_a = side(sys.argv[2])
keys = before.keys() & after.keys()
print(f"runs per side: {len(keys)}; failed runs {failed_b} / {failed_a}; "
      f"paths failing the audit {invalid_b} / {invalid_a}")
print("| problem | before t_init ms (p95) | after t_init ms (p95) | before / after "
      "| before solve ms | after solve ms | before / after |")
print("|---|---|---|---|---|---|---|")
for problem in sorted({k[0] for k in keys}) + ["all"]:
    ks = [k for k in keys if problem in ("all", k[0])]
    row = [problem]
    for i in (0, 1):
        b = [before[k][i] for k in ks]
        a = [after[k][i] for k in ks]
        mb, ma = statistics.median(b), statistics.median(a)
        if i == 0:
            row += [f"{mb * 1e3:.3f} ({p95(b) * 1e3:.2f})", f"{ma * 1e3:.3f} ({p95(a) * 1e3:.2f})"]
        else:
            row += [f"{mb * 1e3:.3f}", f"{ma * 1e3:.3f}"]
        row.append(f"{mb / ma:.2f}")
    print("| " + " | ".join(row) + " |")
