#!/usr/bin/env python3
"""VAMP and mit-star each timed in its own loop of solves, nothing else run between them.

VAMP's harness (`vamp_mbm`) solves the problems one after another, with only its simplifier (the
same collision code) between two solves. mit-star's benchmark harness audits, validates and
records each run between two solves (before f62d831 it also committed a database transaction
per run, which left the next solve cold: the guide's page "Arm planning beside VAMP", "The
harness's database, its audit and the two loops"). `arm_profile` with `ARM_PROFILE_CSV` is a loop like VAMP's: build, solve, next. This reads OUT/ours_K.csv files written that way and the
OUT/vamp_K.csv files of `vamp_mbm`, lays them out as `../shared/peers/vamp/side_by_side.sh`
does, and runs the shared `summarize.py` (path in $SUMMARIZE, else beside the repository):

    ARM_PROFILE_CSV=OUT/ours_1.csv ARM_PROFILE_NO_CHECKS=1 \\
        target/release/examples/arm_profile target 100 rrt-connect 1   # pinned; then ours_2, …
    python3 benches/peers/vamp/summarize_loops.py OUT bookshelf_small bookshelf_tall box cage table_pick
"""
import csv, glob, os, re, subprocess, sys, tempfile
from pathlib import Path

out, scenes = sys.argv[1], sys.argv[2:]
shared = os.environ.get("SUMMARIZE") or str(
    Path(__file__).resolve().parents[3].parent / "shared/peers/vamp/summarize.py")
with tempfile.TemporaryDirectory() as tmp:
    for f in glob.glob(f"{out}/vamp_*.csv"):
        os.symlink(os.path.abspath(f), f"{tmp}/{os.path.basename(f)}")
    for f in glob.glob(f"{out}/ours_*.csv"):
        rows = list(csv.DictReader(open(f)))
        run = re.sub(r"\.csv$", "", os.path.basename(f))
        for scene in {r["scene"] for r in rows}:
            folder = Path(tmp) / run / scene
            folder.mkdir(parents=True)
            with open(folder / "runs.csv", "w", newline="") as handle:
                writer = csv.writer(handle)
                writer.writerow(["instance_seed", "success", "initial_time"])
                for r in rows:
                    if r["scene"] == scene:
                        solved = r["solved"] == "1"
                        seconds = float(r["solve_us"]) / 1e6
                        writer.writerow([r["index"], "true" if solved else "false", seconds])
    sys.exit(subprocess.call([sys.executable, shared, tmp, *scenes]))
