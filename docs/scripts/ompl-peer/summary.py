"""Medians of the peer runs (docs/scripts/ompl-peer/run.sh): per problem and planner, success,
median time to the first solution, median validity calls (OMPL) or grid points (ours) to it, and
each of our planners' speed-up over every OMPL planner (OMPL's median / ours).

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

problems = list(dict.fromkeys((r["problem"], r["n"]) for r in rows))
planners = {s: list(dict.fromkeys(r["planner"] for r in rows if r["side"] == s)) for s in ["ompl", "ours"]}


def stats(problem, n, side, planner):
    r = [x for x in rows if (x["problem"], x["n"], x["side"], x["planner"]) == (problem, n, side, planner)]
    ok = [x for x in r if x["exact"] == "1"]
    if not ok:
        return len(r), 0, float("nan"), float("nan")
    return len(r), len(ok), st.median(float(x["t_first_ms"]) for x in ok), st.median(int(x["calls_first"]) for x in ok)


head = ["problem", "planner", "solved", "median t_first (ms)", "median checks to it"]
ratios = [f"{o} ÷ {p}" for p in planners["ours"] for o in planners["ompl"]]
print("| " + " | ".join(head + ratios) + " |")
print("|" + "---|" * (len(head) + len(ratios)))
for problem, n in problems:
    median = {}
    for side in ["ompl", "ours"]:
        for p in planners[side]:
            runs, solved, t, calls = stats(problem, n, side, p)
            median[p] = t
            label = f"OMPL {p}" if side == "ompl" else p
            print(f"| {problem} R^{n} | {label} | {solved}/{runs} | {t:.3f} | {calls:,.0f} |" + " |" * len(ratios))
    cells = [f"{median[o] / median[p]:.1f}×" for p in planners["ours"] for o in planners["ompl"]]
    print(f"| {problem} R^{n} | speed-up | | | | " + " | ".join(cells) + " |")
