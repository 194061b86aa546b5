#!/usr/bin/env bash
# Issue 9, item 1: where the time goes. Profiles (perf, sampling at 2 kHz, self time by symbol)
# of MIT* and EIT* on dividing walls R^4, goal enclosure R^8 and random rectangles R^4 layout 1:
# runs stopped at the first solution, and whole anytime runs at the paper's budgets.
#   docs/scripts/profile.sh [RUNS]      (default 30 runs per profile; perf from Debian's linux-perf)
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:-30}
cargo build --release -p mit-star-benches
bin=target/release/mit-star
out=results/profiles
mkdir -p "$out"
profile() { # name planner problem dim budget extra...
  local name=$1 planner=$2 problem=$3 dim=$4 budget=$5
  shift 5
  rm -rf "$out/$name.results"
  perf record -F 2000 -o "$out/$name.data" -- "$bin" bench --planners "$planner" \
    --problem "$problem" --dim "$dim" --time "$budget" --runs "$runs" --threads 1 -q --no-plots \
    --output "$out/$name.results" "$@" > /dev/null 2> "$out/$name.perf.log"
  echo "== $name: $planner on $problem R^$dim ($*), self time by symbol"
  perf report -i "$out/$name.data" --no-children --sort symbol --percent-limit 2 --stdio 2> /dev/null \
    | grep -E '^ +[0-9]' | sed 's/  *-  *-  *$//' | head -12
  perf report -i "$out/$name.data" --no-children --sort symbol --percent-limit 0 --stdio 2> /dev/null \
    | python3 docs/scripts/profile-categories.py "$name"
}
for planner in mit-star eit-star; do
  profile "dw4-first-$planner" "$planner" dividing-walls 4 1 --first-solution
  profile "ge8-first-$planner" "$planner" goal-enclosure 8 4 --first-solution
  profile "rr4-first-$planner" "$planner" random-rectangles 4 2 --first-solution --instances 1-1
  profile "dw4-anytime-$planner" "$planner" dividing-walls 4 0.3
  profile "ge8-anytime-$planner" "$planner" goal-enclosure 8 2
  profile "rr4-anytime-$planner" "$planner" random-rectangles 4 0.8 --instances 1-1
done
