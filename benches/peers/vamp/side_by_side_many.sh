#!/usr/bin/env bash
# The shared side-by-side comparison with several of ours in each round: builds or settings
# compared against one VAMP run per round, all alternated, so that drift on the shared machine
# hits every one alike. Each setting is NAME and "BINARY|EXTRA ARGUMENTS" (the arguments added to
# the shared script's `mit-star bench …` line, e.g. `--set rrt_halton=true`). Then, per setting,
# the shared summary with our time to the first solution taken without construction
# (summarize_solve.py).
#   W=<VAMP work folder> MBM=<folder of <scene>_panda> [ROUNDS=3] [CPU=0] [SCENES="…"] \
#     ./side_by_side_many.sh OUT old "old/mit-star|" new "target/release/mit-star|" \
#     seq "target/release/mit-star|--set rrt_halton=true --set rrt_halton_shift=false"
set -euo pipefail
OUT=${1:?usage: side_by_side_many.sh OUT NAME "BINARY|ARGS" [NAME "BINARY|ARGS"]…}
shift
: "${W:?set W}" "${MBM:?set MBM}"
(( $# >= 2 && $# % 2 == 0 )) || { echo "settings come as NAME \"BINARY|ARGS\" pairs" >&2; exit 2; }
ROUNDS=${ROUNDS:-3}
SCENES=${SCENES:-"bookshelf_small bookshelf_tall box cage table_pick"}
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
settings=("$@")
mkdir -p "$OUT"
for i in $(seq 1 "$ROUNDS"); do
  echo "round $i, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
  pinned "$W/cpp/vamp_mbm" "$W/cpp/panda_mbm.txt" 1 > "$OUT/vamp_$i.csv"
  for ((k = 0; k < ${#settings[@]}; k += 2)); do
    name=${settings[k]}; spec=${settings[k + 1]}
    binary=${spec%%|*}; read -r -a extra <<< "${spec#*|}"
    mkdir -p "$OUT/$name/ours_$i"
    cp "$OUT/vamp_$i.csv" "$OUT/$name/vamp_$i.csv"
    for s in $SCENES; do
      ours_scene "$binary" "$OUT/$name/ours_$i" "$s" "${extra[@]}"
    done
  done
done
for ((k = 0; k < ${#settings[@]}; k += 2)); do
  echo "== ${settings[k]}"
  python3 "$HERE/summarize_solve.py" "$OUT/${settings[k]}" $SCENES
done
