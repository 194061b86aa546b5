"""Plans for the Franka Panda in a MotionBenchMaker problem and prints the path.

    mkdir -p target && tar xjf robot/data/panda/mbm_problems.tar.bz2 -C target/
    pip install ./python
    python examples/python/plan_panda.py --scene target/bookshelf_small_panda --instance 3

The scene folders (`target/<scene>_panda`) are extracted from the shipped archive when they
are missing.
"""

from __future__ import annotations

import argparse
import tarfile
from pathlib import Path

import numpy as np

import mit_star

ARCHIVE = Path(__file__).resolve().parents[2] / "robot" / "data" / "panda" / "mbm_problems.tar.bz2"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", type=Path, default=Path("target/bookshelf_small_panda"))
    parser.add_argument("--instance", type=int, default=3, help="problem index, 1-based")
    parser.add_argument("--planner", default="mit-star", choices=mit_star.planners())
    parser.add_argument("--time", type=float, default=1.0, help="seconds")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()

    if not args.scene.is_dir():
        args.scene.parent.mkdir(parents=True, exist_ok=True)
        with tarfile.open(ARCHIVE) as tar:
            tar.extractall(args.scene.parent, filter="data")
    problem = mit_star.Problem.mbm(args.scene, args.instance, robot="panda")
    planner = mit_star.Planner(args.planner, problem, seed=args.seed)
    result = planner.solve(time=args.time)
    print(f"{planner.name} on {problem.id} ({problem.dimension} joints), {args.time} s:")
    if not result.solved:
        print("no solution")
        return
    first = result.trace[0]
    print(f"first solution after {first[0] * 1000:.1f} ms (cost {first[1]:.3f}), final cost {result.cost:.3f}")
    np.set_printoptions(precision=3, suppress=True, linewidth=120)
    print(f"path of {len(result.path)} configurations (radians):")
    print(result.path)


if __name__ == "__main__":
    main()
