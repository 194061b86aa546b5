#!/usr/bin/env python3
"""The side-by-side summary with mit-star timed as VAMP is: from the start of its solve.

`../shared/peers/vamp/side_by_side.sh` times mit-star by `initial_time`, which includes the
planner's construction in the benchmark harness (`setup_time`). This copies OUT to a temporary
folder with every `ours_*/*/runs.csv` rewritten to `initial_time - setup_time`, then runs the
shared `summarize.py` (path in $SUMMARIZE, else `../shared/peers/vamp/summarize.py` beside the
repository) on it:

    python3 benches/peers/vamp/summarize_solve.py OUT bookshelf_small bookshelf_tall box cage table_pick
"""
import csv, glob, os, shutil, subprocess, sys, tempfile
from pathlib import Path

out, scenes = sys.argv[1], sys.argv[2:]
shared = os.environ.get("SUMMARIZE") or str(
    Path(__file__).resolve().parents[3].parent / "shared/peers/vamp/summarize.py")
with tempfile.TemporaryDirectory() as tmp:
    copy = Path(tmp) / "out"
    shutil.copytree(out, copy)
    for f in glob.glob(f"{copy}/ours_*/*/runs.csv"):
        rows = list(csv.DictReader(open(f)))
        for r in rows:
            if r["initial_time"]:
                r["initial_time"] = repr(float(r["initial_time"]) - float(r["setup_time"]))
        if rows:
            with open(f, "w", newline="") as handle:
                writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
                writer.writeheader()
                writer.writerows(rows)
    sys.exit(subprocess.call([sys.executable, shared, str(copy), *scenes]))
