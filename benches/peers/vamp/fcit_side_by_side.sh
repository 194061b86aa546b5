#!/usr/bin/env bash
# FCIT* beside VAMP's FCIT* (issue 72): VAMP's FCIT* over time (vamp_fcit.cc, built here with
# VAMP's Release flags) and our `fcit-star` (the `anytime_arm` example) on problems 1–N of the
# seven Panda MotionBenchMaker scenes, one run a problem for BUDGET seconds, rounds alternating
# which side goes first, each side `pinned`; then fcit_table.py's table of all rounds.
#   W=<VAMP work folder> MBM=<folder of <scene>_panda> ANYTIME=<anytime_arm binary> \
#     [ROUNDS=2] [N=20] [BUDGET=1.0] [CPU=0] ./fcit_side_by_side.sh OUT [KEY=VALUE …]
# The KEY=VALUEs go to our side (anytime_arm's parameters, e.g. batch_size=1000). OUT gets
# vamp_K.csv and ours_K.csv (anytime_arm's CSV shape), vamp_runs_K.csv (every VAMP run),
# ours_K.md (anytime_arm's own table), load.txt and table.md.
set -euo pipefail
OUT=${1:?usage: fcit_side_by_side.sh OUT [KEY=VALUE …]}
shift
: "${W:?set W}" "${MBM:?set MBM}" "${ANYTIME:?set ANYTIME to the anytime_arm binary}"
ROUNDS=${ROUNDS:-2}
N=${N:-20}
BUDGET=${BUDGET:-1.0}
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
mkdir -p "$OUT"
[ -x "$W/ours/vamp_fcit" ] || { mkdir -p "$W/ours"; vamp_compile "$W/src/src/impl" "$W/ours/vamp_fcit" "$HERE/vamp_fcit.cc"; }
SCENES=bookshelf_small,bookshelf_tall,bookshelf_thin,box,cage,table_pick,table_under_pick
vamp_side() {
  pinned "$W/ours/vamp_fcit" "$W/cpp/panda_mbm.txt" "$N" "$BUDGET" "$OUT/vamp_runs_$1.csv" > "$OUT/vamp_$1.csv"
}
our_side() {
  pinned "$ANYTIME" "$MBM" "$N" fcit-star "$BUDGET" scenes=$SCENES csv="$OUT/ours_$1.csv" "${@:2}" \
    > "$OUT/ours_$1.md"
}
for i in $(seq 1 "$ROUNDS"); do
  echo "round $i start, load $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/load.txt" >&2
  if (( i % 2 )); then vamp_side "$i"; our_side "$i" "$@"; else our_side "$i" "$@"; vamp_side "$i"; fi
  echo "round $i end, load $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/load.txt" >&2
done
python3 "$HERE/fcit_table.py" "$OUT" | tee "$OUT/table.md"
