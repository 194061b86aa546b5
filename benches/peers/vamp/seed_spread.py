#!/usr/bin/env python3
"""Repeated anytime runs beside VAMP's AORRTC: one configuration of ours run with several seeds
(anytime_arm's `seed=K`, one CSV per seed), against VAMP's single run per problem (its random
sequence is a Halton sequence reset before every run, so it has one outcome per problem).

Usage: python3 seed_spread.py VAMP.csv LABEL=GLOB [LABEL=GLOB ...]

GLOB names our CSVs of one configuration (e.g. `"base=base.*.csv"`). Per scene and label: the
runs, the median time to the first solution (ms), the median cost at 10 ms and at 100 ms over
all runs (a run without a path by then counting as infinitely long), and in how many runs our
cost at 10 ms is at most VAMP's on the same problem. One run per problem moves a scene's median
at 10 ms by more than a change does on problems such as cage, where whether the first path is
shortened within 10 ms depends on the time the first search took; the spread over seeds does not.
"""
import glob
import sys

from anytime_table import median, our_rows, vamp_rows


def main():
    vamp = vamp_rows(sys.argv[1])
    print("| scene | configuration | runs | median t_first (ms) | cost at 10 ms | at 100 ms | runs ≤ VAMP at 10 ms |")
    print("|---|---|---|---|---|---|---|")
    groups = []
    for argument in sys.argv[2:]:
        label, _, pattern = argument.partition("=")
        runs = []
        for path in sorted(glob.glob(pattern)):
            for rows in our_rows([path]).values():
                runs += [(key, values) for key, values in rows.items() if key in vamp]
        if not runs:
            sys.exit(f"no runs match {pattern}")
        groups.append((label, runs))
    scenes = sorted({key[0] for _, runs in groups for key, _ in runs})
    for scene in scenes + ["all"]:
        for label, runs in groups:
            mine = [(k, v) for k, v in runs if scene in ("all", k[0])]
            if not mine:
                continue
            first = median([v[0] for _, v in mine])
            at10 = median([v[1] for _, v in mine])
            at100 = median([v[2] for _, v in mine])
            level = sum(1 for k, v in mine if v[1] <= vamp[k][1] + 1e-9)
            print(
                f"| {scene} | {label} | {len(mine)} | {first:.2f} | {at10:.2f} | {at100:.2f} "
                f"| {level} of {len(mine)} |"
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
