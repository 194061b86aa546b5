#!/usr/bin/env python3
"""Summarise first-solution runs of `mit-star bench` (runs.csv) for the ablation study.

Usage: ablation-summary.py RESULTS_FOLDER [RESULTS_FOLDER ...] [--confidence 0.99] [--compact]

Per (folder, instance, planner): success, the median time to the first solution with its
nonparametric confidence interval, and the medians of the counters that explain it. Medians
and intervals are those of the KPI tables (`MedianEstimate` in
benches/src/statistics/median.rs, PDT's convention): the median is the value at index n/2 of
the sorted runs, failures count as +inf, and the interval grows from the median index one
order statistic each side until its binomial coverage reaches the confidence. Prints one
markdown table per instance; with --compact, one table per folder: a row per instance, a
column per planner, cells "median t_init [interval] ms · median grid points tested".
"""
import csv
import math
import sys
from pathlib import Path


def binom_cdf(k, n, p=0.5):
    return sum(math.comb(n, i) for i in range(0, k + 1)) * p ** n


def median_interval(values, confidence):
    """Median and its confidence bounds, as `MedianEstimate::of` computes them."""
    v = sorted(values)
    n = len(v)
    m = n // 2
    j = 0
    while True:
        lower, upper = max(m - j, 0), min(m + j, n - 1)
        coverage = binom_cdf(upper, n) - binom_cdf(lower, n)
        if coverage >= confidence - 1e-12 or (lower == 0 and upper == n - 1):
            return v[m], (v[lower], v[upper])
        j += 1


def median(values):
    """The value at index n/2 of the sorted values (the KPI tables' median)."""
    v = sorted(values)
    return v[len(v) // 2]


COUNTERS = [
    ("points_tested", "points"),
    ("reverse_restarts", "restarts"),
    ("batches", "batches"),
    ("samples", "samples"),
    ("sampler_gaussian", "gauss"),
    ("sampler_bridge", "bridge"),
    ("estimate_initial", "s_est0"),
    ("estimate_final", "s_est"),
    ("estimate_batches", "EIS batches"),
]


def fmt(x):
    if x == math.inf:
        return "∞"
    if x == 0:
        return "0"
    if abs(x) >= 1000:
        return f"{x:.3g}"
    return f"{x:.3g}"


def main():
    args = sys.argv[1:]
    confidence = 0.99
    if "--confidence" in args:
        i = args.index("--confidence")
        confidence = float(args[i + 1])
        del args[i : i + 2]
    compact = "--compact" in args
    if compact:
        args.remove("--compact")
    rows = []
    for folder in args:
        label = Path(folder).name
        with open(Path(folder) / "runs.csv") as f:
            for r in csv.DictReader(f):
                r["_folder"] = label
                rows.append(r)
    def order(instance):
        # `dividing-walls-n4`, `random-rectangles-n8-i1`: family, dimension, layout.
        family, _, rest = instance.rpartition("-n")
        parts = rest.split("-i")
        return (family, int(parts[0]), parts[1] if len(parts) > 1 else "")

    instances = sorted({r["instance"] for r in rows}, key=order)
    if compact:
        print_compact(rows, instances, confidence)
        return
    for inst in instances:
        print(f"\n### {inst}\n")
        head = ["run set", "planner", "success", "t_init median [CI] ms"] + [c[1] for c in COUNTERS]
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        groups = {}
        for r in rows:
            if r["instance"] == inst:
                groups.setdefault((r["_folder"], r["planner"]), []).append(r)
        for (folder, planner), rs in groups.items():
            times = [
                float(r["initial_time"]) if r["success"] == "true" and r["initial_time"] else math.inf
                for r in rs
            ]
            med, (lo, hi) = median_interval(times, confidence)
            ok = sum(r["success"] == "true" for r in rs)
            cells = [folder, planner, f"{ok}/{len(rs)}",
                     f"{fmt(1e3 * med)} [{fmt(1e3 * lo)}, {fmt(1e3 * hi)}]"]
            for col, _ in COUNTERS:
                vals = sorted(float(r[col]) for r in rs if r.get(col) not in ("", None))
                cells.append(fmt(median(vals)) if vals else "–")
            print("| " + " | ".join(cells) + " |")


def print_compact(rows, instances, confidence):
    folders = list(dict.fromkeys(r["_folder"] for r in rows))
    for folder in folders:
        mine = [r for r in rows if r["_folder"] == folder]
        order = ["MIT*", "EIT*", "MIT*-AS", "MIT*-EIS", "MIT*-SC", "MIT*-SR"]
        planners = sorted(
            dict.fromkeys(r["planner"] for r in mine),
            key=lambda p: order.index(p) if p in order else len(order),
        )
        print(f"\n{folder}:\n")
        print("| problem | " + " | ".join(planners) + " |")
        print("|---|" + "---|" * len(planners))
        for inst in instances:
            cells = []
            for p in planners:
                rs = [r for r in mine if r["instance"] == inst and r["planner"] == p]
                if not rs:
                    cells.append("–")
                    continue
                times = [
                    float(r["initial_time"]) if r["success"] == "true" and r["initial_time"] else math.inf
                    for r in rs
                ]
                med, (lo, hi) = median_interval(times, confidence)
                pts = median(float(r["points_tested"]) for r in rs)
                ok = sum(r["success"] == "true" for r in rs)
                miss = "" if ok == len(rs) else f" ({len(rs) - ok} failed)"
                cells.append(
                    f"{fmt(1e3 * med)} [{fmt(1e3 * lo)}, {fmt(1e3 * hi)}] · {pts / 1e3:.0f}k{miss}"
                )
            print(f"| {inst} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
