#!/usr/bin/env python3
"""Two sides of `interleaved_ab.sh` compared run by run.

Reads OUT/a_<round>.csv and OUT/b_<round>.csv (`arm_profile`'s `ARM_PROFILE_CSV` rows: scene,
problem, seed, time in µs, solved, counters). Per run (scene, problem, seed), the median time
over each side's rounds; then per scene and over all runs, the median of the per-run ratios
b / a, the ratio of the summed times, and the median times of each side. Runs that did not
solve on either side are left out of the ratios (counted). Where both sides make the same
decisions (a change of speed only), also says how many runs differ in iterations or states
kept, which should be none but for runs cut short by their deadline.

Usage:
    python3 benches/tools/paired_runs.py OUT

Standard library only.
"""

import csv
import glob
import statistics
import sys


def side(folder, name):
    """Per run key: (median time over the rounds, solved in every round, its decisions)."""
    times, solved, work = {}, {}, {}
    for path in sorted(glob.glob(f"{folder}/{name}_*.csv")):
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                key = (row["scene"], int(row["index"]), int(row["seed"]))
                times.setdefault(key, []).append(float(row["solve_us"]))
                solved[key] = solved.get(key, True) and row["solved"] == "1"
                work.setdefault(key, set()).add((row["iterations"], row["states"]))
    return {k: (statistics.median(v), solved[k], work[k]) for k, v in times.items()}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    a, b = side(sys.argv[1], "a"), side(sys.argv[1], "b")
    keys = sorted(set(a) & set(b))
    if not keys:
        sys.exit("no run is in both sides")
    both = [k for k in keys if a[k][1] and b[k][1]]
    print("| scene | runs | median a (µs) | median b (µs) | median ratio b/a | summed b/a |")
    print("|---|---|---|---|---|---|")
    scenes = sorted({k[0] for k in both})
    for scene, runs in [(s, [k for k in both if k[0] == s]) for s in scenes] + [("all", both)]:
        ratios = [b[k][0] / a[k][0] for k in runs]
        summed = sum(b[k][0] for k in runs) / sum(a[k][0] for k in runs)
        print(
            f"| {scene} | {len(runs)} | {statistics.median(a[k][0] for k in runs):.0f} "
            f"| {statistics.median(b[k][0] for k in runs):.0f} "
            f"| {statistics.median(ratios):.3f} | {summed:.3f} |"
        )
    unsolved = len(keys) - len(both)
    differ = sum(1 for k in keys if a[k][2] != b[k][2])
    print(f"\n{len(keys)} runs; {unsolved} unsolved on a side (left out); "
          f"{differ} differ in iterations or states between the sides")


if __name__ == "__main__":
    main()
