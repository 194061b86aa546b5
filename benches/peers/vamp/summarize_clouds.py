#!/usr/bin/env python3
"""The tables of side_by_side_clouds.sh: python3 summarize_clouds.py OUT SCENE…

Per problem, each figure is its median over the rounds; per scene, the median and the 95th
percentile of those over the scene's problems ("all": every problem pooled). Times: VAMP's as
its bindings and planner report them; ours from `plan --json` (planning: `initial_time −
setup_time`, the solve alone, as VAMP's timer starts at its solve call) and from the `cloud:`
lines on its stderr (each filter step's and the tree's time, printed to 0.01 ms).
Ratios are ours / VAMP's.
"""
import csv
import glob
import json
import math
import os
import re
import statistics as st
import sys

OUT, SCENES = sys.argv[1], sys.argv[2:]
KEPT = re.compile(r"^cloud: (crop to|points at least|one point per|the robot's own).*?: (\d+) of (\d+) points kept in ([\d.]+) ms")
TREE = re.compile(r"^cloud: tree of (\d+) points .* built in ([\d.]+) ms")


def p95(v):
    v = sorted(v)
    return v[min(len(v) - 1, math.ceil(0.95 * len(v)) - 1)]


def add(table, key, field, value):
    table.setdefault(key, {}).setdefault(field, []).append(value)


vamp = {}  # (scene, index) -> field -> [values over rounds]
# Round -> side -> RRT-Connect's planning times among VAMP's points, the chosen scenes' solved
# problems: the pooled ratio round by round.
by_round = {}
for f in glob.glob(f"{OUT}/vamp_*/vamp.csv"):
    round_ = f.split(os.sep)[-2][len("vamp_"):]
    for r in csv.DictReader(open(f)):
        k = (r["scene"], int(r["index"]))
        for field in ("filtered", "filter_us", "build_us"):
            add(vamp, k, field, float(r[field]))
        add(vamp, k, "solved", int(r["solved"]))
        if r["solved"] == "1":
            add(vamp, k, "plan_us", float(r["plan_us"]))
            if r["scene"] in SCENES:
                add(by_round, round_, "vamp", float(r["plan_us"]))

vamp_prim = {}  # (scene, index) -> plan_us over rounds: the shared vamp_mbm among primitives
for f in glob.glob(f"{OUT}/vamp_prim_*.csv"):
    for r in csv.DictReader(open(f)):
        if r["scene"] in SCENES and r["solved"] == "1":
            add(vamp_prim, (r["scene"], int(r["index"])), "plan_us", float(r["plan_us"]))

ours = {}  # (variant/planner) -> (scene, index) -> field -> [values]
for f in glob.glob(f"{OUT}/ours_*/*/*/*.json"):
    parts = f.split(os.sep)
    tag = f"{parts[-3]}/{parts[-2]}"
    name = parts[-1][:-5]
    scene, index = name.rsplit("_", 1)
    k = (scene, int(index))
    table = ours.setdefault(tag, {})
    filter_ms, build_ms, points = 0.0, None, None
    for line in open(f[:-5] + ".err"):
        if m := KEPT.match(line):
            filter_ms += float(m.group(4))
        elif m := TREE.match(line):
            points, build_ms = int(m.group(1)), float(m.group(2))
    if build_ms is not None:
        add(table, k, "filter_us", filter_ms * 1e3)
        add(table, k, "build_us", build_ms * 1e3)
        add(table, k, "points", points)
    try:
        record = json.load(open(f))
    except (json.JSONDecodeError, OSError):
        add(table, k, "status", "error")
        continue
    add(table, k, "status", record["status"])
    if record["status"] == "solved":
        plan_us = (record["initial_time"] - record["setup_time"]) * 1e6
        add(table, k, "plan_us", plan_us)
        if tag == "same/rrt-connect" and scene in SCENES:
            add(by_round, parts[-4][len("ours_"):], "ours", plan_us)
        checks = record["counters"]["validity_checks"]
        add(table, k, "checks", checks)
        add(table, k, "ns_per_check", plan_us * 1e3 / max(checks, 1))

# Fidelity: check-path's verdicts, once (round 1).
fidelity = {}  # (who, against) -> (scene, index) -> "valid" | reason
for f in glob.glob(f"{OUT}/fidelity/*.txt"):
    who, against, name = os.path.basename(f)[:-4].rsplit(".", 2)
    scene, index = name.rsplit("_", 1)
    text = open(f).read()
    m = re.search(r"independent check: (valid|invalid \((.*)\))", text)
    verdict = "valid" if m and m.group(1) == "valid" else (m.group(2) if m else "no verdict: " + text[-200:])
    fidelity.setdefault((who, against), {})[(scene, int(index))] = verdict

judged = {}  # who -> (scene, index) -> valid by VAMP's own check among the primitives
for f in glob.glob(f"{OUT}/judge/*.csv"):
    who = os.path.basename(f)[:-4]
    for r in csv.DictReader(open(f)):
        judged.setdefault(who, {})[(r["scene"], int(r["index"]))] = r["valid_by_vamp"] == "1"


def per_problem(table, field, scene):
    return [st.median(v[field]) for k, v in table.items() if (scene == "all" or k[0] == scene) and field in v]


def med(v, scale=1.0, digits=2):
    return f"{st.median(v) * scale:.{digits}f}" if v else "–"


def ratio(a, b):
    return f"{st.median(a) / st.median(b):.2f}×" if a and b else "–"


def solved(table, scene):
    keys = [k for k in table if scene == "all" or k[0] == scene]
    ok = sum(1 for k in keys if st.median([s == "solved" for s in table[k]["status"]]) >= 0.5)
    return f"{ok}/{len(keys)}"


rows = SCENES + ["all"]
same = ours.get("same/rrt-connect", {})
raw = ours.get("raw/rrt-connect", {})
own = ours.get("own/rrt-connect", {})


def fb(table, scene):
    return [st.median(v["filter_us"]) + st.median(v["build_us"])
            for k, v in table.items() if (scene == "all" or k[0] == scene) and "build_us" in v]


print("Filtering and building, milliseconds, median over problems (points: after filtering)\n")
print("| scene | VAMP points | VAMP filter | VAMP CAPT build | ours: tree of VAMP's points | "
      "ours on VAMP's raw points: points, filter, build | ours, own sampling: points, filter, build | "
      "filter+build / VAMP's: raw · own |")
print("|---|---|---|---|---|---|---|---|")
for s in rows:
    vp = per_problem(vamp, "filtered", s)
    vf, vb = per_problem(vamp, "filter_us", s), per_problem(vamp, "build_us", s)
    vfb = [a + b for a, b in zip(vf, vb)]
    sb = per_problem(same, "build_us", s)
    cells = []
    for t in (raw, own):
        cells.append(f"{med(per_problem(t, 'points', s), 1, 0)} · {med(per_problem(t, 'filter_us', s), 1e-3)} · "
                     f"{med(per_problem(t, 'build_us', s), 1e-3)}")
    print(f"| {s} | {st.median(vp):.0f} | {med(vf, 1e-3)} | {med(vb, 1e-3)} | {med(sb, 1e-3)} | "
          f"{cells[0]} | {cells[1]} | {ratio(fb(raw, s), vfb)} · {ratio(fb(own, s), vfb)} |")

print("\nRRT-Connect, planning time in microseconds over each scene's problems (median · p95); "
      "solved/valid\n")
print("| scene | VAMP | solved | ours, VAMP's points | solved | median ratio | p95 ratio | "
      "ours, own sampling | solved |")
print("|---|---|---|---|---|---|---|---|---|")
for s in rows:
    v = per_problem(vamp, "plan_us", s)
    keys = [k for k in vamp if s == "all" or k[0] == s]
    vs = sum(1 for k in keys if st.median(vamp[k]["solved"]) >= 0.5)
    o, w = per_problem(same, "plan_us", s), per_problem(own, "plan_us", s)
    print(f"| {s} | {st.median(v):.0f} · {p95(v):.0f} | {vs}/{len(keys)} | "
          f"{st.median(o):.0f} · {p95(o):.0f} | {solved(same, s)} | {st.median(o) / st.median(v):.2f}× | "
          f"{p95(o) / p95(v):.2f}× | {st.median(w):.0f} · {p95(w):.0f} | {solved(own, s)} |")

# How much of the ratio is the run's own spread.
spread = [f"round {r} {st.median(t['ours']) / st.median(t['vamp']):.2f}× · "
          f"{p95(t['ours']) / p95(t['vamp']):.2f}×"
          for r, t in sorted(by_round.items()) if "ours" in t and "vamp" in t]
if spread:
    print("\nPooled ours / VAMP (median · p95), round by round: " + "; ".join(spread))

print("\nOurs to the first solution among VAMP's points, microseconds (median · p95); solved/valid\n")
print("| scene | AORRTC | solved | MIT* | solved |")
print("|---|---|---|---|---|")
for s in rows:
    cells = []
    for tag in ("same/aorrtc", "same/mit-star"):
        t = ours.get(tag, {})
        v = per_problem(t, "plan_us", s)
        cells.append(f"{st.median(v):.0f} · {p95(v):.0f} | {solved(t, s)}" if v else "– | –")
    print(f"| {s} | {cells[0]} | {cells[1]} |")


print("\nWhat the clouds cost each side: RRT-Connect among the primitives (VAMP: the shared "
      "vamp_mbm harness; ours: the same runs without a cloud), median µs, beside the same among VAMP's "
      "cloud; and ours per configuration checked (planning time / configurations checked, "
      "median over problems, ns)\n")
print("| scene | VAMP, primitives | VAMP, cloud | cloud / primitives | ours, primitives | "
      "ours, cloud | cloud / primitives | ours: configurations checked, primitives · cloud | "
      "ours: ns a configuration, primitives · cloud |")
print("|---|---|---|---|---|---|---|---|---|")
prim = ours.get("prim/rrt-connect", {})
for s in rows:
    vp, vc = per_problem(vamp_prim, "plan_us", s), per_problem(vamp, "plan_us", s)
    op, oc = per_problem(prim, "plan_us", s), per_problem(same, "plan_us", s)
    if not (vp and op):
        continue
    print(f"| {s} | {st.median(vp):.0f} | {st.median(vc):.0f} | {ratio(vc, vp)} | {st.median(op):.0f} | "
          f"{st.median(oc):.0f} | {ratio(oc, op)} | {med(per_problem(prim, 'checks', s), 1, 0)} · "
          f"{med(per_problem(same, 'checks', s), 1, 0)} | {med(per_problem(prim, 'ns_per_check', s), 1, 0)} · "
          f"{med(per_problem(same, 'ns_per_check', s), 1, 0)} |")


def flagged(who, against, scene):
    """Paths found in collision / paths with a verdict (a problem whose start or goal meets
    the cloud gets none)."""
    t = fidelity.get((who, against), {})
    keys = [k for k in t if (scene == "all" or k[0] == scene) and not t[k].startswith("no verdict")]
    return f"{sum(1 for k in keys if t[k] != 'valid')}/{len(keys)}"


def invalid_in_cloud(tag, scene):
    t = ours.get(tag, {})
    keys = [k for k in t if scene == "all" or k[0] == scene]
    return sum(1 for k in keys if "invalid-path" in t[k]["status"])


WHO = [("vamp", "VAMP"), ("same.rrt-connect", "RRT-Connect"), ("same.aorrtc", "AORRTC"),
       ("same.mit-star", "MIT*"), ("own.rrt-connect", "RRT-Connect, own sampling"),
       ("raw.rrt-connect", "RRT-Connect, VAMP's raw points"),
       ("prim.rrt-connect", "RRT-Connect among the primitives (no cloud)")]
print("\nFidelity: returned paths that the independent continuous check (f64) finds in collision "
      "with the scene's TRUE primitives, of the paths returned (round 1); ours among VAMP's points "
      "unless said\n")
print("| scene | " + " | ".join(name for _, name in WHO) + " |")
print("|---|" + "---|" * len(WHO))
for s in rows:
    print(f"| {s} | " + " | ".join(flagged(w, "primitives", s) for w, _ in WHO) + " |")
print("\nThe same paths by VAMP's own check among the TRUE primitives (`Path.validate`: VAMP's "
      "spheres of the Panda, each motion at VAMP's planning resolution, discrete): invalid / paths\n")
print("| scene | " + " | ".join(name for _, name in WHO) + " |")
print("|---|" + "---|" * len(WHO))
for s in rows:
    cells = []
    for w, _ in WHO:
        t = judged.get(w, {})
        keys = [k for k in t if s == "all" or k[0] == s]
        cells.append(f"{sum(1 for k in keys if not t[k])}/{len(keys)}")
    print(f"| {s} | " + " | ".join(cells) + " |")
inv = {tag: sum(invalid_in_cloud(tag, s) for s in SCENES) for tag in ours}
print(f"\nWithin the cloud: VAMP's paths that our continuous check finds within a point's radius "
      f"(+ margin) of a point of VAMP's cloud: {flagged('vamp', 'cloud', 'all')}; "
      f"our paths that `plan`'s own validation flagged (any round): "
      + ", ".join(f"{t} {n}" for t, n in sorted(inv.items())))
reasons = {}
for (who, against), t in fidelity.items():
    for k, r in t.items():
        if r != "valid" and not r.startswith("no verdict"):
            reasons.setdefault((who, against), []).append(f"{k[0]} #{k[1]}: {r}")
for (who, against), rs in sorted(reasons.items()):
    print(f"\n{who} against {against}, first failures:")
    for r in rs[:5]:
        print(f"  {r}")
