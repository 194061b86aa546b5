#!/usr/bin/env python3
"""FCIT* beside VAMP's FCIT* (issue 72): the table of fcit_side_by_side.sh's rounds.

Usage: python3 fcit_table.py OUT

OUT holds vamp_K.csv (vamp_fcit.cc) and ours_K.csv (anytime_arm's `csv=FILE`) for rounds
K = 1, 2, …, both in anytime_arm's shape (scene,index,planner,first_ms,cost_10ms,cost_100ms,
cost_1s; `inf` where a run had no path by then). Per problem and side, each value is the median
over the rounds. Per scene and pooled: problems solved by 1 s (in each round), the median time to
the first solution (ms), the median cost (joint-space path length) at 100 ms and 1 s — a problem
without a path counting as infinitely long, medians taken as the upper middle value as
anytime_arm takes them — how many problems VAMP solved in some round and ours not in every
round (the target's strict reading), and on how many
problems ours is shorter and longer at 1 s. Then the issue's target: every problem VAMP's FCIT*
solves, solved; pooled median cost at 1 s at most VAMP's.
"""
import csv
import glob
import math
import os
import re
import sys

FIELDS = ("first_ms", "cost_100ms", "cost_1s")
SCENES = ["bookshelf_small", "bookshelf_tall", "bookshelf_thin", "box", "cage", "table_pick",
          "table_under_pick"]


def median(values):
    values = sorted(values)
    return values[len(values) // 2] if values else math.nan


def rounds(out, side):
    """{round: {(scene, index): (first_ms, cost_100ms, cost_1s)}} of one side's files."""
    found = {}
    for path in glob.glob(os.path.join(out, f"{side}_*.csv")):
        match = re.fullmatch(rf"{side}_(\d+)\.csv", os.path.basename(path))
        if not match:
            continue
        rows = {}
        for row in csv.DictReader(open(path)):
            key = (row["scene"].removesuffix("_panda"), int(row["index"]))
            rows[key] = tuple(float(row[f]) for f in FIELDS)
        found[int(match.group(1))] = rows
    return found


def per_problem(found, keys):
    """Per problem, the median over the rounds of each field."""
    return {k: tuple(median([r[k][f] for r in found.values()]) for f in range(len(FIELDS)))
            for k in keys}


def fmt(x, digits=2):
    return "∞" if math.isinf(x) else f"{x:.{digits}f}"


def main():
    out = sys.argv[1]
    vamp, ours = rounds(out, "vamp"), rounds(out, "ours")
    both = sorted(set(vamp) & set(ours))
    if not both:
        sys.exit(f"no round with both vamp_K.csv and ours_K.csv in {out}")
    vamp = {k: vamp[k] for k in both}
    ours = {k: ours[k] for k in both}
    keys = sorted(set.intersection(*(set(r) for r in [*vamp.values(), *ours.values()])))
    v, o = per_problem(vamp, keys), per_problem(ours, keys)
    print(f"Rounds {', '.join(map(str, both))}; {len(keys)} problems on both sides.\n")
    print("| scene | solved VAMP | ours | t_first VAMP (ms) | ours | cost 100 ms VAMP | ours "
          "| cost 1 s VAMP | ours | VAMP's solved, ours not | ours shorter / longer at 1 s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    missed_all = []
    for scene in SCENES + ["all"]:
        ks = [k for k in keys if scene in ("all", k[0])]
        if not ks:
            continue

        def solved(side):
            counts = [sum(math.isfinite(r[k][2]) for k in ks) for r in side.values()]
            return ", ".join(map(str, counts)) + f" /{len(ks)}"

        missed = [k for k in ks
                  if any(math.isfinite(r[k][2]) for r in vamp.values())
                  and not all(math.isfinite(r[k][2]) for r in ours.values())]
        if scene != "all":
            missed_all += missed
        shorter = sum(o[k][2] < v[k][2] - 1e-6 for k in ks)
        longer = sum(o[k][2] > v[k][2] + 1e-6 for k in ks)
        cells = [scene, solved(vamp), solved(ours)]
        for f, digits in ((0, 2), (1, 2), (2, 2)):
            cells += [fmt(median([v[k][f] for k in ks]), digits),
                      fmt(median([o[k][f] for k in ks]), digits)]
        cells += [str(len(missed)), f"{shorter} / {longer}"]
        print("| " + " | ".join(cells) + " |")
    pooled_v = median([v[k][2] for k in keys])
    pooled_o = median([o[k][2] for k in keys])
    print()
    print("Target, every problem VAMP's FCIT* solves by 1 s (in any round) solved (in every round): "
          + ("met" if not missed_all else
             "missed on " + ", ".join(f"{s} {i}" for s, i in missed_all)))
    print(f"Target, pooled median cost at 1 s ≤ VAMP's: ours {fmt(pooled_o, 3)}, "
          f"VAMP {fmt(pooled_v, 3)}: " + ("met" if pooled_o <= pooled_v else "missed"))


if __name__ == "__main__":
    main()
