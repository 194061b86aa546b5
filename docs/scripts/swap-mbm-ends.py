#!/usr/bin/env python3
"""Copy a MotionBenchMaker problem folder with every request's start and goal exchanged.

The new requests plan from the old goal (a grasp in a shelf, say) back to the old start: the
retreat after a pick, which puts the start in the pocket instead of the goal. Joints the goal
constraints do not name keep the start's values.

    python3 docs/scripts/swap-mbm-ends.py target/problems/bookshelf_small_fetch \
        target/problems/bookshelf_small_retreat_fetch

Needs PyYAML (`pip install pyyaml`).
"""

import argparse
import shutil
import sys
from pathlib import Path

import yaml


def swap(request: dict, name: str) -> None:
    """Exchanges the start's and the goal's joint values in one request, in place."""
    joints = request["start_state"]["joint_state"]
    index = {joint: i for i, joint in enumerate(joints["name"])}
    constraints = request["goal_constraints"]
    if len(constraints) != 1:
        raise SystemExit(f"{name}: {len(constraints)} goal constraints; only one can be swapped")
    for constraint in constraints[0]["joint_constraints"]:
        joint = constraint["joint_name"]
        if joint not in index:
            raise SystemExit(f"{name}: goal joint {joint} is not in the start state")
        i = index[joint]
        constraint["position"], joints["position"][i] = joints["position"][i], constraint["position"]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source", type=Path, help="a MotionBenchMaker folder (request*.yaml, scene*.yaml)")
    parser.add_argument("target", type=Path, help="the folder to write (must not exist)")
    args = parser.parse_args()
    requests = sorted(args.source.glob("request*.yaml"))
    if not requests:
        raise SystemExit(f"{args.source}: no request*.yaml files")
    if args.target.exists():
        raise SystemExit(f"{args.target} exists; remove it or choose another folder")
    shutil.copytree(args.source, args.target)
    for path in sorted(args.target.glob("request*.yaml")):
        request = yaml.safe_load(path.read_text())
        swap(request, str(path))
        path.write_text(yaml.safe_dump(request))
    print(f"{args.target}: {len(requests)} requests with start and goal exchanged")
    return 0


if __name__ == "__main__":
    sys.exit(main())
