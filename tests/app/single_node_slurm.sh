#!/usr/bin/env bash
# A Slurm cluster of one node on this machine, for the tests of `sedem batch --emit slurm`:
# munged, slurmctld and slurmd (Debian's munge and slurm-wlm) run as root from DIR, where
# their configuration, key, state, logs and pid files all are, on the ports given; stopped by
# their pid files. Nothing outside DIR is read or changed (SLURM_CONF points at DIR's).
#
#   single_node_slurm.sh start DIR CONTROLLER_PORT NODE_PORT
#   single_node_slurm.sh stop DIR
#
# `start` returns once the node is idle, with SLURM_CONF=DIR/slurm.conf for sbatch and squeue.
# It exits 77 with the reason on stderr where Slurm cannot run here (not root, a program
# missing) and 1 when a daemon does not come up (its log's end on stderr).
set -uo pipefail

usage() { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 1; }
[[ $# -ge 2 ]] || usage
action=$1
dir=$(realpath -m "$2")

# Each daemon's pid file, in the order they are stopped.
pid_files=("$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid")

stop() {
  local f pid k
  for f in "${pid_files[@]}"; do
    [[ -s $f ]] || continue
    pid=$(<"$f")
    [[ $pid =~ ^[0-9]+$ ]] || continue
    kill -TERM "$pid" 2>/dev/null || continue
    for ((k = 0; k < 100; k++)); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -KILL "$pid" 2>/dev/null || true
  done
  rm -f "${pid_files[@]}"
}

fail() {  # a daemon did not come up: why, from its log
  echo "single_node_slurm.sh: $1" >&2
  [[ -f $2 ]] && tail -n 15 "$2" >&2
  stop
  exit 1
}

case $action in
  stop) stop; exit 0 ;;
  start) [[ $# -eq 4 ]] || usage ;;
  *) usage ;;
esac
controller_port=$3
node_port=$4

if [[ $(id -u) -ne 0 ]]; then
  echo "single_node_slurm.sh: Slurm's daemons run as root here, and this is user $(id -un)" >&2
  exit 77
fi
for program in munged mungekey slurmctld slurmd sbatch squeue sinfo; do
  if ! command -v "$program" >/dev/null; then
    echo "single_node_slurm.sh: no $program (apt-get install slurm-wlm munge; scripts/setup.sh)" >&2
    exit 77
  fi
done

stop
rm -rf "$dir"
mkdir -p "$dir/state" "$dir/spool" "$dir/munge"
chmod 700 "$dir/munge"
chmod 755 "$dir"

# munge: a key of its own, its socket in DIR (--force: /tmp's parents are world-writable).
mungekey --create --keyfile="$dir/munge/munge.key" --force || fail "mungekey failed" /dev/null
chmod 400 "$dir/munge/munge.key"
munged --force --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" \
  --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" \
  --seed-file="$dir/munge/munged.seed" || fail "munged did not start" "$dir/munge/munged.log"

node=$(hostname -s)
cpus=$(nproc)
# Below the machine's memory, or slurmd would find less than it declares and drain the node.
memory_mb=$(awk '/^MemTotal:/ { printf "%d", $2 / 1024 * 0.9 }' /proc/meminfo)
cat >"$dir/slurm.conf" <<CONF
ClusterName=sedemtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$controller_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
# No cgroups: processes tracked by their parents, tasks not confined.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory_mb State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf

slurmctld || fail "slurmctld did not start" "$dir/slurmctld.log"
slurmd -N "$node" || fail "slurmd did not start" "$dir/slurmd.log"
for ((k = 0; k < 300; k++)); do
  state=$(sinfo -h -n "$node" -o %T 2>/dev/null || true)
  [[ $state == idle ]] && exit 0
  sleep 0.1
done
fail "the node is not idle after 30 s (sinfo: ${state:-no answer})" "$dir/slurmd.log"
