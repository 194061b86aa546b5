#!/usr/bin/env python3
"""Where a path bends: reads the output of `mit-star plan` (its `path (N states):` listing) and
prints the path's length, its straight line, and the states that add the most length — for each
interior state, how much longer the path is through it than along the chord of its two
neighbours (the weight `solution_corner_weights` draws corners by).

Usage:
    mit-star plan --problem mbm:target/box_panda --instance 13 --seed 13 --time 1 \\
        | python3 benches/tools/path_bends.py [TOP]

TOP (default 5) states are listed, largest first, numbered from 0 (the start). Euclidean
distances, as on the shipped arms' joint spaces. Standard library only.
"""
import math
import re
import sys

STATE = re.compile(r"^\s+\(([^()]*)\)\s*$")


def path_states(lines):
    """The states listed after the `path (N states):` line."""
    states, inside = [], False
    for line in lines:
        if re.match(r"^\s*path \(\d+ states\):", line):
            inside = True
            continue
        match = STATE.match(line) if inside else None
        if match:
            states.append([float(x) for x in match.group(1).split(",")])
        elif inside and states:
            break
    return states


def main():
    top = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    states = path_states(sys.stdin)
    if len(states) < 2:
        sys.exit("no path listing in the input (is it `mit-star plan`'s output?)")
    d = math.dist
    legs = [d(a, b) for a, b in zip(states, states[1:])]
    print(f"{len(states)} states, length {sum(legs):.4f}, "
          f"straight line {d(states[0], states[-1]):.4f}")
    bends = sorted(
        ((legs[k - 1] + legs[k] - d(states[k - 1], states[k + 1]), k)
         for k in range(1, len(states) - 1)),
        reverse=True,
    )
    for added, k in bends[:top]:
        print(f"state {k}: adds {added:.4f}")


main()
