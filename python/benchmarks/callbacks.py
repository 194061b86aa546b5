"""What a validity checker written in Python costs: MIT* on dividing walls R^4 for a fixed
number of iterations with the built-in box world, a scalar Python checker and a vectorised
(numpy) one, all with exactly the same answers.

A checker called one state at a time gives the built-in world's search (same seed, same
answers: asserted). A vectorised checker gives another search: with a batch width above one
the samplers draw their candidates a batch ahead and check them together, which consumes
the random sequence in another order (the same law, another realisation). Its search is
asserted equal to that of the pure-Python scalar checker handed the same batches, so the two
compare like for like; against the built-in world the time of the scalar search is
subtracted (about 1 % of the vectorised run's).

    python python/benchmarks/callbacks.py --iterations 1000 --seeds 3 --batch 64
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

import mit_star
from dw_checker import check_agreement, numpy_scalar_checker, scalar_checker, vectorised_checker


def batched(scalar):
    """``scalar`` as a vectorised checker: one call per state of the batch it is handed."""

    def valid(states):
        return np.fromiter((scalar(x) for x in states), dtype=bool, count=len(states))

    return valid


def run(problem, seed, iterations, **checker):
    calls = {"n": 0, "states": 0}
    if "validity" in checker:
        inner = checker["validity"]

        def validity(x):
            calls["n"] += 1
            calls["states"] += 1
            return inner(x)

        checker = {**checker, "validity": validity}
    if "vectorized" in checker:
        inner_many = checker["vectorized"]

        def vectorized(xs):
            calls["n"] += 1
            calls["states"] += len(xs)
            return inner_many(xs)

        checker = {**checker, "vectorized": vectorized}
    started = time.perf_counter()
    result = mit_star.MitStar(problem, seed=seed, **checker).solve(iterations=iterations)
    return time.perf_counter() - started, result, calls


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--iterations", type=int, default=20000)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--batch", type=int, default=64)
    args = parser.parse_args()
    problem = mit_star.Problem("dividing-walls", 4)
    check_agreement(problem)
    scalar, vector = scalar_checker(problem), vectorised_checker(problem)
    numpy_scalar = numpy_scalar_checker(problem)

    # The checkers alone, called from Python (no planner).
    states = np.random.default_rng(1).uniform(-0.5, 0.5, size=(20000, 4))
    t = time.perf_counter()
    for s in states:
        scalar(s)
    alone_scalar = (time.perf_counter() - t) / len(states)
    t = time.perf_counter()
    for i in range(0, len(states), args.batch):
        vector(states[i : i + args.batch])
    alone_vector = (time.perf_counter() - t) / len(states)

    rows = {
        "built-in": [],
        "scalar": [],
        "numpy scalar": [],
        "batched scalar": [],
        "vectorised": [],
    }
    for seed in range(args.seeds):
        base_time, base, _ = run(problem, seed, args.iterations)
        s_time, s_result, s_calls = run(problem, seed, args.iterations, validity=scalar)
        n_time, n_result, n_calls = run(problem, seed, args.iterations, validity=numpy_scalar)
        assert n_result.cost == base.cost, "different searches"
        rows["numpy scalar"].append((n_time, n_calls["n"], n_calls["states"]))
        v_time, v_result, v_calls = run(
            problem, seed, args.iterations, vectorized=vector, batch=args.batch
        )
        b_time, b_result, b_calls = run(
            problem, seed, args.iterations, vectorized=batched(scalar), batch=args.batch
        )
        assert s_result.cost == base.cost, "the scalar checker's search differs"
        assert v_result.cost == b_result.cost and v_calls == b_calls, (
            "the vectorised checker's search differs from the scalar checker's in the same batches"
        )
        rows["batched scalar"].append((b_time, b_calls["n"], b_calls["states"]))
        rows["built-in"].append((base_time, 0, 0))
        rows["scalar"].append((s_time, s_calls["n"], s_calls["states"]))
        rows["vectorised"].append((v_time, v_calls["n"], v_calls["states"]))
        print(
            f"seed {seed}: built-in {base_time:.3f} s; scalar {s_time:.3f} s, {s_calls['n']} calls; "
            f"numpy scalar {n_time:.3f} s; "
            f"vectorised {v_time:.3f} s, {v_calls['n']} calls, {v_calls['states']} states; "
            f"pure-Python scalar in the same batches {b_time:.3f} s"
        )
    base = statistics.median(t for t, _, _ in rows["built-in"])
    print(f"\nMIT* on {problem.id}, {args.iterations} iterations, median of {args.seeds} seeds:")
    print(f"  built-in box world: {base:.3f} s")
    per_state = {}
    for name in ("scalar", "numpy scalar", "batched scalar", "vectorised"):
        t = statistics.median(t for t, _, _ in rows[name])
        calls = statistics.median(c for _, c, _ in rows[name])
        states = statistics.median(s for _, _, s in rows[name])
        per_state[name] = (t - base) / states
        print(
            f"  {name:12}: {t:.3f} s ({t / base:.1f}x the built-in), {calls:.0f} calls, "
            f"{states:.0f} states: {1e6 * (t - base) / calls:.2f} us per call, "
            f"{1e6 * per_state[name]:.3f} us per state above the built-in"
        )
    print(
        f"  vectorised is {per_state['numpy scalar'] / per_state['vectorised']:.1f}x cheaper per "
        f"state than the same numpy code called per state, "
        f"{per_state['scalar'] / per_state['vectorised']:.1f}x cheaper than the pure-Python "
        f"scalar checker (batches of up to {args.batch}); in the same search, "
        f"{per_state['batched scalar'] / per_state['vectorised']:.1f}x cheaper than the "
        f"pure-Python scalar checker handed the same batches"
    )
    print(
        f"  the checkers alone, from Python: scalar {1e6 * alone_scalar:.2f} us per state, "
        f"vectorised {1e6 * alone_vector:.3f} us per state (batches of {args.batch})"
    )


if __name__ == "__main__":
    main()
