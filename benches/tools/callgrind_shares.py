#!/usr/bin/env python3
"""Where a typical solve's instructions go: callgrind shares over the middle half of the solves.

Callgrind's totals over many solves are dominated by the few longest ones. Run the profiler
with one dump per solve, then this script: it ranks the dumps by instructions, keeps the middle
half (25th to 75th percentile) and prints, for each pattern, its inclusive share of their
instructions: per dump, the largest `callgrind_annotate --inclusive=yes` line the regular
expression matches. Callgrind may list a function several times (per source file of inlined
code, with and without the object's name), with overlapping counts; the largest is taken, so
a pattern should name one function, not a prefix nested functions share.

Usage:
    mkdir -p DIR
    ARM_PROFILE_NO_CHECKS=1 valgrind --tool=callgrind --callgrind-out-file=DIR/cg.out \\
        --toggle-collect='*as mit_star::planner::Planner>::solve' \\
        --dump-after='*as mit_star::planner::Planner>::solve' \\
        target/release/examples/arm_profile target 20 mit-star 1
    python3 benches/tools/callgrind_shares.py DIR PATTERN ...

Needs `callgrind_annotate` (valgrind) on the PATH; standard library otherwise.
"""

import glob
import re
import subprocess
import sys


def total(path):
    """The dump's instruction count (its `summary:` or `totals:` line), or 0."""
    with open(path) as f:
        for line in f:
            if line.startswith(("summary:", "totals:")):
                return int(line.split()[1])
    return 0


def inclusive(path):
    """(instructions, function) lines of the dump's inclusive table."""
    out = subprocess.run(
        ["callgrind_annotate", "--auto=no", "--inclusive=yes", "--threshold=100", path],
        capture_output=True, text=True, check=True,
    ).stdout
    for line in out.splitlines():
        m = re.match(r"\s*([\d,]+) \(.*?\)\s+(.*)", line)
        if m:
            yield int(m.group(1).replace(",", "")), m.group(2)


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    folder, patterns = sys.argv[1], sys.argv[2:]
    dumps = sorted((total(p), p) for p in glob.glob(folder + "/cg.out.*"))
    dumps = [(n, p) for n, p in dumps if n > 0]
    if not dumps:
        sys.exit(f"no callgrind dumps with instructions in {folder}")
    middle = dumps[len(dumps) // 4: 3 * len(dumps) // 4] or dumps
    print(f"{len(dumps)} solves; median {dumps[len(dumps) // 2][0]:,} instructions; "
          f"middle half {middle[0][0]:,} to {middle[-1][0]:,}")
    found = dict.fromkeys(patterns, 0)
    for _, path in middle:
        largest = dict.fromkeys(patterns, 0)
        for cost, name in inclusive(path):
            for p in patterns:
                if re.search(p, name):
                    largest[p] = max(largest[p], cost)
        for p in patterns:
            found[p] += largest[p]
    whole = sum(n for n, _ in middle)
    for p in patterns:
        print(f"{100 * found[p] / whole:6.1f} %  {p}")


if __name__ == "__main__":
    main()
