#!/bin/bash
# Side by side: OMPL's planners (./driver) and ours (first_solution_work) on the same problems,
# written by `mit-star problems --write`, seeds 1..SEEDS, one run at a time, each stopping at its
# first exact solution or BUDGET seconds. Writes OUT/problems/*.toml, OUT/ompl.csv, OUT/ours.csv.
#
#   OUT=runs SEEDS=50 ./run.sh            then   python3 summary.py runs
#
# Environment (defaults reproduce issue 9's table): PROBLEMS (family:dim[:layout] ...),
# OMPL_PLANNERS, OUR_PLANNERS (a configuration, or `NAME:one-at-a-time` for checks one state at
# a time as OMPL makes them), SEEDS, BUDGET, OUT, ROOT (the mit-star checkout, built with
# `cargo build --release -p mit-star-benches -p mit-star --examples --bin mit-star`).
set -euo pipefail
cd "$(dirname "$0")"
ROOT=${ROOT:-$(cd ../../.. && pwd)}
OUT=${OUT:-runs}
SEEDS=${SEEDS:-50}
BUDGET=${BUDGET:-3}
PROBLEMS=${PROBLEMS:-"flanking-gap:4 flanking-gap:8 flanking-gap:16 dividing-walls:4 dividing-walls:8 dividing-walls:16 goal-enclosure:2 goal-enclosure:4 goal-enclosure:8 random-rectangles:4:1 random-rectangles:4:2 random-rectangles:4:3"}
OMPL_PLANNERS=${OMPL_PLANNERS:-EITstar}
OUR_PLANNERS=${OUR_PLANNERS:-"mit-star eit-star"}
DRIVER=${DRIVER:-./driver}
MIT_STAR=$ROOT/target/release/mit-star
WORK=$ROOT/target/release/examples/first_solution_work
mkdir -p "$OUT/problems"
header="problem,n,planner,seed,exact,callback,t_first_ms,calls_first,t_total_ms,calls_total,cost,setup_ms"
echo "$header" > "$OUT/ompl.csv"
echo "$header" > "$OUT/ours.csv"
for spec in $PROBLEMS; do
  IFS=: read -r family dim layout <<< "$spec"
  layout=${layout:-0}
  toml="$OUT/problems/$family-$dim-$layout.toml"
  "$MIT_STAR" problems --write "$family" --dim "$dim" --instance "$layout" > "$toml"
  for planner in $OMPL_PLANNERS; do
    for seed in $(seq 1 "$SEEDS"); do
      "$DRIVER" run "$toml" "$planner" "$seed" "$BUDGET" >> "$OUT/ompl.csv"
    done
  done
  for planner in $OUR_PLANNERS; do
    # first_solution_work takes `random-rectangles:K` for a layout and stops at 3 s;
    # `mit-star:one-at-a-time` turns the batched checks and the broad phase off.
    name=$family
    [ "$layout" != 0 ] && name="$family:$layout"
    IFS=: read -r configuration mode <<< "$planner"
    "$WORK" "$name" "$dim" "$configuration" "$SEEDS" $mode --csv >> "$OUT/ours.csv"
  done
  echo "$spec done" >&2
done
for spec in $PROBLEMS; do
  IFS=: read -r family dim layout <<< "$spec"
  "$DRIVER" iso "$OUT/problems/$family-$dim-${layout:-0}.toml"
done > "$OUT/iso.txt"
