#!/usr/bin/env bash
# RRT-Connect beside VAMP on an idle machine and while a build runs on the other CPU (issue 72,
# "speed that holds under load").
#
#   W=<VAMP work folder> BIN=<mit-star> MBM=<folder of <scene>_panda> [ROUNDS=3] [CPU=0]
#     [LOAD_CPU=1] [SCENES="…"] [CONDITIONS="idle busy crowded"]
#     [LOOP=target/release/examples/arm_profile] ./under_load.sh OUT
#
# Each round runs the shared harness's two sides (VAMP's `vamp_mbm`, our `bench` to the first
# solution, range 1, problems 1–100 of each scene), both pinned to CPU ${CPU:-0} in their own
# session at the highest priority, under each condition:
# - idle: nothing else runs;
# - busy: a loop compiles this workspace from scratch on the other CPU (`cargo build --release
#   -j1` into OUT/load-target-busy, pinned to CPU ${LOAD_CPU:-1} at normal priority), as the issue
#   asks: a developer's build beside the planner;
# - crowded: the same loop with `-j4` and no pinning, so that compilers also share the planner's
#   CPU (a load average about 3 on two CPUs, as on a machine running perception, control and
#   logging beside the planner).
# The conditions and the sides alternate from round to round so that drift on the machine hits
# all alike. A build loop is started before a round's first run and stopped after its last;
# each round records the load average and how busy the other CPU was (from /proc/stat).
#
# With LOOP (the `arm_profile` example, built in release), each round also times our planner in
# a loop like VAMP's harness (build, solve, next; nothing between two solves) on problems 1–100
# of the five scenes `arm_profile` knows, pinned like the others: it tells the planner's own
# sensitivity from the harness's (the audit and recording between two runs).
#
# Then `under_load_table.py OUT` prints, per scene and pooled, each side's median under each
# condition, how much each slows down under each load, and our time outside the solve
# (construction, audit, the bench process's wall time per run) apart. The build loops' target
# folders are removed at the end.
set -euo pipefail
OUT=${1:?usage: under_load.sh OUT}
: "${W:?set W to the VAMP work folder}" "${BIN:?set BIN to the mit-star binary}" "${MBM:?set MBM}"
ROUNDS=${ROUNDS:-3}
LOAD_CPU=${LOAD_CPU:-1}
SCENES=${SCENES:-"bookshelf_small bookshelf_tall bookshelf_thin box cage table_pick table_under_pick"}
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../../.." && pwd)
source "$HERE/common.sh"
BIN=$(realpath "$BIN")
[ -z "${LOOP:-}" ] || LOOP=$(realpath "$LOOP")
mkdir -p "$OUT"
OUT=$(realpath "$OUT")

CONDITIONS=${CONDITIONS:-"idle busy crowded"}
loader=""
start_load() {
  local cpus=$LOAD_CPU jobs=1
  if [ "$1" = crowded ]; then cpus=0-$(($(nproc) - 1)); jobs=4; fi
  # A fresh session so that the whole loop (cargo, rustc, the linker) is stopped as one group.
  setsid taskset -c "$cpus" bash -c '
    cd "$0"
    while :; do
      cargo build --release --locked -j"$2" -q --workspace --target-dir "$1" > /dev/null 2>&1 || true
      rm -rf "$1/release"
    done' "$ROOT" "$OUT/load-target-$1" "$jobs" &
  loader=$!
  sleep 20 # past cargo's start, into the compiling
}
stop_load() {
  [ -n "$loader" ] && kill -- -"$loader" 2> /dev/null || true
  wait "$loader" 2> /dev/null || true
  loader=""
}
# The build loops' target folders are scratch (hundreds of MB each): gone at the end.
trap 'stop_load; rm -rf "$OUT"/load-target-*' EXIT

# Busy share of CPU LOAD_CPU between two reads of /proc/stat.
cpu_ticks() { awk -v c="cpu$LOAD_CPU" '$1 == c { idle = $5 + $6; t = 0; for (i = 2; i <= NF; i++) t += $i; print t, idle }' /proc/stat; }

loop_round() {
  [ -n "${LOOP:-}" ] || return 0
  ARM_PROFILE_CSV=$1/loop_$2.csv ARM_PROFILE_NO_CHECKS=1 pinned "$LOOP" "$MBM" 100 rrt-connect 1 \
    > "$1/loop_$2.txt"
}
vamp_round() { pinned "$W/cpp/vamp_mbm" "$W/cpp/panda_mbm.txt" 1 > "$1/vamp_$2.csv"; }
ours_round() {
  mkdir -p "$1/ours_$2"
  for s in $SCENES; do
    local t0 t1
    t0=$(date +%s.%N)
    ours_scene "$BIN" "$1/ours_$2" "$s"
    t1=$(date +%s.%N)
    echo "$s,$t0,$t1" >> "$1/ours_$2/wall.csv"
  done
}

for i in $(seq 1 "$ROUNDS"); do
  read -r -a conditions <<< "$CONDITIONS"
  # Odd rounds in the given order, even rounds reversed.
  (( i % 2 == 0 )) && for ((a = 0, b = ${#conditions[@]} - 1; a < b; a++, b--)); do
    t=${conditions[a]}; conditions[a]=${conditions[b]}; conditions[b]=$t
  done
  for condition in "${conditions[@]}"; do
    dir=$OUT/$condition
    mkdir -p "$dir"
    [ "$condition" = idle ] || start_load "$condition"
    read -r t0 i0 < <(cpu_ticks)
    load=$(cut -d' ' -f1-3 /proc/loadavg)
    if (( i % 2 == 1 )); then vamp_round "$dir" "$i"; ours_round "$dir" "$i"; loop_round "$dir" "$i"
    else loop_round "$dir" "$i"; ours_round "$dir" "$i"; vamp_round "$dir" "$i"; fi
    read -r t1 i1 < <(cpu_ticks)
    [ "$condition" = idle ] || stop_load
    busy=$(awk -v a="$((t1 - t0))" -v b="$((i1 - i0))" 'BEGIN { x = (a > 0) ? 100 * (a - b) / a : 0; printf "%.0f", x }')
    echo "round $i $condition: load $load, CPU $LOAD_CPU busy $busy %" >> "$OUT/rounds.txt"
  done
done
CONDITIONS="$CONDITIONS" python3 "$HERE/under_load_table.py" "$OUT" $SCENES
