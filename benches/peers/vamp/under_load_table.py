#!/usr/bin/env python3
"""The table of under_load.sh: [CONDITIONS="idle busy crowded"] python3 under_load_table.py OUT SCENE…

OUT holds a folder per condition (`idle/`, `busy/`, `crowded/`), each with VAMP's `vamp_K.csv` and our `ours_K/SCENE/` results
folders of round K. Per scene and pooled, for each condition, medians over problems of each
problem's median over rounds (as the shared summarize.py takes them), in microseconds:

- VAMP: its planning time (its harness's timer, around the solve);
- ours, solve: `initial_time - setup_time` (timed as VAMP is, from the solve's start);
- ours, +constr.: `initial_time` (the planner's construction included);
- constr., audit: the construction (`setup_time`) and the independent audit of the path
  (`validation.seconds` in runs.jsonl), both outside the solve;
- per run: the bench process's wall time over its runs (process start, problem loading, the
  runs, audits and recording), the harness's whole cost of one run;
- loop: our solve timed in `arm_profile`'s loop (under_load.sh's LOOP), nothing between two
  solves, as VAMP's harness runs (five scenes: bookshelf_thin and table_under_pick are not in it).

Then the ratios: ours / VAMP under each condition, and each loaded condition against idle for
each side (how much each slows down under that load).
"""
import csv
import json
import math
import os
import statistics as st
import sys
from pathlib import Path


def p95(v):
    v = sorted(v)
    return v[min(len(v) - 1, math.ceil(0.95 * len(v)) - 1)]


def read(folder, scenes):
    """Per (scene, problem): lists over rounds of each measure (µs), and per-scene wall per run."""
    m = {k: {} for k in ("vamp", "solve", "constructed", "setup", "audit", "loop")}
    per_run = {}
    for f in sorted(folder.glob("vamp_*.csv")):
        for r in csv.DictReader(open(f)):
            if r["scene"] in scenes and r.get("solved", "1") == "1":
                m["vamp"].setdefault((r["scene"], int(r["index"])), []).append(float(r["plan_us"]))
    for f in sorted(folder.glob("loop_*.csv")):
        for r in csv.DictReader(open(f)):
            if r["scene"] in scenes and r["solved"] == "1":
                m["loop"].setdefault((r["scene"], int(r["index"])), []).append(float(r["solve_us"]))
    for d in sorted(folder.glob("ours_*")):
        walls = {}
        if (d / "wall.csv").exists():
            for line in open(d / "wall.csv"):
                s, t0, t1 = line.strip().split(",")
                walls[s] = float(t1) - float(t0)
        for s in scenes:
            try:
                rows = list(csv.DictReader(open(d / s / "runs.csv")))
            except FileNotFoundError:
                continue
            audits = {}
            for line in open(d / s / "runs.jsonl"):
                j = json.loads(line)
                v = j.get("validation") or {}
                audits[(j.get("instance"), j.get("run"))] = v.get("seconds", 0.0)
            for r in rows:
                k = (s, int(r["instance_seed"]))
                if r["success"] != "true":
                    continue
                t, setup = float(r["initial_time"]), float(r["setup_time"])
                m["solve"].setdefault(k, []).append((t - setup) * 1e6)
                m["constructed"].setdefault(k, []).append(t * 1e6)
                m["setup"].setdefault(k, []).append(setup * 1e6)
                m["audit"].setdefault(k, []).append(
                    audits.get((r["instance"], int(r["run"])), 0.0) * 1e6)
            if s in walls and rows:
                per_run.setdefault(s, []).append(walls[s] / len(rows) * 1e6)
    return m, per_run


def dashes(row):
    """A table row with "–" where a measure has no data (the loop's two missing scenes, a run
    without LOOP)."""
    return row.replace("nan×", "–").replace("nan", "–")


def median_of_medians(measure, scene):
    v = [st.median(x) for k, x in measure.items() if scene == "all" or k[0] == scene]
    return (st.median(v), p95(v)) if v else (math.nan, math.nan)


def main():
    out, scenes = Path(sys.argv[1]), sys.argv[2:]
    conditions = [c for c in os.environ.get("CONDITIONS", "idle busy crowded").split()
                  if (out / c).is_dir()]
    data = {c: read(out / c, scenes) for c in conditions}
    rounds = out / "rounds.txt"
    if rounds.exists():
        print(rounds.read_text().strip())
        print()
    for condition in conditions:
        m, per_run = data[condition]
        # The loop covers five scenes: its pooled ratio is against VAMP on those five.
        loop_scenes = {k[0] for k in m["loop"]}
        vamp_on_loop_scenes = {k: x for k, x in m["vamp"].items() if k[0] in loop_scenes}
        print(f"### {condition}: medians (p95) over problems, µs")
        print("| scene | VAMP | ours, solve | ours, +constr. | solve / VAMP | +constr. / VAMP "
              "| constr. | audit | per run (harness) | loop | loop / VAMP |")
        print("|---|---|---|---|---|---|---|---|---|---|---|")
        for s in scenes + ["all"]:
            v, vp = median_of_medians(m["vamp"], s)
            o, op = median_of_medians(m["solve"], s)
            c, cp = median_of_medians(m["constructed"], s)
            setup, _ = median_of_medians(m["setup"], s)
            audit, _ = median_of_medians(m["audit"], s)
            walls = [w for sc, ws in per_run.items() if s in ("all", sc) for w in ws]
            wall = st.median(walls) if walls else math.nan
            loop, _ = median_of_medians(m["loop"], s)
            loop_vamp, _ = median_of_medians(vamp_on_loop_scenes, s)
            print(dashes(f"| {s} | {v:.0f} ({vp:.0f}) | {o:.0f} ({op:.0f}) | {c:.0f} ({cp:.0f}) "
                         f"| {o / v:.2f}× | {c / v:.2f}× | {setup:.0f} | {audit:.0f} | {wall:.0f} "
                         f"| {loop:.0f} | {loop / loop_vamp:.2f}× |"))
        print()
    for loaded in (c for c in conditions if c != "idle" and "idle" in data):
        print(f"### {loaded} / idle: how much each side slows down")
        print("| scene | VAMP | ours, solve | ours, +constr. | ours construction | ours, loop |")
        print("|---|---|---|---|---|---|")
        for s in scenes + ["all"]:
            row = []
            for key in ("vamp", "solve", "constructed", "setup", "loop"):
                idle = median_of_medians(data["idle"][0][key], s)[0]
                load = median_of_medians(data[loaded][0][key], s)[0]
                row.append(f"{load / idle:.2f}×")
            print(dashes(f"| {s} | " + " | ".join(row) + " |"))
        print()
    unsolved = {c: sum(1 for d in (out / c).glob("ours_*/*/runs.csv")
                       for r in csv.DictReader(open(d)) if r["success"] != "true")
                for c in conditions}
    print("ours unsolved runs: " + ", ".join(f"{c} {n}" for c, n in unsolved.items()))


if __name__ == "__main__":
    main()
