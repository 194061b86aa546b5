#!/usr/bin/env python3
"""Where a planner's solves spend their time: inclusive shares of `perf` samples by stack frame.

Reads the output of `perf script` over a `perf record --call-graph dwarf` profile, keeps the
samples taken inside a solve (a frame containing `Planner>::solve`, so that loading the problems
is left out; `--root=TEXT` names another frame) and prints, for each pattern, the share of those
samples with a matching frame on their stack. A sample counts for every pattern it matches, so
the shares overlap (a configuration check inside a motion check counts for both). A pattern is a
substring of a frame's name; `A|B` matches either, `A&B` needs both on the same stack.

Usage (the arm figures of the guide's "Where an arm solve's time goes"):
    ARM_PROFILE_NO_CHECKS=1 ARM_PROFILE_SCENES=cage perf record -e cpu-clock -F 10000 \\
        --call-graph dwarf,16384 -o cage.data target/release/examples/arm_profile target 100 \\
        rrt-connect 10
    perf script -i cage.data > cage.txt
    python3 benches/tools/perf_shares.py cage.txt check_full_and_end \\
        'check_full_and_end&invalid_on' 'check_full_and_end&link_poses_in' \\
        'check_full_and_end&fill_on_line' certify_connection 'clock_gettime|Timespec>::now' \\
        ::nearest steer 'sample_uniform|draw_any'

Standard library only.
"""

import sys


def stacks(path):
    """Each sample's frames (function names, offsets cut), leaf first."""
    frames = []
    with open(path, errors="replace") as lines:
        for line in lines:
            if not line.strip():
                if frames:
                    yield frames
                frames = []
            elif line[0] in " \t":
                parts = line.split(None, 1)
                if len(parts) == 2:
                    frames.append(parts[1].split("+0x")[0].strip())
            else:
                frames = []  # a sample's header line
    if frames:
        yield frames


def matches(frames, pattern):
    """Whether the stack `frames` matches `pattern` (`A&B`: both, `A|B`: either)."""
    return all(
        any(any(option in frame for frame in frames) for option in part.split("|"))
        for part in pattern.split("&")
    )


def main(argv):
    root = "Planner>::solve"
    args = []
    for arg in argv:
        if arg.startswith("--root="):
            root = arg.removeprefix("--root=")
        else:
            args.append(arg)
    if len(args) < 2:
        sys.exit(__doc__)
    path, patterns = args[0], args[1:]
    inside = [frames for frames in stacks(path) if any(root in f for f in frames)]
    if not inside:
        sys.exit(f"no sample of {path} has a frame containing `{root}`")
    print(f"{len(inside)} samples inside `{root}`")
    print("| frames | share |")
    print("|---|---|")
    for pattern in patterns:
        share = 100 * sum(matches(frames, pattern) for frames in inside) / len(inside)
        print(f"| `{pattern}` | {share:.1f} % |")


if __name__ == "__main__":
    main(sys.argv[1:])
