#!/usr/bin/env python3
"""Per-problem comparison of two `mit_arm_probe` listings run with
`PROBE_FIXED_ITERATIONS=N` (whose `cend` is then the cost after the N iterations): how many
problems the second listing's path is shorter and longer on, per scene and over all, and the
median of second / first.

A fixed number of iterations makes each listing a function of the build, the setting and the
seed alone, so a change that leaves the speed of an iteration alone is compared without the
timing noise of two runs on a shared machine (the same build and seed run twice at 1 s read
16 shorter and 38 longer from timing alone). A change that makes iterations cheaper or dearer
needs the timed comparison (`benches/peers/vamp/pair_runs.py`) as well.

Usage: python3 probe_pairs.py FIRST.txt SECOND.txt
"""
import statistics
import sys


def load(path):
    """(scene, index) -> final cost, from a probe listing (header line first)."""
    rows = {}
    with open(path) as listing:
        header = listing.readline().split()
        scene, index, cost = header.index("scene"), header.index("idx"), header.index("cend")
        for line in listing:
            fields = line.split()
            if len(fields) != len(header):
                continue
            rows[(fields[scene], int(fields[index]))] = float(fields[cost])
    return rows


def compare(first, second, keys):
    """(shorter, longer, equal, median ratio) of `second` against `first` over `keys`."""
    shorter = longer = equal = 0
    ratios = []
    for key in keys:
        a, b = first[key], second[key]
        if b < a:
            shorter += 1
        elif b > a:
            longer += 1
        else:
            equal += 1
        if a < float("inf") and b < float("inf"):
            ratios.append(b / a)
    return shorter, longer, equal, (statistics.median(ratios) if ratios else float("nan"))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    first, second = load(sys.argv[1]), load(sys.argv[2])
    keys = sorted(first.keys() & second.keys())
    if not keys:
        sys.exit("the two listings share no problem")
    for scene in sorted({s for s, _ in keys}):
        shorter, longer, equal, ratio = compare(
            first, second, [k for k in keys if k[0] == scene])
        print(f"{scene}: second shorter on {shorter}, longer on {longer}, equal on {equal}, "
              f"median ratio {ratio:.4f}")
    shorter, longer, equal, ratio = compare(first, second, keys)
    print(f"all ({len(keys)}): second shorter on {shorter}, longer on {longer}, "
          f"equal on {equal}, median ratio {ratio:.4f}")


if __name__ == "__main__":
    main()
