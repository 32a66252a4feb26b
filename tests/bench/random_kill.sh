#!/bin/sh
# Crash safety and exact resume under SIGKILL at random moments, in every
# phase of a run's life on a cluster. A small scene is run once
# uninterrupted (the reference); then, RUNS times in each phase, a job is
# killed with SIGKILL after a random delay within that job's own wall time,
# the file is checked with coolgas-validate, the same job is started again
# (as a scheduler's next job would) and the file must equal the reference
# (h5diff: every dataset and attribute):
#   fresh     a new run is killed (one killed before its first dump left no
#             file and is started again, as a user would);
#   sigint    a run stopped by SIGINT (a time limit with grace) is resumed,
#             and the resume is killed;
#   sigkill   a run killed at a random moment is resumed, and the resume is
#             killed too;
#   extend    a finished run is extended with --set run.t_end=..., and the
#             extension is killed.
# KILL_AT=events stops each job at a named point instead (common/fault_point.h,
# docs/reliability.md): after a number of events drawn from the same seeds,
# below 0.9 times the collisions the job has left (it has more events than
# that), with a checkpoint after every slice of events. The kills are then
# the same on every machine: ctest runs this, 5 jobs a phase; the timed kills
# are for running by hand.
# Prints one line per job (a failing file or message is kept in the scratch
# folder as failed-*), a summary per phase, and exits 1 unless every job in
# every phase ended identical to the reference:
#   PHASE K: at WHEN (time|events) killed=0|1 validates=0|1 again=0|1 identical=0|1
#   PHASE: identical=I of RUNS (validated=V resumed=R)
#
# usage: tests/bench/random_kill.sh BUILD_DIR [RUNS] [SCRATCH_DIR] [PHASES]
#   e.g. tests/bench/random_kill.sh build 50 /tmp/kill
#        tests/bench/random_kill.sh build 3 /tmp/kill "sigint extend"
# Environment: COOLGAS_CHECKPOINT_INTERVAL (default here 0.05 s, so kills land
# between mid-run checkpoints and inside them as well as before the first
# one; 0 with KILL_AT=events); KILL_N, KILL_T_END (the scene's size and
# length; defaults 8000, 1000); KILL_AT (time, the default, or events).
set -u
build=${1:?usage: random_kill.sh BUILD_DIR [RUNS] [SCRATCH_DIR] [PHASES]}
runs=${2:-50}
dir=${3:-$(mktemp -d)}
phases=${4:-fresh sigint sigkill extend}
sim="$build/bin/coolgas-simulate -q"
validate="$build/bin/coolgas-validate"
kill_at=${KILL_AT:-time}
case $kill_at in
  time) export COOLGAS_CHECKPOINT_INTERVAL=${COOLGAS_CHECKPOINT_INTERVAL:-0.05} ;;
  events) export COOLGAS_CHECKPOINT_INTERVAL=${COOLGAS_CHECKPOINT_INTERVAL:-0} ;;
  *) echo "KILL_AT=$kill_at: time or events"; exit 2 ;;
esac
t_end=${KILL_T_END:-1000}
mkdir -p "$dir"
cat > "$dir/gas.toml" <<SCENE
[system]
N = ${KILL_N:-8000}
phi = 0.208
seed = 5
equilibrate = 1
[collision]
model = "inelastic"
r0 = 0.1
delta = 1e-4
[run]
t_end = $t_end
[output]
dumps_per_decade = 10
SCENE

now() { date +%s.%N; }
since() { echo "$(now) - $1" | bc; }
# A delay in [0, 0.9 * $2) seconds, the same for the same seed $1.
delay_for() { awk -v seed="$1" -v w="$2" 'BEGIN { srand(seed); printf "%.3f", 0.9 * rand() * w }'; }
# An event count in [1, 0.9 * $2], the same for the same seed $1.
count_for() { awk -v seed="$1" -v n="$2" 'BEGIN { srand(seed); printf "%d", 1 + 0.9 * rand() * n }'; }
# The collisions of a run's file up to its last observation.
collisions_of() {
  h5dump -d /observables/collisions/value -y -w 0 "$1" | tr -s ' ,' '\n\n' | grep -E '^[0-9]+$' | tail -n 1
}
# Stops a job ("$@" after $1 and $2) at a moment drawn from seed $1: with
# SIGKILL within 0.9 of $2 seconds (KILL_AT=time), or at the fault after that
# share of $3 events (KILL_AT=events). Sets $at to what it chose and $killed
# to 1 if the job was killed (0: it ended first).
stop_job() {
  seed=$1 seconds=$2 events=$3
  shift 3
  if [ "$kill_at" = events ]; then
    at=$(count_for "$seed" "$events")
    COOLGAS_FAULT=events:$at "$@" >/dev/null 2>&1
  else
    at=$(delay_for "$seed" "$seconds")
    kill_after "$at" "$@"
  fi
  [ $? -eq 137 ] && killed=1 || killed=0
}
# Runs a job ("$@") in the background and kills it with SIGKILL after $1 seconds.
kill_after() {
  d=$1
  shift
  "$@" >/dev/null 2>&1 &
  pid=$!
  sleep "$d"
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
}
# The files of a run named $1 (trajectory, checkpoint and their temporary names) copied to $2.
copy_run() {
  rm -f "$2" "$2.checkpoint" "$2.partial" "$2.checkpoint.partial"
  cp "$1" "$2"
  [ -f "$1.checkpoint" ] && cp "$1.checkpoint" "$2.checkpoint"
  return 0
}

start=$(now)
$sim "$dir/gas.toml" -o "$dir/whole.h5" --force || { echo "the uninterrupted run failed"; exit 1; }
wall=$(since "$start")
echo "uninterrupted run: ${wall}s"
# The states the resuming phases start from, and how long their jobs take uninterrupted.
whole_collisions=$(collisions_of "$dir/whole.h5")
if [ "$kill_at" = events ]; then
  COOLGAS_FAULT=events:$((whole_collisions / 3)):INT $sim "$dir/gas.toml" -o "$dir/stopped.h5" --force >/dev/null 2>&1
else
  $sim "$dir/gas.toml" -o "$dir/stopped.h5" --force >/dev/null 2>&1 &
  pid=$!
  sleep "$(echo "$wall / 3" | bc -l)"
  kill -INT "$pid"
  wait "$pid"
fi
[ $? -eq 3 ] || { echo "the SIGINT run did not stop with exit code 3"; exit 1; }
copy_run "$dir/stopped.h5" "$dir/probe.h5"
start=$(now)
$sim --resume "$dir/probe.h5" || { echo "resuming the SIGINT run failed"; exit 1; }
wall_sigint=$(since "$start")
short_end=$(echo "$t_end / 4" | bc -l)
$sim "$dir/gas.toml" -o "$dir/short.h5" --force --set "run.t_end=$short_end" || { echo "the short run failed"; exit 1; }
copy_run "$dir/short.h5" "$dir/probe.h5"
start=$(now)
$sim --resume "$dir/probe.h5" --set "run.t_end=$t_end" || { echo "the extension failed"; exit 1; }
wall_extend=$(since "$start")
stopped_collisions=$(collisions_of "$dir/stopped.h5")
short_collisions=$(collisions_of "$dir/short.h5")

failed=0
for phase in $phases; do
  validated=0 resumed=0 identical=0
  k=0
  while [ "$k" -lt "$runs" ]; do
    k=$((k + 1))
    out="$dir/run.h5"
    rm -f "$out" "$out.checkpoint" "$out.partial" "$out.checkpoint.partial"
    case $phase in
      fresh)
        stop_job "$k" "$wall" "$whole_collisions" $sim "$dir/gas.toml" -o "$out"
        job="$sim --resume $out" ;;
      sigint)
        copy_run "$dir/stopped.h5" "$out"
        job="$sim --resume $out"
        stop_job "$k" "$wall_sigint" "$((whole_collisions - stopped_collisions))" $job ;;
      sigkill)
        stop_job "$((k + 1000))" "$wall" "$whole_collisions" $sim "$dir/gas.toml" -o "$out"
        first=$at
        job="$sim --resume $out"
        [ -f "$out" ] || job="$sim $dir/gas.toml -o $out --force"  # killed before its first dump
        left=$([ "$kill_at" = events ] && echo "$((whole_collisions - first))" || echo "$wall - $first" | bc)
        stop_job "$k" "$left" "$left" $job ;;
      extend)
        copy_run "$dir/short.h5" "$out"
        job="$sim --resume $out --set run.t_end=$t_end"
        stop_job "$k" "$wall_extend" "$((whole_collisions - short_collisions))" $job ;;
      *) echo "unknown phase '$phase' (fresh, sigint, sigkill, extend)"; exit 2 ;;
    esac
    # The job again; a fresh run killed before its first dump left no file
    # (nothing to validate) and starts again.
    [ -f "$out" ] || job="$sim $dir/gas.toml -o $out --force"
    ok_valid=0 ok_resume=0 ok_same=0
    # (time limits: a reader that hangs on a damaged file is a failure too)
    if [ ! -f "$out" ] || timeout 60 $validate "$out" >"$dir/validate.out" 2>&1; then ok_valid=1; fi
    [ "$ok_valid" = 1 ] || cp "$out" "$dir/failed-validate-$phase-$k.h5"
    timeout 120 $job >/dev/null 2>"$dir/again.err" && ok_resume=1
    [ "$ok_resume" = 1 ] || cp "$dir/again.err" "$dir/failed-again-$phase-$k.err"
    h5diff -q "$dir/whole.h5" "$out" >/dev/null 2>&1 && ok_same=1
    [ "$ok_same" = 1 ] || cp "$out" "$dir/failed-differs-$phase-$k.h5"
    validated=$((validated + ok_valid)) resumed=$((resumed + ok_resume)) identical=$((identical + ok_same))
    # Named points always land: one that did not is a failure.
    [ "$kill_at" = time ] || [ "$killed" = 1 ] || ok_same=0
    echo "$phase $k: at $at ($kill_at) killed=$killed validates=$ok_valid again=$ok_resume identical=$ok_same"
  done
  echo "$phase: identical=$identical of $runs (validated=$validated resumed=$resumed)"
  [ "$identical" = "$runs" ] || failed=1
done
exit $failed
