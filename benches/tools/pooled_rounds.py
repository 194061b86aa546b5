#!/usr/bin/env python3
"""Time to the first solution from `mit-star bench` results folders: one build, or two side by
side, each measured in one or more rounds.

Each side is one or more results folders (one per round, the sides alternated). Per run (the
planner, problem, instance and seed of a `runs.csv` row), the median over that side's rounds
of `initial_time` (a failed run counts as infinite) and of the solve time without
construction (`initial_time - setup_time`); then, per problem and planner and pooled per
planner ("all"), the median and 95th percentile of those.

With one side: runs, solved runs and paths failing the harness's audit (summed over the
rounds), median and 95th percentile of `t_init` in seconds — the pooled rows of a results
folder, which its `kpi.md` gives per problem only. With two: before and after in
milliseconds, and before / after.

Usage:
    python3 benches/tools/pooled_rounds.py FOLDER[,FOLDER...]
    python3 benches/tools/pooled_rounds.py BEFORE_1,BEFORE_2 AFTER_1,AFTER_2

Standard library only.
"""

import csv
import math
import statistics
import sys


def side(folders):
    """Per run key (planner, problem, instance, seed): the median (t_init, solve) over the
    rounds in `folders`; and per (planner, problem): [runs, solved, paths failing the audit]."""
    times, tallies = {}, {}
    for folder in folders.split(","):
        with open(f"{folder}/runs.csv") as handle:
            for row in csv.DictReader(handle):
                solved = row["success"] == "true"
                t = float(row["initial_time"]) if solved else math.inf
                solve = t - float(row["setup_time"] or 0) if solved else math.inf
                key = (row["planner"], row["problem"], row["instance"], row["seed"])
                times.setdefault(key, []).append((t, solve))
                tally = tallies.setdefault(key[:2], [0, 0, 0])
                tally[0] += 1
                tally[1] += solved
                tally[2] += row["status"] == "invalid-path"
    medians = {
        k: tuple(statistics.median(r[i] for r in rounds) for i in (0, 1))
        for k, rounds in times.items()
    }
    return medians, tallies


def p95(values):
    """The value at index ⌊0.95 n⌋ of the sorted values (the last for small n)."""
    values = sorted(values)
    return values[min(len(values) - 1, int(0.95 * len(values)))]


def groups(keys):
    """(problem, planner, keys of its runs) per problem and planner, then "all" per planner."""
    planners = sorted({k[0] for k in keys})
    for problem in sorted({k[1] for k in keys}) + ["all"]:
        for planner in planners:
            ks = [k for k in keys if k[0] == planner and problem in ("all", k[1])]
            if ks:
                yield problem, planner, ks


def one(folders):
    times, tallies = side(folders)
    print("| problem | planner | runs | solved | audit failures | t_init median (s) | t_init p95 (s) |")
    print("|---|---|---|---|---|---|---|")
    for problem, planner, ks in groups(times.keys()):
        runs, solved, invalid = (
            sum(t[i] for (p, q), t in tallies.items() if p == planner and problem in ("all", q))
            for i in range(3)
        )
        ts = [times[k][0] for k in ks]
        print(f"| {problem} | {planner} | {runs} | {solved} | {invalid} | "
              f"{statistics.median(ts):.3e} | {p95(ts):.3e} |")


def two(before_folders, after_folders):
    (before, tb), (after, ta) = side(before_folders), side(after_folders)
    keys = before.keys() & after.keys()
    failed = [sum(t[0] - t[1] for t in tallies.values()) for tallies in (tb, ta)]
    invalid = [sum(t[2] for t in tallies.values()) for tallies in (tb, ta)]
    print(f"runs per side: {len(keys)}; failed runs {failed[0]} / {failed[1]}; "
          f"paths failing the audit {invalid[0]} / {invalid[1]}")
    print("| problem | planner | before t_init ms (p95) | after t_init ms (p95) | before / after "
          "| before solve ms | after solve ms | before / after |")
    print("|---|---|---|---|---|---|---|---|")
    for problem, planner, ks in groups(keys):
        row = [problem, planner]
        for i in (0, 1):
            b = [before[k][i] for k in ks]
            a = [after[k][i] for k in ks]
            mb, ma = statistics.median(b), statistics.median(a)
            if i == 0:
                row += [f"{mb * 1e3:.3f} ({p95(b) * 1e3:.2f})",
                        f"{ma * 1e3:.3f} ({p95(a) * 1e3:.2f})"]
            else:
                row += [f"{mb * 1e3:.3f}", f"{ma * 1e3:.3f}"]
            row.append(f"{mb / ma:.2f}")
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    if len(sys.argv) == 2:
        one(sys.argv[1])
    elif len(sys.argv) == 3:
        two(sys.argv[1], sys.argv[2])
    else:
        sys.exit(__doc__)
