#!/usr/bin/env bash
# The sweeps of docs/guide/src/reference/ablation-study.md: the ablation-study experiment (first solutions, 200 runs,
# GE R^2/R^4, DW R^4/R^8, FG R^4) with one parameter changed at a time, for the
# configurations it affects. Results go to results/ablation-sweeps/<sweep>; summarise with
#   python3 docs/scripts/ablation-summary.py results/ablation-sweeps/*
# Runs one at a time (--threads 1). Times drift between sweeps on a shared machine by 10 % or
# more, so every sweep runs EIT* as its own reference; compare times within a sweep and work
# (grid points) across sweeps. About 40 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -p mit-star-benches
bin=target/release/mit-star
out=results/ablation-sweeps
run() { # name planners [--set k=v ...]
  local name=$1 planners=$2
  shift 2
  echo "== $name ($planners) $*"
  rm -rf "${out:?}/$name"
  "$bin" bench --experiment ablation-study --only "$planners" --threads 1 -q --no-plots \
    --output "$out/$name" "$@" > /dev/null
}
all=mit-star,eit-star,mit-star-as,mit-star-eis,mit-star-sc,mit-star-sr
# The defaults (a new estimated informed set bounds the next batch, as the paper's Alg. 1).
run base $all
# The first study ran with the MIT* authors' immediate batch in a new estimated informed set
# (then the default); every sweep below but the last varies one parameter from there.
old="--set eis_immediate_batch=true"
run base-immediate-batch $all $old
# The estimated informed set: when it asks for a batch, how e_γ is computed, when it expands.
run eis-no-immediate-batch mit-star,eit-star,mit-star-eis --set eis_immediate_batch=false
run eis-authors-form mit-star,eit-star,mit-star-eis $old --set eis_expansion_form=authors
run eis-per-invalid-edge mit-star,eit-star,mit-star-eis $old --set eis_expansion_rule=per-invalid-edge
# The adaptive sampler: the Gaussian standard deviation δ and the bridge-check budget.
for d in 0.02 0.05 0.2; do
  run "delta-$d" mit-star,eit-star,mit-star-as $old --set gaussian_std_fraction=$d
done
for b in 1 16; do
  run "bridge-$b" mit-star,eit-star,mit-star-as $old --set bridge_checks=$b
done
# Smaller batches: first solutions after several batches, where sampling parts can act.
for q in 25 50; do
  run "batch-$q" mit-star,eit-star,mit-star-as,mit-star-eis,mit-star-sc $old --set batch_size=$q
done
# Smaller batches with the defaults.
run batch-25-paper-eis mit-star,eit-star,mit-star-as,mit-star-eis,mit-star-sc --set batch_size=25
# The batch size under the estimated informed set alone: batches of 25 until an estimate
# exists, then 100 in it.
run batch-25-eis-100 mit-star,eit-star,mit-star-eis --set batch_size=25 --set eis_batch_size=100
