#!/usr/bin/env bash
# Planning among point clouds, VAMP and mit-star side by side on the Panda MotionBenchMaker
# problems (issue 69, item 6).
#
#   W=<VAMP work folder, made by build_vamp.sh> BIN=<mit-star, release> MBM=<folder holding the
#   unpacked <scene>_panda folders> [ROUNDS=2] [CPU=0] [SCENES="box cage …"] [RAW=1]
#   ./side_by_side_clouds.sh OUT
#
# With LOOP=<cloud_loop example binary> (examples/cloud_loop.rs), our runs of one planner on
# one variant are made in one process, as VAMP's loop makes them; without it, one `plan` process
# a problem (cold caches and first-touched memory on every solve).
#
# Each round goes scene by scene: for each scene VAMP's runs and ours back to back (VAMP first
# in odd rounds, ours first in even ones), so that a slow spell of a shared machine falls on
# both sides of a scene rather than on one side's block of the round. Every side is pinned to
# one CPU at the highest priority (`pinned`, common.sh), one problem at a time:
# - VAMP (vamp_clouds.py, VAMP's Python module): evaluate_mbm.py --pointcloud True's protocol —
#   10 000 points on each primitive, filter_pointcloud (0.02 m, culled at 1.19 m), the CAPT of
#   points of radius 2.5 mm, RRT-Connect. It writes each problem's filtered cloud to
#   OUT/clouds (round 1; seeded, so the same every round) and, with RAW=1 (the default), the
#   cloud before filtering to OUT/raw.
# - mit-star, `plan --json --no-picture`, per problem:
#   same/<planner>  among VAMP's filtered points (`--cloud OUT/clouds/… --drop-primitives`):
#                   RRT-Connect (range 1, as VAMP's), AORRTC and MIT* to the first solution;
#   own/rrt-connect our own sampling of the same protocol (`--scene-as-cloud 10000
#                   --crop-reach --min-distance 0.02`): our filters and tree on our points;
#   raw/rrt-connect VAMP's points before filtering through our filters (`--cloud OUT/raw/…
#                   --crop-reach --min-distance 0.02`): both filters on the same input;
#   prim/rrt-connect among the scene's primitives, no cloud: what the clouds cost us.
# and, for the same reference on VAMP's side, the shared harness `vamp_mbm` among the
# primitives (OUT/vamp_prim_K.csv).
# Then, once and untimed, the fidelity check: every returned path (VAMP's and ours) through
# `mit-star check-path` on the problem WITH its primitives and no cloud (continuous, f64), and
# VAMP's paths also within VAMP's cloud (`--cloud … --drop-primitives`); and every path by
# VAMP's own check among the primitives (vamp_judge.py: its spheres, its resolution). Finally
# summarize_clouds.py prints the tables.
set -euo pipefail
OUT=${1:?usage: side_by_side_clouds.sh OUT}
: "${W:?set W to the VAMP work folder}" "${BIN:?set BIN to the mit-star binary}" "${MBM:?set MBM}"
ROUNDS=${ROUNDS:-2}; RAW=${RAW:-1}
SCENES=${SCENES:-"bookshelf_small bookshelf_tall bookshelf_thin box cage table_pick table_under_pick"}
HERE=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=common.sh
. "$HERE/common.sh"
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
BIN=$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN")
export BIN MBM OUT

vamp_scene() { # ROUND SCENE: VAMP's runs of one scene, added to OUT/vamp_ROUND
  local keep=()
  # The clouds are seeded (the same every round): round 1 keeps them, for our side.
  [ "$1" = 1 ] && keep=(--clouds "$OUT/clouds")
  [ "$1" = 1 ] && [ "$RAW" = 1 ] && keep+=(--raw "$OUT/raw")
  pinned "$W/venv/bin/python" "$HERE/vamp_clouds.py" "$W/src/resources/panda/problems.pkl" \
    "$OUT/vamp_$1" "${keep[@]}" --scenes "$2" --append >> "$OUT/vamp_$1.log" 2>&1
}

# One of our runs: VARIANT PLANNER SCENE INDEX [ARGUMENT…]; JSON on stdout, cloud steps on stderr.
ours_one() {
  local variant=$1 planner=$2 scene=$3 index=$4
  shift 4
  local dir="$OUT/ours_$ROUND/$variant/$planner"
  mkdir -p "$dir"
  local extra=()
  [ "$planner" = rrt-connect ] && extra=(--set range=1.0)
  [ "$planner" = rrt-connect ] || extra=(--first-solution)
  "$BIN" plan --planner "$planner" --problem "mbm:$MBM/${scene}_panda" --instance "$((10#$index))" \
    --time 1 --seed 0 --no-picture --json "${extra[@]}" "$@" \
    > "$dir/${scene}_$index.json" 2> "$dir/${scene}_$index.err" || true
}
export -f ours_one

# The runs of one variant and planner, one line each: NAME and `plan`'s problem options.
runs_of() { # VARIANT
  local n
  for scene in $SCENES; do
    for f in "$OUT/clouds/${scene}"_*.npy; do
      n=${f##*_}; n=${n%.npy}
      local problem="--problem mbm:$MBM/${scene}_panda --instance $((10#$n))"
      case $1 in
        same) echo "${scene}_$n $problem --cloud $f --drop-primitives" ;;
        prim) echo "${scene}_$n $problem" ;;
        own) echo "${scene}_$n $problem --scene-as-cloud 10000 --crop-reach --min-distance 0.02" ;;
        raw) [ -f "$OUT/raw/${scene}_$n.npy" ] && echo "${scene}_$n $problem --cloud $OUT/raw/${scene}_$n.npy --drop-primitives --crop-reach --min-distance 0.02" ;;
      esac
    done
  done
}
export -f runs_of

ours_round() { # ROUND, with SCENES: every problem VAMP had as valid, in VAMP's order of scenes
  local v p
  for vp in same/rrt-connect same/aorrtc same/mit-star prim/rrt-connect own/rrt-connect raw/rrt-connect; do
    v=${vp%/*}; p=${vp#*/}
    [ "$v" = raw ] && [ ! -d "$OUT/raw" ] && continue
    if [ -n "${LOOP:-}" ]; then
      # One process for all the problems, as VAMP's loop (examples/cloud_loop.rs).
      local set=()
      [ "$p" = rrt-connect ] && set=(--set range=1.0)
      runs_of "$v" | grep . | "$LOOP" "$p" "$OUT/ours_$ROUND/$v/$p" "${set[@]}"
    else
      runs_of "$v" | grep . | while read -r name options; do
        # shellcheck disable=SC2086
        ours_one "$v" "$p" "${name%_*}" "${name##*_}" ${options#*--instance * }
      done
    fi
  done
}
export -f ours_round
export SCENES LOOP

ALL_SCENES=$SCENES
for i in $(seq 1 "$ROUNDS"); do
  echo "round $i, load $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/load.txt" >&2
  rm -f "$OUT/vamp_$i/vamp.csv" "$OUT/vamp_$i.log"
  for scene in $ALL_SCENES; do
    # Round 1 needs VAMP's clouds before our runs among them, so VAMP goes first there.
    if [ $((i % 2)) = 1 ]; then
      vamp_scene "$i" "$scene"
      SCENES=$scene ROUND=$i pinned bash -c ours_round
    else
      SCENES=$scene ROUND=$i pinned bash -c ours_round
      vamp_scene "$i" "$scene"
    fi
  done
  # VAMP among the primitives (the shared vamp_mbm harness), a reference for prim/rrt-connect.
  pinned "$W/cpp/vamp_mbm" "$W/cpp/panda_mbm.txt" 1 > "$OUT/vamp_prim_$i.csv"
  echo "round $i done, load $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/load.txt" >&2
done
SCENES=$ALL_SCENES

# Fidelity, untimed: every path against the scene's true primitives (no cloud).
check() { # PATHFILE SCENE INDEX OUTFILE [ARGUMENT…]
  local path=$1 scene=$2 index=$3 out=$4
  shift 4
  "$BIN" check-path --problem "mbm:$MBM/${scene}_panda" --instance "$((10#$index))" \
    --path "$path" --tolerance 1e-4 "$@" > "$out" 2>&1
  echo "exit $?" >> "$out"
}
mkdir -p "$OUT/fidelity"
for f in "$OUT"/vamp_1/paths/*.txt; do
  name=$(basename "$f" .txt); scene=${name%_*}; n=${name##*_}
  check "$f" "$scene" "$n" "$OUT/fidelity/vamp.primitives.$name.txt" || true
  check "$f" "$scene" "$n" "$OUT/fidelity/vamp.cloud.$name.txt" \
    --cloud "$OUT/clouds/$name.npy" --drop-primitives || true
done
for d in "$OUT"/ours_1/*/*; do
  tag=$(basename "$(dirname "$d")").$(basename "$d")
  for f in "$d"/*.json; do
    name=$(basename "$f" .json); scene=${name%_*}; n=${name##*_}
    grep -q '"status":"solved"\|"status":"invalid-path"' "$f" || continue
    check "$f" "$scene" "$n" "$OUT/fidelity/$tag.primitives.$name.txt" || true
  done
done
# The same paths by VAMP's own check (its spheres, discrete at its resolution), for comparison.
mkdir -p "$OUT/judge"
"$W/venv/bin/python" "$HERE/vamp_judge.py" "$W/src/resources/panda/problems.pkl" \
  "$OUT/judge/vamp.csv" "$OUT"/vamp_1/paths/*.txt
for d in "$OUT"/ours_1/*/*; do
  "$W/venv/bin/python" "$HERE/vamp_judge.py" "$W/src/resources/panda/problems.pkl" \
    "$OUT/judge/$(basename "$(dirname "$d")").$(basename "$d").csv" "$d"/*.json
done
python3 "$HERE/summarize_clouds.py" "$OUT" $SCENES | tee "$OUT/table.md"
