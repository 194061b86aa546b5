"""Ctrl-C (SIGINT) stops a long solve promptly and raises KeyboardInterrupt."""

from __future__ import annotations

import _thread
import signal
import threading
import time

import numpy as np
import pytest

import mit_star


@pytest.fixture(autouse=True)
def python_handles_ctrl_c():
    """Python's own SIGINT handler, as at a terminal. A process started in the background by a
    non-interactive shell inherits SIGINT ignored, and Python then leaves it ignored: Ctrl-C
    (and `_thread.interrupt_main`) would do nothing, whatever the planner does."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


def interrupt_after(seconds: float) -> threading.Timer:
    timer = threading.Timer(seconds, _thread.interrupt_main)
    timer.start()
    return timer


# Anytime planners (RRT-Connect returns at its first solution, before the signal).
@pytest.mark.parametrize("name", ["mit-star", "eit-star", "aorrtc", "informed-rrt-star"])
def test_ctrl_c_stops_a_long_solve(walls4: mit_star.Problem, name: str) -> None:
    planner = mit_star.Planner(name, walls4, seed=1)
    started = time.perf_counter()
    timer = interrupt_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        planner.solve(time=60.0)
    stopped = time.perf_counter() - started
    timer.join()
    assert stopped < 1.0, f"stopped after {stopped:.3f} s"
    # The planner is intact: it plans again.
    assert planner.solve(time=0.2).solved


def test_ctrl_c_stops_a_solve_with_a_python_checker(walls4: mit_star.Problem) -> None:
    def slow(state: np.ndarray) -> bool:
        time.sleep(1e-4)
        return walls4.is_valid(state)

    planner = mit_star.MitStar(walls4, seed=1, validity=slow)
    started = time.perf_counter()
    timer = interrupt_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        planner.solve(time=60.0)
    timer.join()
    assert time.perf_counter() - started < 1.0


def test_other_threads_run_while_planning(walls4: mit_star.Problem) -> None:
    ticks = []
    done = threading.Event()

    def tick() -> None:
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.01)

    thread = threading.Thread(target=tick)
    thread.start()
    mit_star.MitStar(walls4, seed=1).solve(time=0.5)
    done.set()
    thread.join()
    assert len(ticks) > 20  # the GIL was released while planning
