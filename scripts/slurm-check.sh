#!/usr/bin/env bash
# make slurm-check: the sharded run against a real Slurm, not a mock. Installs Slurm and munge
# from the distribution's packages (Debian: slurm-wlm, munge), starts a single-node cluster
# (munged, slurmctld, slurmd; 2 CPUs) with its own configuration under a temporary folder,
# writes the job array of `repro slurm fig7 --tasks 3 --level 5`, submits it with its
# dependent merge-and-assemble job, waits, and compares the assembled fig7.csv, fig7-line.csv
# and fig7.svg byte for byte with a one-machine run. Stops the daemons it started (by their
# pid files), whatever happens. Needs root (packages, daemons); not part of `make test`.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
REPRO="$ROOT/target/release/repro"
LEVEL=${LEVEL:-5}
TASKS=${TASKS:-3}
WAIT_SECONDS=${WAIT_SECONDS:-1200}

[ "$(id -u)" = 0 ] || { echo "slurm-check: needs root (installs packages, starts daemons)" >&2; exit 1; }
[ -x "$REPRO" ] || { echo "slurm-check: $REPRO missing: run make build first" >&2; exit 1; }

WORK=$(mktemp -d /tmp/repro-slurm-check.XXXXXX)
STARTED_PIDFILES=()
phase_start=$(date +%s.%N)
check_start=$phase_start
phase() { # phase NAME: closes the previous phase with its time, opens NAME
  local now; now=$(date +%s.%N)
  if [ -n "${PHASE:-}" ]; then
    printf '== %-28s %7.1f s\n' "$PHASE" "$(awk -v a="$now" -v b="$phase_start" 'BEGIN{print a-b}')"
  fi
  PHASE=$1; phase_start=$now
  [ -z "$1" ] || echo "-- $1"
}
stop_daemons() {
  local f pid
  for f in "${STARTED_PIDFILES[@]}"; do
    [ -s "$f" ] || continue
    pid=$(cat "$f")
    if kill -0 "$pid" 2>/dev/null; then
      kill "$pid" && echo "stopped pid $pid ($(basename "$f" .pid))"
      for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    fi
  done
}
on_exit() {
  local rc=$?
  stop_daemons
  if [ $rc -ne 0 ]; then
    echo "slurm-check: FAILED (exit $rc); daemon logs and job logs kept in $WORK" >&2
    tail -n 20 "$WORK"/log/*.log 2>/dev/null >&2 || true
  fi
}
trap on_exit EXIT

phase "install slurm and munge"
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v munged >/dev/null; then
  # Keep the packages' init scripts from starting daemons with the default configuration:
  # this check starts its own (policy-rc.d is the Debian way; ours only if there was none).
  policy_made=""
  if [ ! -e /usr/sbin/policy-rc.d ]; then
    printf '#!/bin/sh\nexit 101\n' > /usr/sbin/policy-rc.d; chmod +x /usr/sbin/policy-rc.d; policy_made=1
  fi
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    slurm-wlm munge >/dev/null
  [ -z "$policy_made" ] || rm -f /usr/sbin/policy-rc.d
fi
slurmctld -V

phase "start munge, slurmctld, slurmd"
HOST=$(hostname -s)
mkdir -p "$WORK"/{etc,state,spool,log,run}
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  [ -s /etc/munge/munge.key ] || { mungekey --create --keyfile=/etc/munge/munge.key 2>/dev/null \
    || dd if=/dev/urandom bs=1 count=1024 of=/etc/munge/munge.key 2>/dev/null; }
  chown munge:munge /etc/munge/munge.key; chmod 400 /etc/munge/munge.key
  install -d -o munge -g munge -m 0755 /run/munge
  install -d -o munge -g munge -m 0700 /var/lib/munge /var/log/munge
  runuser -u munge -- munged --pid-file=/run/munge/munged.pid
  STARTED_PIDFILES+=(/run/munge/munged.pid)
  for _ in $(seq 50); do munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break; sleep 0.1; done
fi
munge -n | unmunge | grep -q 'STATUS: *Success' && echo "munge: credentials round-trip"
cat > "$WORK/etc/slurm.conf" <<CONF
ClusterName=reprocheck
SlurmctldHost=$HOST
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/run/slurmctld.pid
SlurmdPidFile=$WORK/run/slurmd.pid
SlurmctldLogFile=$WORK/log/slurmctld.log
SlurmdLogFile=$WORK/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
ReturnToService=2
MinJobAge=3600
NodeName=$HOST CPUs=2 State=UNKNOWN
PartitionName=check Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$WORK/etc/slurm.conf"
slurmctld -f "$SLURM_CONF"
STARTED_PIDFILES+=("$WORK/run/slurmctld.pid")
slurmd -f "$SLURM_CONF"
STARTED_PIDFILES+=("$WORK/run/slurmd.pid")
for _ in $(seq 100); do
  state=$(sinfo -h -N -o %T 2>/dev/null | head -n1 || true)
  [ "$state" = idle ] && break; sleep 0.3
done
sinfo -N -o '%N %T %c' 
[ "$state" = idle ] || { echo "node never became idle (state '$state')" >&2; exit 1; }

phase "one-machine run (reference)"
"$REPRO" fig7 --level "$LEVEL" --cache "$WORK/local-cache" --out "$WORK/local-out" -q

phase "repro slurm (write scripts)"
cd "$WORK"
"$REPRO" slurm fig7 --tasks "$TASKS" --level "$LEVEL" --cpus 1 --time 20:00 --partition check \
  --dir "$WORK/slurm" --cache "$WORK/cluster-cache" --out "$WORK/cluster-out"
cd "$ROOT"

phase "submit, run array + assembly"
submitted=$(sh "$WORK/slurm/repro-fig7.submit.sh")
echo "$submitted"
array=$(echo "$submitted" | sed -n 's/^array job \([0-9]*\).*/\1/p')
assemble=$(echo "$submitted" | sed -n 's/.*assembly job \([0-9]*\).*/\1/p')
[ -n "$array" ] && [ -n "$assemble" ] || { echo "could not read the job ids" >&2; exit 1; }
waited=0
while squeue -h -j "$array,$assemble" 2>/dev/null | grep -q .; do
  sleep 2; waited=$((waited + 2))
  [ $waited -lt "$WAIT_SECONDS" ] || { echo "jobs still queued after $WAIT_SECONDS s" >&2; squeue; exit 1; }
done
scontrol show job "$array" | grep -E '^JobId|JobState|ExitCode' | paste - - - | sed 's/  */ /g'
scontrol show job "$assemble" | grep -E '^JobId|JobState|ExitCode' | paste - - - | sed 's/  */ /g'
bad=$(scontrol -o show job "$array" | grep -v 'JobState=COMPLETED' || true)
bad+=$(scontrol -o show job "$assemble" | grep -v 'JobState=COMPLETED' || true)
[ -z "$bad" ] || { echo "a job did not complete:"; echo "$bad"; cat "$WORK"/slurm/logs/*.log; exit 1; } >&2
for log in "$WORK"/slurm/logs/*.log; do
  echo "--- $(basename "$log")"; grep -E '^(shard|Slurm|merged|fig7|.*: [0-9]+ copied)' "$log" || true
done

phase "compare with the one-machine run"
for f in fig7.csv fig7-line.csv fig7.svg; do
  cmp "$WORK/local-out/$f" "$WORK/cluster-out/$f"
  echo "$f: byte-identical ($(wc -c < "$WORK/cluster-out/$f") bytes)"
done
echo "provenance of the assembled fig7 (who solved its cases):"
awk '/"computed_by"/{on=1} /"cases": \[/{on=0} on' "$WORK/cluster-out/fig7.provenance.json"

phase "stop daemons"
stop_daemons
STARTED_PIDFILES=()
phase ""
printf '== %-28s %7.1f s\n' "total" "$(awk -v a="$(date +%s.%N)" -v b="$check_start" 'BEGIN{print a-b}')"
rm -rf "$WORK"
echo "slurm-check: passed"
