#!/bin/bash
# Runs 30 seeded runs per problem x planner, one process per run, sequentially; then the isolated timing.
set -e
cd "$(dirname "$0")"
echo "problem,planner,seed,exact,callback,t_first_ms,calls_first,t_total_ms,calls_total,cost,setup_ms" > runs.csv
for prob in DW GE; do
  for pl in BITstar RRTConnect; do
    for seed in $(seq 1 30); do
      nice -n 10 ./driver run $prob $pl $seed >> runs.csv
    done
  done
done
for i in 1 2 3; do nice -n 10 ./driver iso; done > iso.txt
