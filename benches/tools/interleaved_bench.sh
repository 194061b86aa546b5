#!/usr/bin/env bash
# Two `mit-star` builds (or one build with two settings) timed with `mit-star bench` one scene at
# a time, alternated round by round, each pinned to one CPU at the highest priority, every
# problem with the same seed on both sides (round r uses --seed 7·r), so that both sides make the
# same decisions and differ only in speed. Then `paired_bench.py` compares them run by run:
# construction, time to the first solution with construction, and the solve alone.
#
# Usage:
#   ROUNDS=16 benches/tools/interleaved_bench.sh OUT "OLD_BINARY" "target/release/mit-star" \
#       [extra bench arguments, for both sides]
#   python3 benches/tools/paired_bench.py OUT
#
# Environment: ROUNDS (default 4), SCENES (the seven MotionBenchMaker scenes), MBM (the folder
# of <scene>_panda, default target), PLANNER (default rrt-connect), RANGE (default
# "--set range=1.0"; empty for planners without a range), CPU (default 0). Writes
# OUT/<a|b>.<round>.<scene>/ (a bench's folder each).
set -euo pipefail
out=${1:?usage: interleaved_bench.sh OUT A_BINARY B_BINARY [bench arguments]}
a=${2:?the first mit-star binary}
b=${3:?the second mit-star binary}
shift 3
rounds=${ROUNDS:-4}
scenes=${SCENES:-bookshelf_small bookshelf_tall bookshelf_thin box cage table_pick table_under_pick}
mbm=${MBM:-target}
planner=${PLANNER:-rrt-connect}
range=${RANGE---set range=1.0}
cpu=${CPU:-0}
mkdir -p "$out"
pinned() {
  setsid -w bash -c 'echo -20 > /proc/self/autogroup; exec nice -n -20 taskset -c "$0" "$@"' "$cpu" "$@"
}
for scene in ${scenes//,/ }; do
  for round in $(seq 1 "$rounds"); do
    if (( round % 2 )); then order="a b"; else order="b a"; fi
    for side in $order; do
      if [[ $side == a ]]; then binary=$a; else binary=$b; fi
      # shellcheck disable=SC2086 # RANGE is split into words on purpose
      pinned "$binary" bench --robot panda --planners "$planner" \
        --problem "mbm:$mbm/${scene}_panda" --instances 1-100 --time 1 --runs 1 --threads 1 \
        --first-solution $range --no-plots -q --seed $((round * 7)) "$@" \
        --output "$out/$side.$round.$scene" > /dev/null
    done
  done
done
