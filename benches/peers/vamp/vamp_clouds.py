#!/usr/bin/env python3
"""VAMP's side of the point-cloud comparison (side_by_side_clouds.sh), run with the Python of
VAMP's work folder ($W/venv/bin/python), which has VAMP's module.

For every valid problem of the chosen Panda scenes, VAMP's own protocol of
`scripts/evaluate_mbm.py --pointcloud True`, through VAMP's own functions:
`vamp.pointcloud.problem_dict_to_pointcloud` (10 000 points on each box and cylinder,
numpy seeded 0 for every problem, `filter_pointcloud` at 0.02 m culled at the Panda's
1.19 m, `Environment.add_pointcloud` with points of radius 0.0025: the CAPT), then the Halton
sampler reset and RRT-Connect with the script's settings (range 1.0). The filtering and
build times are the ones VAMP's bindings return (timed in C++ around the call, after the
points were converted from Python); the planning time is the planner's own.

Writes OUT/vamp.csv (one line per problem; its last column is VAMP's own check of the path
among the scene's true primitives, `Path.validate`, untimed), OUT/paths/SCENE_NNNN.txt (each solved path, one
configuration per line) and, with --clouds DIR, the filtered cloud of each problem as
DIR/SCENE_NNNN.npy (float32, N×3) — and with --raw DIR the cloud before filtering — for our
side to plan among the same points. NNNN is the problem's index, as in the MotionBenchMaker
folders' request files.

With --append the lines are added to an existing OUT/vamp.csv (its header written only when
the file is new): side_by_side_clouds.sh runs one scene at a time, each beside our runs of it.

    python vamp_clouds.py PROBLEMS.pkl OUT [--clouds DIR] [--raw DIR] [--scenes a,b,…] [--append]
"""
import argparse
import csv
import pickle
from pathlib import Path

import numpy as np
import vamp
from vamp import pointcloud as vpc

SAMPLES_PER_OBJECT = 10000  # evaluate_mbm.py's samples_per_object
FILTER_RADIUS = 0.02  # evaluate_mbm.py's filter_radius
FILTER_CULL = True  # evaluate_mbm.py's filter_cull


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("problems")
    parser.add_argument("out")
    parser.add_argument("--clouds")
    parser.add_argument("--raw")
    parser.add_argument("--scenes", default="")
    parser.add_argument("--append", action="store_true")
    args = parser.parse_args()
    with open(args.problems, "rb") as f:
        problems = pickle.load(f)["problems"]
    scenes = [s for s in args.scenes.split(",") if s] or list(problems)
    out = Path(args.out)
    (out / "paths").mkdir(parents=True, exist_ok=True)
    for folder in (args.clouds, args.raw):
        if folder:
            Path(folder).mkdir(parents=True, exist_ok=True)
    module, plan, settings, _ = vamp.configure_robot_and_planner_with_kwargs("panda", "rrtc")
    sampler = module.halton()
    r_min, r_max = module.min_max_radii()
    table = out / "vamp.csv"
    header = not (args.append and table.exists() and table.stat().st_size > 0)
    with open(table, "a" if args.append else "w", newline="") as f:
        rows = csv.writer(f)
        if header:
            rows.writerow(["scene", "index", "sampled", "filtered", "filter_us", "build_us",
                           "plan_us", "iterations", "solved", "valid_among_primitives"])
        for scene in scenes:
            for data in problems[scene]:
                if not data["valid"]:
                    continue
                env, raw, filtered, filter_ns, build_ns = vpc.problem_dict_to_pointcloud(
                    "panda", r_min, r_max, data, SAMPLES_PER_OBJECT, FILTER_RADIUS, FILTER_CULL)
                sampler.reset()
                result = plan(data["start"], data["goals"], env, settings, sampler)
                name = f"{scene}_{int(data['index']):04d}"
                if args.clouds:
                    np.save(Path(args.clouds) / f"{name}.npy", np.asarray(filtered, np.float32))
                if args.raw:
                    np.save(Path(args.raw) / f"{name}.npy", np.asarray(raw, np.float32))
                # Untimed: VAMP's own check of its path among the scene's true primitives
                # (its motion validation, at its resolution): a fidelity figure by VAMP's rules.
                among_primitives = ""
                if result.solved:
                    np.savetxt(out / "paths" / f"{name}.txt", result.path.numpy(), fmt="%.9g")
                    among_primitives = int(result.path.validate(vamp.problem_dict_to_vamp(data)))
                rows.writerow([scene, data["index"], len(raw), len(filtered), filter_ns / 1e3,
                               build_ns / 1e3, result.nanoseconds / 1e3, result.iterations,
                               int(result.solved), among_primitives])
                f.flush()


if __name__ == "__main__":
    main()
