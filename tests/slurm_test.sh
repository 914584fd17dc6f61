#!/usr/bin/env bash
# A one-node Slurm on this machine (Debian 12's munge, slurmctld and slurmd 22.05; no cgroups:
# proctrack/linuxproc, task/none), running cluster/slurm/submit as a user would: the array job
# of sample ranges, then the merge job. The merged image must equal a single process's render
# per pixel (tests/compare_exact.py) and pass pt diff against it; a failing task must keep the
# merge from running and be named by cluster/slurm/failed. Installs what it needs
# (tools/install-deps --slurm), stops what it started; exits 77 (skipped) only when the daemons
# cannot start here, saying why.
# usage: slurm_test.sh PT
set -uo pipefail
export PT
PT=$(realpath "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
started=()
cleanup() {
  for pidfile in "${started[@]}"; do [[ -f "$pidfile" ]] && kill "$(cat "$pidfile")" 2>/dev/null; done
  sleep 1
  rm -rf "$work"
}
trap cleanup EXIT
skip() { echo "SKIPPED: $*"; exit 77; }

[[ $(id -u) -eq 0 ]] || command -v sudo >/dev/null || skip "needs root (or sudo) to run slurmctld and slurmd"
"$root/tools/install-deps" --slurm >/dev/null || skip "could not install munge and Slurm (tools/install-deps --slurm)"
as_root=()
[[ $(id -u) -eq 0 ]] || as_root=(sudo)

# munge: reuse a running one, else start one (as root it needs --force).
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  "${as_root[@]}" mkdir -p /run/munge
  "${as_root[@]}" munged --force 2>"$work/munged.err" || skip "munged did not start: $(cat "$work/munged.err")"
  started+=(/run/munge/munged.pid)
  sleep 0.5
  munge -n | unmunge >/dev/null 2>&1 || skip "munge does not answer: $(cat "$work/munged.err")"
fi

host=$(hostname -s)
port=$((20000 + RANDOM % 20000))
mkdir -p "$work/state" "$work/spool"
cat >"$work/slurm.conf" <<CONF
ClusterName=pttest
SlurmctldHost=$host
AuthType=auth/munge
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
"${as_root[@]}" slurmctld -f "$SLURM_CONF" || skip "slurmctld did not start: $(tail -3 "$work/slurmctld.log" 2>/dev/null)"
started+=("$work/slurmctld.pid")
"${as_root[@]}" slurmd -f "$SLURM_CONF" || skip "slurmd did not start: $(tail -3 "$work/slurmd.log" 2>/dev/null)"
started+=("$work/slurmd.pid")
for _ in $(seq 1 30); do
  sinfo -h -o %t 2>/dev/null | grep -q idle && break
  sleep 1
done
sinfo -h -o %t 2>/dev/null | grep -q idle || skip "the node never came up: $(tail -3 "$work/slurmd.log") $(tail -3 "$work/slurmctld.log")"
echo "slurm: one node ($host, $(nproc) CPUs) up on port $port"

# wait_for JOB: until it has left the queue; prints its final state.
wait_for() {
  for _ in $(seq 1 180); do
    state=$(scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | head -1 | cut -d= -f2)
    [[ "$state" == PENDING || "$state" == RUNNING || "$state" == CONFIGURING || "$state" == COMPLETING ]] || { echo "$state"; return; }
    sleep 1
  done
  echo TIMEOUT
}

fail=0
scene=$root/scenes/cornell_box.obj
opts=(--res 64x48 --aov variance,albedo)
read -r array merge < <("$root/cluster/slurm/submit" "$scene" -spp 32 --tasks 4 -o "$work/out.exr" "${opts[@]}" | tail -1)
state=$(wait_for "$merge")
"$PT" render "$scene" -spp 32 "${opts[@]}" -q -o "$work/single.exr" >/dev/null
if [[ "$state" != COMPLETED || ! -f "$work/out.exr" ]]; then
  echo "FAIL: the merge job ended $state"; cat "$work"/out.parts/*.log; fail=1
else
  /usr/bin/python3 "$root/tests/compare_exact.py" "$work/out.exr" "$work/single.exr" || fail=1
  "$PT" diff "$work/out.exr" "$work/single.exr" -q || fail=1
  echo "ok: 4 tasks of 8 spp through Slurm (array job $array, merge job $merge) equal one 32-spp render"
fi

# A task that fails (its part's path is a folder) cancels the merge; the failed task is named.
mkdir -p "$work/bad.parts/part-0002.exr"
read -r array merge < <("$root/cluster/slurm/submit" "$scene" -spp 32 --tasks 4 -o "$work/bad.exr" "${opts[@]}" | tail -1)
state=$(wait_for "$merge")
report=$("$root/cluster/slurm/failed" "$array" "$work/bad.parts")
if [[ "$state" == CANCELLED && ! -e "$work/bad.exr" && "$report" == *"task 2: FAILED"*"is a folder"* ]]; then
  echo "ok: a failed task cancels the merge (merge job $state) and is named:"; echo "$report"
else
  echo "FAIL: failed task: merge job $state, bad.exr $(ls "$work/bad.exr" 2>&1), report: $report"; fail=1
fi
exit $fail
