#!/usr/bin/env python3
"""Sums a `perf report --no-children --sort symbol --stdio` listing (on stdin) into categories:
the per-point validity work, nearest neighbours, the RGG's neighbour lists, the two searches,
queues, sampling, the harness (database, files), kernel and allocation, and the rest.
Prints one line: `NAME category share% …` (NAME is the first argument)."""
import re
import sys

CATEGORIES = [
    ("validity", r"mit_star_validity::|World|GridWalker|bisection"),
    ("kd-tree", r"kd_tree|nearest"),
    ("neighbour lists", r"neighbour|graph::"),
    ("reverse search", r"reverse"),
    ("forward search", r"forward"),
    ("queues", r"heap|BinaryHeap|queue"),
    ("sampling", r"sampler|informed|rand|Xoshiro|gaussian|hyperspheroid"),
    ("harness", r"sqlite|csv|serde|json|fmt|write|mit_star_benches|plotters"),
    ("kernel/alloc", r"memmove|memcpy|malloc|free|memset|alloc"),
]

totals = {name: 0.0 for name, _ in CATEGORIES}
totals["other"] = 0.0
for line in sys.stdin:
    m = re.match(r"\s+([0-9.]+)%\s+\[(.)\]\s+(.*)", line)
    if not m:
        continue
    share, kind, symbol = float(m.group(1)), m.group(2), m.group(3)
    if kind == "k":
        totals["kernel/alloc"] += share
        continue
    for name, pattern in CATEGORIES:
        if re.search(pattern, symbol, re.IGNORECASE):
            totals[name] += share
            break
    else:
        totals["other"] += share
print(sys.argv[1] if len(sys.argv) > 1 else "profile",
      " · ".join("%s %.0f %%" % (k, v) for k, v in totals.items()))
