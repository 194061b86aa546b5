#!/usr/bin/env bash
# The shared side-by-side comparison with both sides drawing at random: in round i, VAMP's
# RRT-Connect with its XORShift generator (the `vamp_mbm_random` that random_draws.sh builds)
# keyed K_i + 100000 · (index − 1) on problem `index` (VAMP_PER_PROBLEM=1), and ours with
# `--seed K_i`, which seeds the k-th problem K_i + 100000 · k: every problem draws its own
# random sequence on both sides, and no fixed sequence's luck is shared by a scene. Otherwise the
# shared script's protocol: problems 1–100 of each scene, range 1, first solution, one thread,
# both sides pinned to one CPU at top priority, alternated. Then the shared summary, with our
# time to the first solution taken without construction (summarize_solve.py).
#   W=<VAMP work folder> RD=<random_draws.sh's OUT> BIN=<mit-star> MBM=<folder of <scene>_panda>
#   [KEYS="2 5 7"] [CPU=0] [SCENES="…"] ./side_by_side_random.sh OUT
set -euo pipefail
OUT=${1:?usage: side_by_side_random.sh OUT}
: "${W:?set W}" "${RD:?set RD}" "${BIN:?set BIN}" "${MBM:?set MBM}"
KEYS=${KEYS:-2 5 7}
SCENES=${SCENES:-"bookshelf_small bookshelf_tall box cage table_pick"}
HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/common.sh"
mkdir -p "$OUT"
[ -x "$RD/vamp_mbm_random" ] || { echo "no $RD/vamp_mbm_random: run random_draws.sh first" >&2; exit 2; }
i=0
for key in $KEYS; do
  i=$((i + 1))
  echo "round $i (key $key), load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
  VAMP_KEY=$key VAMP_PER_PROBLEM=1 pinned "$RD/vamp_mbm_random" "$W/cpp/panda_mbm.txt" 1 > "$OUT/vamp_$i.csv"
  mkdir -p "$OUT/ours_$i"
  for s in $SCENES; do
    ours_scene "$BIN" "$OUT/ours_$i" "$s" --seed "$key"
  done
done
python3 "$HERE/summarize_solve.py" "$OUT" $SCENES
