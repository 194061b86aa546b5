#!/usr/bin/env python3
"""Summarise first-solution runs of `mit-star bench` (runs.csv) for the ablation study.

Usage: ablation-summary.py RESULTS_FOLDER [RESULTS_FOLDER ...] [--confidence 0.99] [--compact]

Per (folder, instance, planner): success, the median time to the first solution with its
nonparametric confidence interval (order statistics of the binomial, failures counted as
+inf, as in the KPI tables), and the medians of the counters that explain it. Prints one
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
    """Median and the (lo, hi) order statistics covering it with `confidence`."""
    v = sorted(values)
    n = len(v)
    med = v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])
    # The widest symmetric pair of order statistics whose coverage still reaches `confidence`
    # is tightened until one step more would fall short: with 0-based indices lo and hi,
    # P(v[lo] <= median <= v[hi]) = P(lo + 1 <= B <= hi) for B ~ Bin(n, 1/2).
    best = (v[0], v[-1])
    for lo in range(0, n // 2):
        hi = n - 1 - lo
        if binom_cdf(hi, n) - binom_cdf(lo, n) >= confidence:
            best = (v[lo], v[hi])
        else:
            break
    return med, best


COUNTERS = [
    ("edge_points_tested", "points"),
    ("reverse_search_restarts", "restarts"),
    ("batches", "batches"),
    ("samples", "samples"),
    ("sampler_gaussian_repairs", "gauss"),
    ("sampler_bridge_repairs", "bridge"),
    ("estimated_informed_set_initial_cost", "s_est0"),
    ("estimated_informed_set_final_cost", "s_est"),
    ("estimated_informed_set_batches", "EIS batches"),
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
                if not vals:
                    cells.append("–")
                else:
                    m = vals[len(vals) // 2] if len(vals) % 2 else 0.5 * (vals[len(vals) // 2 - 1] + vals[len(vals) // 2])
                    cells.append(fmt(m))
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
                pts = sorted(float(r["edge_points_tested"]) for r in rs)
                ok = sum(r["success"] == "true" for r in rs)
                miss = "" if ok == len(rs) else f" ({len(rs) - ok} failed)"
                cells.append(
                    f"{fmt(1e3 * med)} [{fmt(1e3 * lo)}, {fmt(1e3 * hi)}] · {pts[len(pts) // 2] / 1e3:.0f}k{miss}"
                )
            print(f"| {inst} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
