#!/usr/bin/env python3
"""Two sides of `interleaved_bench.sh`, run by run: per scene and pooled, the medians of
construction (`setup_time`), of the time to the first solution with construction
(`initial_time`) and of the solve alone (their difference), with the ratio b/a; then how many
runs made the same decisions on both sides (iterations and validity checks equal), and the
median over problems of each problem's ratio (its median over rounds, with construction).

Usage: python3 benches/tools/paired_bench.py OUT

Standard library only.
"""

import collections
import csv
import glob
import statistics
import sys


def load(out, side):
    """(problem, instance, round) -> (setup µs, initial µs, iterations, validity checks)."""
    runs = {}
    for path in glob.glob(f"{out}/{side}.*/runs.csv"):
        round_ = path.split("/")[-2].split(".")[1]
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                if row["initial_time"]:
                    runs[(row["problem"], row["instance"], round_)] = (
                        float(row["setup_time"]) * 1e6,
                        float(row["initial_time"]) * 1e6,
                        row["iterations"],
                        row["validity_checks"],
                    )
    return runs


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    a, b = load(out, "a"), load(out, "b")
    keys = sorted(set(a) & set(b))
    if not keys:
        sys.exit(f"no run solved on both sides in {out}")
    median = statistics.median
    print("| scene | runs | construction a, b (µs) | with construction a, b (µs) | b/a "
          "| solve a, b (µs) | b/a |")
    print("|---|---|---|---|---|---|---|")
    for scene in sorted({k[0] for k in keys}) + ["all"]:
        ks = [k for k in keys if scene == "all" or k[0] == scene]
        setup = [median(s[k][0] for k in ks) for s in (a, b)]
        first = [median(s[k][1] for k in ks) for s in (a, b)]
        solve = [median(s[k][1] - s[k][0] for k in ks) for s in (a, b)]
        print(f"| {scene} | {len(ks)} | {setup[0]:.1f}, {setup[1]:.1f} "
              f"| {first[0]:.1f}, {first[1]:.1f} | {first[1] / first[0]:.3f} "
              f"| {solve[0]:.1f}, {solve[1]:.1f} | {solve[1] / solve[0]:.3f} |")
    same = sum(a[k][2:] == b[k][2:] for k in keys)
    per = collections.defaultdict(lambda: ([], []))
    for k in keys:
        per[k[:2]][0].append(a[k][1])
        per[k[:2]][1].append(b[k][1])
    ratios = [median(y) / median(x) for x, y in per.values()]
    print(f"\n{len(keys)} runs solved on both sides; {same} made the same decisions. Per problem, "
          f"with construction: median ratio {median(ratios):.3f}, "
          f"{sum(r < 1 for r in ratios)} faster, {sum(r > 1 for r in ratios)} slower.")


if __name__ == "__main__":
    main()
