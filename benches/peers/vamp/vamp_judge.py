#!/usr/bin/env python3
"""VAMP's own verdict on paths among a problem's TRUE primitives, run with the Python of VAMP's
work folder: for the fidelity table of side_by_side_clouds.sh, beside our continuous check.

Each path file is `plan --json`'s output (its "path") or text (one configuration per line);
its name is SCENE_NNNN.json or SCENE_NNNN.txt (files without a path are skipped). The verdict is VAMP's `Path.validate` in the
environment VAMP makes of the problem (`vamp.problem_dict_to_vamp`: boxes, cylinders as
capsules, the box scene's as cuboids), each motion checked at VAMP's planning resolution with
VAMP's spheres of the Panda: a discrete check, not a continuous one.

    python vamp_judge.py PROBLEMS.pkl OUT.csv FILE…
"""
import csv
import json
import pickle
import sys
from pathlib import Path

import numpy as np
import vamp


def states(path):
    text = path.read_text()
    if path.suffix == ".json":
        try:
            return json.loads(text).get("path") or []
        except json.JSONDecodeError:  # a run refused before planning writes no JSON
            return []
    return [[float(x) for x in line.split()] for line in text.splitlines() if line.strip()]


def main():
    problems = pickle.load(open(sys.argv[1], "rb"))["problems"]
    by_index = {(s, int(p["index"])): p for s, ps in problems.items() for p in ps}
    with open(sys.argv[2], "w", newline="") as f:
        rows = csv.writer(f)
        rows.writerow(["file", "scene", "index", "valid_by_vamp"])
        for name in sys.argv[3:]:
            path = Path(name)
            scene, index = path.stem.rsplit("_", 1)
            configurations = states(path)
            if len(configurations) < 2:
                continue
            walk = vamp.panda.Path()
            for q in configurations:
                walk.append(np.asarray(q, dtype=np.float32))
            env = vamp.problem_dict_to_vamp(by_index[(scene, int(index))])
            rows.writerow([name, scene, int(index), int(walk.validate(env))])


if __name__ == "__main__":
    main()
