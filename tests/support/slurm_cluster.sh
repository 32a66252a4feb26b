# slurm_cluster.sh — a one-node Slurm cluster in a folder, for tests, from
# Debian's packages (slurmctld, slurmd, munge, slurm-client), as root and
# without systemd: its own munge key and socket, its own ports, state and
# spool folders and logs, so that it meets nothing else on the machine.
# Sourced by a POSIX shell script:
#   . tests/support/slurm_cluster.sh
#   slurm_cluster_start FOLDER || skip "$slurm_cluster_why"
#   trap slurm_cluster_stop EXIT   # (set it before the start: it stops what started)
#   sbatch ...                      # SLURM_CONF is exported: the clients talk to this cluster
# slurm_cluster_wait_job ID SECONDS prints a job's state once it has ended.
#
# The configuration, and why (slurm.conf(5)):
# - ProctrackType=proctrack/linuxproc, TaskPlugin=task/none: a job's
#   processes are tracked by their parent process ids and confined in
#   nothing, because the cgroup plugins need a cgroup tree slurmd may write
#   (a container's, or a CI machine's, may be read-only or a v1/v2 mix).
#   A process that daemonized would escape the tracking; the runs do not.
# - no accounting (slurmdbd) or job completion log: a job's end state is read
#   from slurmctld while MinJobAge keeps it (10 minutes, past any test).
# - one node claiming 4 CPUs and 8 GB (SlurmdParameters=config_overrides,
#   whatever the machine has): the scheduler books what the jobs ask for and
#   nothing enforces it (no cgroups); the test's jobs mostly wait at a fault
#   point or run in a second, so a 2-core machine runs them all.
# - KillWait stays Slurm's default, 30 s: at a time limit the steps get
#   SIGTERM, and SIGKILL only 30 s later, as on most clusters.
# - SlurmUser=root: slurmd must be root to start jobs, and the test is root.

slurm_cluster_why=""
slurm_cluster_dir=""

# Whether this machine can run the cluster at all; else the reason in slurm_cluster_why.
slurm_cluster_usable() {
  if [ "$(id -u)" -ne 0 ]; then
    slurm_cluster_why="the Slurm daemons must run as root (this is uid $(id -u))"
    return 1
  fi
  for c in munged mungekey slurmctld slurmd sbatch srun squeue scontrol scancel sinfo; do
    if ! command -v "$c" >/dev/null 2>&1; then
      slurm_cluster_why="no '$c' (Debian 12: apt-get install slurmctld slurmd munge slurm-client; make test-deps installs them)"
      return 1
    fi
  done
}

# Two free TCP ports on 127.0.0.1 (taken and released at once: free when the daemons bind them).
slurm_cluster_ports() {
  /usr/bin/python3 -c 'import socket
ss = [socket.socket() for _ in range(2)]
for s in ss: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in ss])'
}

# Writes the configuration into $1 and starts munged, slurmctld and slurmd;
# returns once a one-task step ran. Else stops what it started, says why in
# slurm_cluster_why (with the daemon's last log line) and returns 1.
slurm_cluster_start() {
  slurm_cluster_usable || return 1
  # A Slurm job around the test (CI inside an allocation) must not leak into this cluster's clients.
  for v in $(env | sed -n 's/^\(\(SLURM\|SBATCH\|SALLOC\|SRUN\)_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
  d=$1
  # Unix socket paths are limited to 108 bytes: a deep build folder puts the
  # cluster in a temporary folder instead.
  [ "${#d}" -le 64 ] || d=$(mktemp -d)
  slurm_cluster_dir=$d
  mkdir -p "$d/munge" "$d/state" "$d/spool" "$d/log"
  chmod 755 "$d" "$d/munge"  # munged refuses a socket folder others cannot enter
  mungekey --create --keyfile="$d/munge/munge.key" 2>"$d/log/mungekey.log" || {
    slurm_cluster_why="mungekey failed: $(tail -n 1 "$d/log/mungekey.log")"; return 1; }
  munged --foreground --socket="$d/munge/socket" --key-file="$d/munge/munge.key" --pid-file="$d/munge/pid" \
    --log-file="$d/log/munged.log" --seed-file="$d/munge/seed" >>"$d/log/munged.log" 2>&1 &
  echo $! >"$d/munged.pid"
  ports=$(slurm_cluster_ports) || { slurm_cluster_why="no free ports for slurmctld and slurmd"; return 1; }
  host=$(uname -n)
  host=${host%%.*}
  : >"$d/plugstack.conf"
  cat >"$d/slurm.conf" <<EOF
ClusterName=coolgastest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=${ports% *}
SlurmdPort=${ports#* }
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$d/munge/socket
CredType=cred/munge
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pidfile
SlurmdPidFile=$d/slurmd.pidfile
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
PlugStackConfig=$d/plugstack.conf
MailProg=/bin/true
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
SlurmdParameters=config_overrides
ReturnToService=2
MinJobAge=600
NodeName=coolgasnode NodeHostname=$host NodeAddr=127.0.0.1 CPUs=4 RealMemory=8192 State=UNKNOWN
PartitionName=test Nodes=coolgasnode Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF="$d/slurm.conf"
  slurm_cluster_until 30 test -S "$d/munge/socket" ||
    { slurm_cluster_why="munged did not start: $(tail -n 1 "$d/log/munged.log")"; return 1; }
  slurmctld -D -f "$d/slurm.conf" >"$d/log/slurmctld.out" 2>&1 &
  echo $! >"$d/slurmctld.pid"
  slurmd -D -f "$d/slurm.conf" -N coolgasnode >"$d/log/slurmd.out" 2>&1 &
  echo $! >"$d/slurmd.pid"
  slurm_cluster_exited=""
  slurm_cluster_until 60 slurm_cluster_up || slurm_cluster_exited=${slurm_cluster_exited:-"the node is $(sinfo -h -o %T 2>&1 | head -n 1), not idle, after 60 s: slurmctld: $(slurm_cluster_last slurmctld); slurmd: $(slurm_cluster_last slurmd)"}
  if [ -n "$slurm_cluster_exited" ]; then
    slurm_cluster_why=$slurm_cluster_exited
    return 1
  fi
  # A step on the node (srun and slurmd reach each other), bounded by its own time limit.
  if ! srun --time=1 --mem=16 true >"$d/log/srun.out" 2>&1; then
    slurm_cluster_why="a one-task step failed: $(tail -n 1 "$d/log/srun.out")"
    return 1
  fi
}

# Whether the node is idle (0), or a daemon has exited (0 too, the reason in
# slurm_cluster_exited): the wait for it ends either way.
slurm_cluster_up() {
  for daemon in slurmctld slurmd; do
    if ! kill -0 "$(cat "$slurm_cluster_dir/$daemon.pid")" 2>/dev/null; then
      slurm_cluster_exited="$daemon exited: $(slurm_cluster_last "$daemon")"
      return 0
    fi
  done
  [ "$(sinfo -h -o %T 2>/dev/null)" = idle ]
}

# A daemon's last fatal line, else its last error that is not one of a first
# start's (no state files yet, no PMIx library), else its last line.
slurm_cluster_last() {
  logs="$slurm_cluster_dir/log/$1.out $slurm_cluster_dir/log/$1.log"
  # shellcheck disable=SC2086 # two file names
  { grep -h 'fatal' $logs || grep -h -i 'error' $logs | grep -v -i 'state\|pmix\|mpi' || cat $logs; } 2>/dev/null | tail -n 1
}

# slurm_cluster_until SECONDS COMMAND...: runs COMMAND every half second
# until it succeeds (0) or SECONDS have passed (1). A bound on a wait for
# failure, never a measure of anything.
slurm_cluster_until() {
  tries=$(($1 * 2))
  shift
  while ! "$@"; do
    tries=$((tries - 1))
    [ "$tries" -gt 0 ] || return 1
    sleep 0.5
  done
}

# A job's state (PENDING, RUNNING, COMPLETED, TIMEOUT, FAILED, ...).
slurm_cluster_job_state() { scontrol show job "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p'; }

# Whether a job has ended: its state is one of the final ones (squeue(1),
# JOB STATE CODES). Not "anything but the running states": a job shows
# passing states too, SIGNALING while its --signal is sent (then RUNNING
# again), which a wait must not take for its end.
slurm_cluster_job_ended() {
  case $(slurm_cluster_job_state "$1") in
    BOOT_FAIL | CANCELLED | COMPLETED | DEADLINE | FAILED | NODE_FAIL | OUT_OF_MEMORY | PREEMPTED | TIMEOUT) return 0 ;;
  esac
  return 1
}

# slurm_cluster_wait_job ID SECONDS: waits until job ID has ended, then
# prints its state; prints "still STATE after SECONDS s" if it has not.
slurm_cluster_wait_job() {
  if slurm_cluster_until "$2" slurm_cluster_job_ended "$1"; then
    slurm_cluster_job_state "$1"
  else
    echo "still $(slurm_cluster_job_state "$1") after $2 s"
  fi
}

# Stops the cluster: every job cancelled and gone (their steps' processes
# with them), then slurmd, slurmctld and munged, each by its process id.
slurm_cluster_stop() {
  d=$slurm_cluster_dir
  [ -n "$d" ] || return 0
  if [ -f "$d/slurmctld.pid" ]; then
    scancel --user="$(id -un)" 2>/dev/null
    slurm_cluster_until 60 slurm_cluster_no_jobs || echo "slurm_cluster_stop: jobs still listed after 60 s: $(squeue -h -o '%i %T' | tr '\n' ' ')"
  fi
  for daemon in slurmd slurmctld munged; do
    [ -f "$d/$daemon.pid" ] || continue
    pid=$(cat "$d/$daemon.pid")
    kill "$pid" 2>/dev/null
    slurm_cluster_until 20 slurm_cluster_gone "$pid" || kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    rm -f "$d/$daemon.pid"
  done
  slurm_cluster_dir=""
}

slurm_cluster_no_jobs() { [ -z "$(squeue -h -o %i 2>/dev/null)" ]; }
slurm_cluster_gone() { ! kill -0 "$1" 2>/dev/null; }
