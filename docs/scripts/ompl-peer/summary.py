"""Medians of the peer runs (docs/scripts/ompl-peer/run.sh): per problem and planner, success,
median time to the first solution, median validity calls (OMPL) or grid points decided (ours)
up to it, and the median over runs of that time per check (planner included); for each of our
planners, OMPL's median for the same planner (EIT* for MIT* and its ablations) over ours.

    python3 summary.py OUT
"""
import csv
import statistics as st
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "runs"
rows = []
for side in ["ompl", "ours"]:
    for r in csv.DictReader(open(f"{out}/{side}.csv")):
        r["side"] = side
        rows.append(r)

# OMPL's class for each of our labels (a label may carry " one at a time").
COUNTERPART = {"EIT*": "EITstar", "AIT*": "AITstar", "BIT*": "BITstar",
               "RRT-Connect": "RRTConnect", "Informed RRT*": "InformedRRTstar"}


def counterpart(label):
    base = label.replace(" one at a time", "")
    return COUNTERPART.get(base, "EITstar" if base.startswith("MIT*") else None)


def stats(problem, n, side, planner):
    r = [x for x in rows if (x["problem"], x["n"], x["side"], x["planner"]) == (problem, n, side, planner)]
    ok = [x for x in r if x["exact"] == "1"]
    t = st.median(float(x["t_first_ms"]) for x in ok) if ok else float("inf")
    calls = st.median(int(x["calls_first"]) for x in ok) if ok else float("nan")
    per = st.median(1e6 * float(x["t_first_ms"]) / max(int(x["calls_first"]), 1) for x in ok) if ok else float("nan")
    return len(r), len(ok), t, calls, per


problems = list(dict.fromkeys((r["problem"], r["n"]) for r in rows))
print("| problem | planner | solved | median t_first (ms) | median checks to it | median ns per check | OMPL ÷ ours |")
print("|---|---|---|---|---|---|---|")
for problem, n in problems:
    medians = {}
    for side in ["ompl", "ours"]:
        for p in dict.fromkeys(r["planner"] for r in rows if r["side"] == side):
            runs, solved, t, calls, per = stats(problem, n, side, p)
            if runs == 0:
                continue
            ratio = ""
            if side == "ompl":
                medians[p] = t
                label = f"OMPL {p}"
            else:
                label = p
                other = medians.get(counterpart(p))
                if other is not None:
                    ratio = f"{other / t:.2f}×" if t != float("inf") else "—"
            print(f"| {problem} R^{n} | {label} | {solved}/{runs} | {t:.3f} | {calls:,.0f} | {per:.1f} | {ratio} |")
