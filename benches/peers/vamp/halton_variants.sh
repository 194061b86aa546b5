#!/usr/bin/env bash
# VAMP's RRT-Connect with other Halton sequences than the one its harness restarts before every
# problem: is its lead on some scenes (cage) a property of low-discrepancy sampling or of that
# one sequence? Builds the shared harness again with two switches read at each problem's
# start: VAMP_HALTON_SKIP=N draws and drops the sequence's first N points, VAMP_HALTON_ROTATE=R
# rotates its bases R places (VAMP's own Halton::rotate_bases: bases 3, 5, …, 19 give the
# joints 5, 7, …, 19, 3 after one). Then, per scene, the median iterations and planning time
# of each variant (VAMP's timer; iterations do not depend on the machine).
#   W=<VAMP work folder> [VARIANTS="0:0 100:0 1000:0 0:1 0:2 0:3"] ./halton_variants.sh OUT
set -euo pipefail
OUT=${1:?usage: halton_variants.sh OUT}
: "${W:?set W to the VAMP work folder}"
VARIANTS=${VARIANTS:-"0:0 100:0 1000:0 0:1 0:2 0:3"}
source "$(cd "$(dirname "$0")" && pwd)/common.sh"
mkdir -p "$OUT"
# The one change: after each reset, rotate the bases and drop points as the switches say.
AFTER_RESET='rng->reset(); for (long k = 0; k < std::atol(std::getenv("VAMP_HALTON_ROTATE")); ++k) rng->rotate_bases(); for (long k = 0; k < std::atol(std::getenv("VAMP_HALTON_SKIP")); ++k) rng->next();'
sed -e "s|rng->reset();|$AFTER_RESET|" -e 's|#include <vamp/random/halton.hh>|#include <vamp/random/halton.hh>\n#include <cstdlib>|' \
  "$W/cpp/vamp_mbm.cc" > "$OUT/vamp_mbm_halton.cc"
grep -q VAMP_HALTON_SKIP "$OUT/vamp_mbm_halton.cc" || { echo "no reset to patch in $W/cpp/vamp_mbm.cc" >&2; exit 1; }
vamp_compile "$W/src/src/impl" "$OUT/vamp_mbm_halton" "$OUT/vamp_mbm_halton.cc"
for v in $VARIANTS; do
  VAMP_HALTON_SKIP=${v%%:*} VAMP_HALTON_ROTATE=${v##*:} pinned "$OUT/vamp_mbm_halton" \
    "$W/cpp/panda_mbm.txt" 1 > "$OUT/rrtc.$v.csv"
done
python3 - "$OUT" $VARIANTS <<'PY'
import csv, statistics as st, sys, collections
out, variants = sys.argv[1], sys.argv[2:]
table = {}
for v in variants:
    rows = collections.defaultdict(list)
    for r in csv.DictReader(open(f"{out}/rrtc.{v}.csv")):
        rows[r["scene"]].append(r)
    table[v] = rows
scenes = sorted(table[variants[0]])
print("VAMP's RRT-Connect, medians per scene: iterations / planning µs; variant = points skipped:bases rotated")
print("| scene | " + " | ".join(variants) + " |")
print("|---|" + "---|" * len(variants))
for s in scenes:
    cells = []
    for v in variants:
        rs = table[v][s]
        solved = sum(r["solved"] == "1" for r in rs)
        it = st.median(float(r["iterations"]) for r in rs)
        us = st.median(float(r["plan_us"]) for r in rs)
        cells.append(f"{it:.0f} / {us:.0f}" + ("" if solved == len(rs) else f" ({solved}/{len(rs)})"))
    print(f"| {s} | " + " | ".join(cells) + " |")
PY
