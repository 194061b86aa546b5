#!/usr/bin/env bash
# Two `arm_profile` command lines (two builds, or one build with two settings) timed one scene
# at a time, alternated, pinned to one CPU at the highest priority, so that both sides of every
# comparison run within seconds of each other. Then `paired_runs.py` compares them run by run.
#
# Usage:
#   ROUNDS=6 SCENES=box,cage benches/tools/interleaved_ab.sh OUT \
#       "OLD_BINARY target 20 mit-star 3" "target/release/examples/arm_profile target 20 mit-star 3"
#   python3 benches/tools/paired_runs.py OUT
#
# Writes OUT/a_<round>.csv and OUT/b_<round>.csv (`ARM_PROFILE_CSV`, every scene of a round in
# one file). Rounds alternate which side runs first; ROUNDS defaults to 6, SCENES to the seven
# MotionBenchMaker scenes, CPU to 0. Why: this machine's host changes speed within seconds, so
# two builds each timed over all scenes in turn (15 s a run on the Fetch) read per-scene ratios
# of 0.81–1.27 for identical work; the same runs interleaved per scene read 0.97–1.00.
set -euo pipefail
out=${1:?usage: interleaved_ab.sh OUT "A command" "B command"}
a=${2:?the first arm_profile command line}
b=${3:?the second arm_profile command line}
rounds=${ROUNDS:-6}
scenes=${SCENES:-bookshelf_small,bookshelf_tall,bookshelf_thin,box,cage,table_pick,table_under_pick}
cpu=${CPU:-0}
mkdir -p "$out"
pinned() {
  setsid -w bash -c 'echo -20 > /proc/self/autogroup; exec nice -n -20 taskset -c "$0" "$@"' "$cpu" "$@"
}
run() { # side round scene command...
  local side=$1 round=$2 scene=$3
  shift 3
  # shellcheck disable=SC2086 # the command line is split into words on purpose
  ARM_PROFILE_SCENES=$scene ARM_PROFILE_NO_CHECKS=1 ARM_PROFILE_CSV="$out/$side.$round.$scene.csv" \
    pinned $1 > /dev/null
}
for scene in ${scenes//,/ }; do
  for round in $(seq 1 "$rounds"); do
    if (( round % 2 )); then order="a b"; else order="b a"; fi
    for side in $order; do
      if [[ $side == a ]]; then run a "$round" "$scene" "$a"; else run b "$round" "$scene" "$b"; fi
    done
  done
done
for side in a b; do
  for round in $(seq 1 "$rounds"); do
    awk 'FNR > 1 || NR == 1' "$out/$side.$round".*.csv > "$out/${side}_$round.csv"
    rm "$out/$side.$round".*.csv
  done
done
echo "wrote $out/{a,b}_1..$rounds.csv; compare: python3 benches/tools/paired_runs.py $out"
