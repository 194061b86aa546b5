#!/usr/bin/env python3
"""Per-problem comparison of two of our anytime runs (anytime_arm's CSV, `csv=FILE`), as the
guide's "what changed" figures are taken: for each moment (10 ms, 100 ms, 1 s), how many problems
the second run's path is shorter and longer on, and the median of second / first.

Usage: python3 pair_runs.py FIRST.csv SECOND.csv
"""
import statistics
import sys

from anytime_table import our_rows

MOMENTS = ["cost_10ms", "cost_100ms", "cost_1s"]


def load(path):
    """The run's rows of one file: (scene, index) → (first_ms, cost at 10 ms, 100 ms, 1 s)."""
    (rows,) = our_rows([path]).values()
    return rows


first, second = load(sys.argv[1]), load(sys.argv[2])
for m, column in enumerate(MOMENTS, start=1):
    shorter = longer = 0
    ratios = []
    for key in first.keys() & second.keys():
        a, b = first[key][m], second[key][m]
        shorter += b < a - 1e-9
        longer += b > a + 1e-9
        if a < float("inf") and b < float("inf"):
            ratios.append(b / a)
    print(f"{column}: second shorter on {shorter}, longer on {longer}, "
          f"median ratio {statistics.median(ratios):.4f}")
