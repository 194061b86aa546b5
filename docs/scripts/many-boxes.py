#!/usr/bin/env python3
"""Writes a 2-D problem file with many small random boxes, for the large-world figures in
docs/guide/src/reference/reliability.md ("Construction in a large world"):

    python3 docs/scripts/many-boxes.py 100000 big.toml
    mit-star plan --problem-file big.toml --time 0.001 --no-picture

Boxes have sides 0.001-0.002 and centres in [0.05, 0.95]^2 of the unit square (seed 1), so the
start (0.02, 0.02) and goal (0.98, 0.98) stay free.
"""
import random
import sys

count = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
out = sys.argv[2] if len(sys.argv) > 2 else "big.toml"
random.seed(1)
with open(out, "w") as f:
    f.write('name = "big"\nstart = [0.02, 0.02]\ngoal = [0.98, 0.98]\n')
    f.write("[bounds]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n")
    for _ in range(count):
        c = [random.uniform(0.05, 0.95), random.uniform(0.05, 0.95)]
        w = [random.uniform(0.001, 0.002), random.uniform(0.001, 0.002)]
        f.write(f"[[obstacles]]\ncenter = [{c[0]:.6f}, {c[1]:.6f}]\n")
        f.write(f"widths = [{w[0]:.6f}, {w[1]:.6f}]\n")
