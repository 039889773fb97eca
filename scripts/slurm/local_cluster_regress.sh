#!/usr/bin/env bash
# The regression on Slurm, proven on this machine: starts a one-node Slurm
# cluster (Debian's slurm-wlm and munge, loopback only), submits the
# regression as an array job through scripts/slurm/regress_array.sbatch,
# waits, merges the shards' results, runs the same selection locally and
# checks that the merged report equals the local one test by test
# (scripts/slurm/compare_results.py). The daemons are stopped at the end,
# also on failure. Needs root (daemons, apt-get) and a build (scripts/build.sh).
#
# Usage: scripts/slurm/local_cluster_regress.sh [--shards N] [--out-dir DIR] [regress selection...]
#   --shards N   array tasks (default 2), each one core
#   --out-dir    work and results (default build/slurm)
#   the rest goes to `scurve regress` in both runs (default: --label quick)
# Exit status: 0 when the Slurm run passed and equals the local run; 1 when
# they differ or a test failed; 2 on bad usage or when the cluster does not
# come up (the daemons' logs are printed).
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$here/build}
shards=2
out=$build/slurm
sel=()
while [ $# -gt 0 ]; do
  case "$1" in
    --shards) shards=${2:-}; shift 2 || { echo "error: --shards needs a value" >&2; exit 2; } ;;
    --out-dir) out=${2:-}; shift 2 || { echo "error: --out-dir needs a value" >&2; exit 2; } ;;
    *) sel+=("$1"); shift ;;
  esac
done
if ! [[ "$shards" =~ ^[0-9]+$ ]] || [ "$shards" -lt 1 ] || [ "$shards" -gt 64 ]; then
  echo "error: --shards=$shards: must be an integer from 1 to 64" >&2; exit 2
fi
[ ${#sel[@]} -gt 0 ] || sel=(--label quick)
if [ "$(id -u)" -ne 0 ]; then echo "error: needs root (starts munged, slurmctld, slurmd)" >&2; exit 2; fi
if [ ! -x "$build/bin/scurve" ]; then echo "error: $build/bin/scurve missing: run scripts/build.sh" >&2; exit 2; fi

# Debian packages, when missing (about 10 s).
need=()
for p in slurmctld slurmd slurm-client munge; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
  echo "slurm: installing ${need[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq && apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi

rm -rf "$out" && mkdir -p "$out/state" "$out/spool" "$out/logs"
conf=$out/slurm.conf
cpus=$(nproc)
mem=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 - 512 ))
cat > "$conf" <<CONF
# One-node cluster on the loopback interface (written by local_cluster_regress.sh).
ClusterName=scurve
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
SlurmctldPort=6817
SlurmdPort=6818
AuthType=auth/munge
StateSaveLocation=$out/state
SlurmdSpoolDir=$out/spool
SlurmctldPidFile=$out/slurmctld.pid
SlurmdPidFile=$out/slurmd.pid
SlurmctldLogFile=$out/logs/slurmctld.log
SlurmdLogFile=$out/logs/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
NodeName=localhost CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=local Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$conf

started_munge=0
cleanup() {
  scontrol shutdown >/dev/null 2>&1 || true
  for f in "$out/slurmd.pid" "$out/slurmctld.pid"; do
    [ -f "$f" ] && kill "$(cat "$f")" 2>/dev/null || true
  done
  if [ $started_munge = 1 ]; then pkill -u munge -x munged 2>/dev/null || true; fi
}
trap cleanup EXIT
die_with_logs() {
  echo "error: $1" >&2
  for f in "$out"/logs/*.log; do [ -f "$f" ] && { echo "--- $f" >&2; tail -20 "$f" >&2; }; done
  exit 2
}

# munge: /run/munge owned by munge, munged as the munge user.
if ! pgrep -u munge -x munged >/dev/null; then
  install -d -o munge -g munge -m 0755 /run/munge
  [ -f /etc/munge/munge.key ] || { mungekey --create --keyfile /etc/munge/munge.key; chown munge:munge /etc/munge/munge.key; }
  # In the foreground, backgrounded here: a daemonizing munged reopens
  # /dev/null, which some containers do not let other users write.
  runuser -u munge -- /usr/sbin/munged --foreground </dev/null >"$out/logs/munged.log" 2>&1 &
  started_munge=1
  for _ in $(seq 1 40); do [ -S /run/munge/munge.socket.2 ] && break; sleep 0.25; done
fi
munge -n | unmunge >/dev/null || die_with_logs "munge does not authenticate"

slurmctld -f "$conf" || die_with_logs "slurmctld did not start"
slurmd -f "$conf" -N localhost || die_with_logs "slurmd did not start"
for _ in $(seq 1 60); do
  state=$(sinfo -h -N -o %t 2>/dev/null || true)
  [ "$state" = "idle" ] && break
  sleep 0.5
done
[ "$state" = "idle" ] || die_with_logs "node localhost not idle after 30 s (state '$state')"
echo "slurm: one-node cluster up ($cpus CPUs), $shards array tasks of one core"

start=$(date +%s)
SC_REGRESS_SHARDS=$out/shards sbatch --wait --array=1-"$shards" --cpus-per-task=1 --chdir="$here" \
  --output="$out/logs/task_%a.out" --export=ALL,BUILD_DIR="$build" \
  "$here/scripts/slurm/regress_array.sbatch" "${sel[@]}" >"$out/logs/sbatch.out" 2>&1 || {
  cat "$out/logs/sbatch.out" >&2; tail -n 30 "$out"/logs/task_*.out >&2 || true; echo "slurm: an array task failed" >&2; }
echo "slurm: array job done in $(( $(date +%s) - start )) s: $(cat "$out/logs/sbatch.out")"

"$build/bin/scurve" regress --merge "$out"/shards/shard*/results.json --out-dir "$out/merged" >/dev/null
echo "slurm: local run of the same selection"
"$build/bin/scurve" regress --list "$here/tests/regress_list.json" --jobs "$cpus" --out-dir "$out/local" \
  "${sel[@]}" >/dev/null || true
rc=0
python3 "$here/scripts/slurm/compare_results.py" "$out/merged/results.json" "$out/local/results.json" || rc=$?
exit $rc
