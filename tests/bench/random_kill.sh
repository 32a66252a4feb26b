#!/bin/sh
# Crash safety and exact resume under SIGKILL at random moments (not a unit
# test: it takes minutes). Runs a small scene once uninterrupted, then RUNS
# times: starts it, kills it with SIGKILL after a random delay within the
# uninterrupted run's wall time, checks the file with coolgas-validate,
# resumes it with --resume to the end (a run killed before its first dump
# left no file and is started again, as a user would) and compares the whole
# file with the uninterrupted one (h5diff: every dataset and attribute).
# Prints one line per run (a failing file or message is kept in the scratch
# folder as failed-*) and a summary:
#   killed=K validated=V resumed=R identical=I of RUNS
#
# usage: tests/bench/random_kill.sh BUILD_DIR [RUNS] [SCRATCH_DIR]
#   e.g. tests/bench/random_kill.sh build 200 /tmp/kill
# Environment: COOLGAS_CHECKPOINT_INTERVAL (default here 0.2 s, so kills land
# between mid-run checkpoints as well as before the first one).
set -u
build=${1:?usage: random_kill.sh BUILD_DIR [RUNS] [SCRATCH_DIR]}
runs=${2:-200}
dir=${3:-$(mktemp -d)}
sim="$build/bin/coolgas-simulate -q"
validate="$build/bin/coolgas-validate"
export COOLGAS_CHECKPOINT_INTERVAL=${COOLGAS_CHECKPOINT_INTERVAL:-0.2}
mkdir -p "$dir"
cat > "$dir/gas.toml" <<'SCENE'
[system]
N = 3000
phi = 0.208
seed = 5
equilibrate = 1
[collision]
model = "inelastic"
r0 = 0.1
delta = 1e-4
[run]
t_end = 300
[output]
dumps_per_decade = 10
SCENE

start=$(date +%s.%N)
$sim "$dir/gas.toml" -o "$dir/whole.h5" --force || { echo "the uninterrupted run failed"; exit 1; }
wall=$(echo "$(date +%s.%N) - $start" | bc)
echo "uninterrupted run: ${wall}s"

killed=0 validated=0 resumed=0 identical=0
k=0
while [ "$k" -lt "$runs" ]; do
  k=$((k + 1))
  out="$dir/run.h5"
  rm -f "$out" "$out.checkpoint" "$out.partial" "$out.checkpoint.partial"
  delay=$(awk -v seed="$k" -v w="$wall" 'BEGIN { srand(seed); printf "%.3f", 0.9 * rand() * w }')
  $sim "$dir/gas.toml" -o "$out" & pid=$!
  sleep "$delay"
  kill -KILL "$pid" 2>/dev/null && killed=$((killed + 1))
  wait "$pid" 2>/dev/null
  if [ ! -f "$out" ]; then  # killed during set-up: nothing to resume, start again
    note="no file yet"
    $sim "$dir/gas.toml" -o "$out" --force
  else
    note="resumed"
  fi
  ok_valid=0 ok_resume=0 ok_same=0
  # (time limits: a reader that hangs on a damaged file is a failure too)
  timeout 60 $validate "$out" >"$dir/validate.out" 2>&1 && ok_valid=1
  [ "$ok_valid" = 1 ] || cp "$out" "$dir/failed-validate-$k.h5"
  timeout 120 $sim --resume "$out" >/dev/null 2>"$dir/resume.err" && ok_resume=1
  [ "$ok_resume" = 1 ] || cp "$dir/resume.err" "$dir/failed-resume-$k.err"
  h5diff -q "$dir/whole.h5" "$out" >/dev/null 2>&1 && ok_same=1
  validated=$((validated + ok_valid)) resumed=$((resumed + ok_resume)) identical=$((identical + ok_same))
  echo "run $k: kill after ${delay}s, $note: validates=$ok_valid resumes=$ok_resume identical=$ok_same"
done
echo "killed=$killed validated=$validated resumed=$resumed identical=$identical of $runs"
