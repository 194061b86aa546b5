#!/bin/bash
# Tries a campaign on a real, single-node Slurm cluster on this machine, end to end: sets up
# munge, slurmctld and slurmd (Debian's slurm-wlm packages), submits a small experiment as a
# job array of 3 shards plus a dependent merge job (submit-campaign.sh), waits for them, runs
# the same experiment whole without Slurm, and checks that the merged folder holds exactly the
# whole run's runs: same (problem, planner, run), seeds, statuses and first-solution costs.
#
#   sudo docs/slurm/try-on-one-node.sh [MIT_STAR_BINARY]      (default: target/release/mit-star)
#
# Runs as root (it configures system daemons); it writes /etc/slurm/slurm.conf only if there
# is none or it wrote it before, and leaves the daemons running. Exit code 0 if the check
# passes. The experiment stops each run at its first solution, which on its problems comes
# long before the budget, so outcomes depend on the seeds only and can be compared exactly.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
mit_star=$(realpath "${1:-$repo/target/release/mit-star}")
[ -x "$mit_star" ] || { echo "no mit-star binary at $mit_star (cargo build --release)" >&2; exit 2; }
[ "$(id -u)" = 0 ] || { echo "run as root: it configures munge and Slurm" >&2; exit 2; }
if ! command -v slurmctld > /dev/null; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y slurm-wlm munge
fi

conf=/etc/slurm/slurm.conf
marker="# written by mit-star docs/slurm/try-on-one-node.sh"
if [ -f "$conf" ] && ! grep -q "$marker" "$conf"; then
    echo "$conf exists and was not written by this script; not touching it" >&2
    exit 2
fi
host=$(hostname -s)
memory=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 - 512 ))
mkdir -p /etc/slurm /var/spool/slurmctld /var/spool/slurmd /var/log/slurm
cat > "$conf" <<CONF
$marker
ClusterName=mitstar
SlurmctldHost=$host
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldPidFile=/run/slurmctld.pid
SlurmdPidFile=/run/slurmd.pid
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
NodeName=$host CPUs=$(nproc) RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
mkdir -p /run/munge && chown munge:munge /run/munge
pgrep -x munged > /dev/null || su -s /bin/sh munge -c /usr/sbin/munged
pgrep -x slurmctld > /dev/null || slurmctld
pgrep -x slurmd > /dev/null || slurmd
for _ in $(seq 60); do
    state=$(sinfo -h -o %T 2> /dev/null | head -1 || true)
    [ "$state" = idle ] && break
    sleep 1
done
[ "$state" = idle ] || { echo "the node did not become idle (state: ${state:-none}); see /var/log/slurm" >&2; exit 1; }
echo "== Slurm $(sinfo -V) up: $(sinfo -h -o '%P %D nodes %c CPUs %T')"

campaign=$(mktemp -d /tmp/mit-star-slurm-trial.XXXXXX)
cat > "$campaign/trial.toml" <<TOML
name = "slurm-trial"
description = "Three planners on two 2-D problems, to the first solution: a campaign that fits in a minute"
runs = 10
seed = 100
confidence = 0.99
first_solution = true
planners = ["rrt-connect", "mit-star", "eit-star"]

[[problems]]
name = "dividing-walls"
dimensions = [2]
time = 5.0

[[problems]]
name = "goal-enclosure"
dimensions = [2]
time = 5.0
TOML
echo "== submitting 3 shards and a merge ($campaign)"
"$here/submit-campaign.sh" "$campaign/trial.toml" 3 "$campaign" "$mit_star" -- --cpus-per-task=1
for _ in $(seq 600); do
    [ -z "$(squeue -h -o %i)" ] && break
    sleep 1
done
echo "== jobs finished; their logs:"
for out in "$campaign"/*.out; do echo "--- $(basename "$out")"; tail -3 "$out"; done
[ -f "$campaign/merged/runs.jsonl" ] || { echo "FAIL: no merged folder" >&2; exit 1; }

echo "== the same experiment, whole, without Slurm"
"$mit_star" bench "$campaign/trial.toml" --output "$campaign/whole" --quiet --no-plots > /dev/null
python3 - "$campaign/whole/runs.jsonl" "$campaign/merged/runs.jsonl" <<'PY'
import json, sys
def runs(path):
    out = {}
    for line in open(path):
        r = json.loads(line)
        key = (r["instance"], r["planner"], r["run"])
        assert key not in out, f"{path}: {key} twice"
        out[key] = (r["seed"], r["status"], r.get("initial_cost"))
    return out
whole, merged = runs(sys.argv[1]), runs(sys.argv[2])
same = whole == merged
print(f"whole: {len(whole)} runs; merged from 3 Slurm shards: {len(merged)} runs; "
      f"identical runs, seeds, statuses and first-solution costs: {same}")
sys.exit(0 if same and len(whole) == 60 else 1)
PY
"$mit_star" compare "$campaign/whole" "$campaign/merged" | head -12
echo "== PASS: $campaign/merged"
