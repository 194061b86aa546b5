#!/bin/bash
# Submits a campaign to Slurm: a job array of N shards of EXPERIMENT (one task each), then a
# merge job that starts when every shard succeeded. Results: CAMPAIGN_FOLDER/merged.
#
#   docs/slurm/submit-campaign.sh EXPERIMENT N CAMPAIGN_FOLDER [MIT_STAR_BINARY] [-- SBATCH_OPTIONS...]
#
# EXPERIMENT is a shipped experiment's name (paper-table, paper-planners, ...) or a TOML file
# readable from the compute nodes; CAMPAIGN_FOLDER must be on a file system they share.
# Options after `--` go to both sbatch calls (e.g. --partition=short --account=lab).
# Prints the two job ids.
set -euo pipefail
if [ $# -lt 3 ]; then
    sed -n '2,12p' "$0" >&2
    exit 2
fi
experiment=$1
count=$2
campaign=$3
mit_star=${4:-$(command -v mit-star || echo mit-star)}
shift $(( $# >= 4 ? 4 : 3 ))
[ "${1:-}" = "--" ] && shift
here=$(cd "$(dirname "$0")" && pwd)
# A file must be found from the campaign folder, where the jobs run.
[ -f "$experiment" ] && experiment=$(realpath "$experiment")
mkdir -p "$campaign"
campaign=$(cd "$campaign" && pwd)
array=$(sbatch --parsable --array="1-$count" --chdir="$campaign" "$@" \
    "$here/shard.sbatch" "$experiment" "$count" "$campaign" "$mit_star")
array=${array%%;*}
merge=$(sbatch --parsable --dependency="afterok:$array" --chdir="$campaign" "$@" \
    "$here/merge.sbatch" "$count" "$campaign" "$mit_star")
echo "shards: job array $array (tasks 1-$count); merge: job ${merge%%;*} after all of them"
