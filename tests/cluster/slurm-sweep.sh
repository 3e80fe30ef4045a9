#!/usr/bin/env bash
# The cluster recipes of docs/analysis.md under a real scheduler: a one-node Slurm cluster on
# localhost runs docs/examples/sweep-slurm.sh as an array job, and GNU parallel runs the sweep's
# shards; in both cases the shards, put back in index order, must equal the single-process sweep
# line for line.
#   tests/cluster/slurm-sweep.sh [CUELAB-CLI]      (default: build/bin/cuelab-cli)
# Needs root (the daemons run as root in a temporary folder) and the packages of
# `scripts/install-deps.sh --cluster`; .ci/run runs it after installing them. Everything it starts
# (munged, slurmctld, slurmd) is stopped by its pid when the script exits, however it exits.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
cli=$(realpath "${1:-$root/build/bin/cuelab-cli}")
setup=$root/resources/examples/half-ball-cut.json
# 5 x 4 x 3 = 60 shots: small enough for seconds, four shards of unequal sizes (15 each; with 7
# shards the last ones are shorter, see the parallel run).
grid=(--vary shot.heading=-1:1:5 --vary shot.speed=1.5:3:4 --vary shot.side=-0.2:0.2:3 --goal pot:1@pocket-tr,no-scratch)

fail() { echo "slurm-sweep: FAILED: $*" >&2; exit 1; }
step() { echo "slurm-sweep: $*"; }

[ "$(id -u)" -eq 0 ] || fail "must run as root (it starts munged, slurmctld and slurmd)"
[ -x "$cli" ] || fail "no cuelab-cli at $cli (build first, or pass its path)"
for tool in munged mungekey munge unmunge slurmctld slurmd sbatch sinfo scontrol parallel; do
  command -v "$tool" >/dev/null || fail "$tool not found: run scripts/install-deps.sh --cluster"
done

tmp=$(mktemp -d /tmp/cuelab-slurm.XXXXXX)
chmod 755 "$tmp"
pids=()
cleanup() {
  local status=$?
  # Stop what this script started, newest first, by pid; then wait so nothing outlives the test.
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill "${pids[i]}" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  if [ $status -ne 0 ]; then
    for log in "$tmp"/munged.log "$tmp"/slurmctld.log "$tmp"/slurmd.log "$tmp"/work/logs/*; do
      [ -f "$log" ] && { echo "---- $log (last 30 lines)"; tail -n 30 "$log"; }
    done
  fi
  rm -rf "$tmp"
  exit $status
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# Waits up to $1 seconds for the command after it to succeed.
wait_for() {
  local seconds=$1; shift
  local deadline=$((SECONDS + seconds))
  until "$@" >/dev/null 2>&1; do
    [ $SECONDS -lt $deadline ] || return 1
    sleep 0.2
  done
}

# A TCP port nobody listens on, from $1 upwards.
free_port() {
  local port=$1
  while (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; do port=$((port + 1)); done
  echo "$port"
}

# ---- the reference: one process, every shot, grid order
mkdir -p "$tmp/work/logs"
cp "$setup" "$tmp/work/cut.json"
cd "$tmp/work"
"$cli" sweep cut.json "${grid[@]}" --jobs 1 > whole.jsonl
[ "$(wc -l < whole.jsonl)" -eq 60 ] || fail "the single-process sweep printed $(wc -l < whole.jsonl) lines, not 60"

# The shards' lines in grid order: each line begins {"index": i, and the indices are unique.
in_grid_order() { cat "$@" | sort -t: -k2,2n; }
compare() {  # $1: what ran; the rest: the shard files
  local what=$1; shift
  in_grid_order "$@" > merged.jsonl
  if ! cmp -s merged.jsonl whole.jsonl; then
    diff whole.jsonl merged.jsonl | head -n 10 >&2 || true
    fail "$what: the shards ($(wc -l < merged.jsonl) lines) differ from the single-process sweep (60 lines)"
  fi
  step "$what: $# shards, $(wc -l < merged.jsonl) lines, equal to the single-process sweep"
}

# ---- GNU parallel: the command of docs/analysis.md with a small grid, 7 shards on 2 workers
step "GNU parallel $(parallel --version | head -n 1 | awk '{print $3}')"
rm -rf out && mkdir out
timeout 60 parallel --will-cite --halt now,fail=1 -j 2 \
  "'$cli' sweep cut.json ${grid[*]} --shard {}/7 --jobs 1 > out/shard-{}.jsonl" ::: 1 2 3 4 5 6 7 \
  || fail "GNU parallel: a shard failed or it took over 60 s"
compare "GNU parallel" out/shard-*.jsonl

# ---- MUNGE: Slurm's authentication, with a key made for this run
step "munged"
mkdir -p "$tmp/munge"
chmod 700 "$tmp/munge"
mungekey --create --keyfile="$tmp/munge/munge.key" --bits=1024 >/dev/null 2>&1 \
  || dd if=/dev/urandom of="$tmp/munge/munge.key" bs=128 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
mkdir -p "$tmp/munge-socket"  # clients need to reach the socket: not inside the key's private folder
socket=$tmp/munge-socket/munge.socket
munged --foreground --force --key-file="$tmp/munge/munge.key" --socket="$socket" \
  --pid-file="$tmp/munge/munged.pid" --seed-file="$tmp/munge/munged.seed" \
  --log-file="$tmp/munged.log" >/dev/null 2>&1 &
pids+=($!)
wait_for 15 bash -c "munge -n -S '$socket' | unmunge -S '$socket'" || fail "munged did not answer within 15 s"

# ---- Slurm: slurmctld and slurmd on this host, configured in $tmp only
host=$(hostname -s)
ctld_port=$(free_port 16817)
slurmd_port=$(free_port $((ctld_port + 1)))
cpus=$(nproc)
mkdir -p "$tmp/state" "$tmp/spool"
export SLURM_CONF=$tmp/slurm.conf
cat > "$SLURM_CONF" <<CONF
ClusterName=cuelab-ci
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
SlurmdParameters=config_overrides
MaxArraySize=1001
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=ci Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF

step "slurmctld and slurmd ($host, ports $ctld_port and $slurmd_port, $cpus CPUs)"
slurmctld -D -i -f "$SLURM_CONF" > "$tmp/slurmctld.out" 2>&1 &
pids+=($!)
wait_for 20 scontrol ping || fail "slurmctld did not answer within 20 s"
slurmd -D -f "$SLURM_CONF" > "$tmp/slurmd.out" 2>&1 &
pids+=($!)
node_idle() { sinfo -h -n "$host" -o %T | grep -qx idle; }
wait_for 30 node_idle || fail "the node did not become idle within 30 s (state: $(sinfo -h -n "$host" -o %T 2>&1))"

# ---- the array job: docs/examples/sweep-slurm.sh with the small grid, 4 tasks of 1 CPU
rm -rf out
step "sbatch --wait --array=1-4 docs/examples/sweep-slurm.sh"
export PATH="$(dirname "$cli"):$PATH"
timeout 90 sbatch --wait --quiet --array=1-4 --cpus-per-task=1 --time=00:05:00 \
  "$root/docs/examples/sweep-slurm.sh" cut.json "${grid[@]}" \
  || fail "the array job failed or took over 90 s (sbatch exit $?)"
[ "$(ls out/shard-*.jsonl 2>/dev/null | wc -l)" -eq 4 ] || fail "expected 4 shard files, found: $(ls out 2>&1)"
compare "Slurm array job" out/shard-*.jsonl
step "passed"
