"""PDT's dividing walls as Python validity checkers — scalar (pure Python) and vectorised
(numpy) — with exactly the semantics of the built-in box world: a state is invalid inside an
obstacle unless it is inside an anti-obstacle (closed boxes, PDT's tolerance)."""

from __future__ import annotations

import tomllib

import numpy as np

import mit_star

FREE = 1000  # the weight of an anti-obstacle in the vectorised score
EPSILON = 1e-9  # mit_star_validity::World's tolerance on box membership is tiny; agreement is checked


def boxes(problem: mit_star.Problem, key: str) -> list[tuple[list[float], list[float]]]:
    table = tomllib.loads(problem.describe())
    return [
        (
            [c - w / 2 for c, w in zip(b["center"], b["widths"])],
            [c + w / 2 for c, w in zip(b["center"], b["widths"])],
        )
        for b in table.get(key, [])
    ]


def scalar_checker(problem: mit_star.Problem):
    """``valid(state)`` in pure Python (a numpy array, taken as a list, or an OMPL state, indexed)."""
    obstacles = boxes(problem, "obstacles")
    free = boxes(problem, "anti_obstacles")
    d = problem.dimension

    def inside(x, box) -> bool:
        lo, hi = box
        for i in range(d):
            if not (lo[i] - EPSILON <= x[i] <= hi[i] + EPSILON):
                return False
        return True

    def valid(x) -> bool:
        if hasattr(x, "tolist"):
            x = x.tolist()  # a numpy array: Python floats index and compare faster
        for box in obstacles:
            if inside(x, box):
                return any(inside(x, f) for f in free)
        return True

    return valid


def vectorised_checker(problem: mit_star.Problem):
    """``valid(states)`` on an (n, d) array, in numpy: every box in one broadcast test
    (obstacles first, then anti-obstacles); valid unless in an obstacle and in no
    anti-obstacle."""
    obstacles = boxes(problem, "obstacles")
    free = boxes(problem, "anti_obstacles")
    every = obstacles + free
    centre = np.array([[(lo + hi) / 2 for lo, hi in zip(*b)] for b in every])
    half = np.array([[(hi - lo) / 2 + EPSILON for lo, hi in zip(*b)] for b in every])
    # Obstacles weigh 1, anti-obstacles `FREE`: valid when the score is 0 (in no obstacle)
    # or at least `FREE` (in an anti-obstacle).
    weights = np.array([1] * len(obstacles) + [FREE] * len(free), dtype=np.int32)
    all_four = np.uint32(0x01010101)  # four true bytes: a 4-D state inside a box

    def valid(states: np.ndarray) -> np.ndarray:
        offset = states[:, None, :] - centre
        np.abs(offset, out=offset)
        near = offset <= half
        if near.shape[2] == 4:
            inside = near.view(np.uint32)[..., 0] == all_four
        else:
            inside = near.all(axis=2)
        score = inside.view(np.uint8) @ weights
        return (score == 0) | (score >= FREE)

    return valid


def numpy_scalar_checker(problem: mit_star.Problem):
    """``valid(state)``: the vectorised numpy code on one state (what a numpy checker written
    for one state costs)."""
    vector = vectorised_checker(problem)

    def valid(state: np.ndarray) -> bool:
        return bool(vector(np.asarray(state)[None, :])[0])

    return valid


def check_agreement(problem: mit_star.Problem, samples: int = 20000) -> None:
    """The checkers answer what the built-in world answers (random states, and states near
    the walls)."""
    rng = np.random.default_rng(0)
    lower, upper = problem.bounds
    states = rng.uniform(lower, upper, size=(samples, problem.dimension))
    states[: samples // 2, 0] = rng.choice([-0.275, -0.225, -0.05, 0.05, 0.225, 0.275], samples // 2)
    scalar, vector = scalar_checker(problem), vectorised_checker(problem)
    one = numpy_scalar_checker(problem)
    assert all(one(s) == problem.is_valid(s) for s in states[:2000]), "numpy scalar disagrees"
    built_in = np.array([problem.is_valid(s) for s in states])
    assert np.array_equal(built_in, np.array([scalar(s) for s in states])), "scalar disagrees"
    assert np.array_equal(built_in, vector(states)), "vectorised disagrees"
