#!/usr/bin/env python3
"""Summarize side_by_side.sh: per scene, medians over problems of each problem's median time."""
import csv, glob, math, statistics as st, sys

out, scenes = sys.argv[1], sys.argv[2:]
vamp, ours, fails = {}, {}, {}
for f in glob.glob(f"{out}/vamp_*.csv"):
    for r in csv.DictReader(open(f)):
        if r["scene"] in scenes and r.get("solved", "1") == "1":
            vamp.setdefault((r["scene"], int(r["index"])), []).append(float(r["plan_us"]))
for d in glob.glob(f"{out}/ours_*"):
    for s in scenes:
        try:
            rows = list(csv.DictReader(open(f"{d}/{s}/runs.csv")))
        except FileNotFoundError:
            continue
        for r in rows:
            k = (s, int(r["instance_seed"]))
            if r["success"] == "true":
                ours.setdefault(k, []).append((float(r["initial_time"]) - float(r["setup_time"])) * 1e6)
            else:
                fails[k] = fails.get(k, 0) + 1

def p95(v):
    v = sorted(v)
    return v[min(len(v) - 1, math.ceil(0.95 * len(v)) - 1)]

print("| scene | VAMP median µs | mit-star median µs | mit-star / VAMP | VAMP p95 | mit-star p95 | p95 ratio | mit-star unsolved |")
print("|---|---|---|---|---|---|---|---|")
pool_v, pool_o = [], []
for s in scenes + ["all"]:
    keys = [k for k in set(vamp) | set(ours) if s == "all" or k[0] == s]
    v = [st.median(vamp[k]) for k in keys if k in vamp]
    o = [st.median(ours[k]) for k in keys if k in ours]
    nf = sum(n for k, n in fails.items() if s == "all" or k[0] == s)
    if v and o:
        print(f"| {s} | {st.median(v):.0f} | {st.median(o):.0f} | {st.median(o)/st.median(v):.2f}× "
              f"| {p95(v):.0f} | {p95(o):.0f} | {p95(o)/p95(v):.2f}× | {nf} |")
