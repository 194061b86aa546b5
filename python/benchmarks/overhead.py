"""Python overhead against Rust: the same plans (same problem, planner, seeds and iteration
counts, so the same work and the same costs) built and solved through ``mit_star`` and through
the Rust example ``rust_baseline``, alternating sides round by round in one run.

    cargo build --release -p mit-star-python --example rust_baseline
    python python/benchmarks/overhead.py dividing-walls 4 --iterations 200000 --seeds 10
    python python/benchmarks/overhead.py mbm:target/box_panda 1 --iterations 20000 --seeds 10
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import time
from pathlib import Path

import mit_star

BINARY = Path(__file__).resolve().parents[2] / "target" / "release" / "examples" / "rust_baseline"


def python_side(problem: mit_star.Problem, planner: str, iterations: int, seeds: range):
    rows = []
    for seed in seeds:
        started = time.perf_counter()
        result = mit_star.Planner(planner, problem, seed=seed).solve(iterations=iterations)
        rows.append((seed, time.perf_counter() - started, result.cost))
    return rows


def rust_side(spec: str, number: int, planner: str, iterations: int, seeds: range):
    out = subprocess.run(
        [str(BINARY), spec, str(number), planner, str(iterations), f"{seeds.start}..{seeds.stop}"],
        check=True, capture_output=True, text=True,
    ).stdout
    return [(int(s), float(t), float(c)) for s, t, c in (line.split() for line in out.splitlines())]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("problem")
    parser.add_argument("number", type=int, help="dimension, or instance of an mbm: folder")
    parser.add_argument("--planner", default="mit-star")
    parser.add_argument("--iterations", type=int, default=200000)
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--rounds", type=int, default=4)
    args = parser.parse_args()
    arm = args.problem.startswith("mbm:")
    problem = (
        mit_star.Problem(args.problem, instance=args.number)
        if arm else mit_star.Problem(args.problem, args.number)
    )
    seeds = range(args.seeds)
    totals = {"rust": [], "python": []}
    for round_ in range(args.rounds):
        order = ["rust", "python"] if round_ % 2 == 0 else ["python", "rust"]
        rows = {}
        for side in order:
            if side == "rust":
                rows[side] = rust_side(args.problem, args.number, args.planner, args.iterations, seeds)
            else:
                rows[side] = python_side(problem, args.planner, args.iterations, seeds)
            totals[side].append(sum(t for _, t, _ in rows[side]))
        same = all(
            abs(a[2] - b[2]) <= 1e-6 * max(1.0, abs(a[2])) or a[2] == b[2]
            for a, b in zip(rows["rust"], rows["python"])
        )
        print(
            f"round {round_}: rust {totals['rust'][-1]:.3f} s, python {totals['python'][-1]:.3f} s, "
            f"same costs: {same}"
        )
    rust = statistics.median(totals["rust"])
    python = statistics.median(totals["python"])
    print(
        f"{problem.id} {args.planner} {args.iterations} iterations x {args.seeds} seeds: "
        f"median over {args.rounds} rounds: rust {rust:.3f} s, python {python:.3f} s, "
        f"overhead {100 * (python / rust - 1):+.2f} %"
    )


if __name__ == "__main__":
    main()
