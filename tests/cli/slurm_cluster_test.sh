#!/bin/sh
# The cluster templates of pipelines/cluster/ under a real Slurm: a one-node
# cluster from Debian's packages started in SCRATCH (tests/support/slurm_cluster.sh),
# four checks at once inside it, the cluster stopped at the end whatever happens.
# - time limit: paper.sbatch at SCALE=tiny with --time=1, its runs held at a
#   fault point (COOLGAS_FAULT=...:WAIT) so that none can finish first: the
#   job reaches its limit (TIMEOUT), the runs held then get SIGTERM, write
#   their checkpoints and exit 3; paper.sbatch submitted again
#   (--dependency=afterany) resumes them and makes the rest. Its runs are
#   the pipeline's without Slurm bit for bit (h5diff), its exponents.tsv the
#   same apart from provenance: each run an srun step, the same result.
# - killed step: one run held at a fault point after its checkpoints, its
#   step killed (scancel --signal=KILL); the next submission resumes the same
#   file (the same inode: appended, not begun again) to the run without
#   Slurm's, bit for bit.
# - per-run jobs: submit-runs.sh submits each run as its own job asking for
#   its estimate's time and memory (as scontrol shows them), then the
#   analysis after them all: the same runs and exponents as without Slurm.
# - chains (no cluster needed): a dry run of submit-runs.sh with MAX_TIME
#   makes a run longer than the queue's limit a chain of jobs, each after the
#   one before (afterany), and asks for every run what its estimate says.
# Where the cluster cannot start (not root, packages missing, a daemon
# failing) the test prints the reason and exits 77, which ctest counts as
# skipped. Prints each check's wall time.
#
# usage: tests/cli/slurm_cluster_test.sh BUILD_DIR SCRATCH_DIR
set -u
build=${1:?usage: slurm_cluster_test.sh BUILD_DIR SCRATCH_DIR}
scratch=${2:?usage: slurm_cluster_test.sh BUILD_DIR SCRATCH_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=$build/bin
. "$root/tests/support/slurm_cluster.sh"
# The faults below are set for one job each; none comes from outside.
unset COOLGAS_FAULT COOLGAS_CHECKPOINT_INTERVAL
skip() { echo "SKIP: $*"; exit 77; }
rm -rf "$scratch"
mkdir -p "$scratch"
started=$(date +%s)

trap slurm_cluster_stop EXIT
trap 'exit 1' INT TERM HUP
slurm_cluster_start "$scratch/cluster" || skip "no Slurm cluster: $slurm_cluster_why"
echo "cluster up in $(($(date +%s) - started)) s (its files: $slurm_cluster_dir)"

# The fault that holds a run once its process has made this many events
# (early in a tiny run); a run with fewer simply finishes, as without it.
hold=events:1000:WAIT
tiny="SCALE=tiny BIN=$bin"
# sbatch [VARIABLE=VALUE...] OPTIONS... from the repository root, as the
# templates expect; the variables go into the job's environment only.
submit() {
  (
    cd "$root" || exit 1
    while case $1 in -*) false ;; *=*) true ;; *) false ;; esac do
      export "${1?}"
      shift
    done
    sbatch --parsable "$@"
  )
}

# check NAME: runs the function NAME in the background, its output in
# SCRATCH/NAME.log and its verdict ("ok" or the failure) in SCRATCH/NAME.verdict.
# (Their ids are kept: a bare `wait` would wait for the daemons too.)
checks=""
check() {
  (
    start=$(date +%s)
    if ("$1") >"$scratch/$1.log" 2>&1; then verdict=ok; else verdict="FAILED: $(tail -n 1 "$scratch/$1.log")"; fi
    echo "$verdict ($(($(date +%s) - start)) s)" >"$scratch/$1.verdict"
  ) &
  checks="$checks $!"
}
fail() { echo "$*"; exit 1; }

# The same tiny pipeline without Slurm, the reference.
reference() {
  make -s -C "$root/pipelines/paper" -j2 $tiny OUT="$scratch/reference" >"$scratch/reference.make.log" 2>&1 ||
    fail "the pipeline without Slurm failed: $(tail -n 3 "$scratch/reference.make.log")"
  echo "the tiny pipeline without Slurm, made"
}

# OUT's exponents (provenance dropped) and runs are the reference's, bit for bit.
same_as_reference() {
  slurm_cluster_until 300 test -f "$scratch/reference.verdict" || fail "no reference after 300 s"
  grep -q '^ok' "$scratch/reference.verdict" || fail "no reference: $(cat "$scratch/reference.verdict")"
  grep -v '^#' "$scratch/reference/exponents.tsv" >"$1/expected.tsv"
  grep -v '^#' "$1/exponents.tsv" >"$1/measured.tsv" || fail "$1: no exponents.tsv"
  diff "$1/expected.tsv" "$1/measured.tsv" || fail "$1: exponents.tsv differs from the run without Slurm"
  runs=0
  for f in "$scratch"/reference/runs/*.h5; do
    h5diff "$f" "$1/runs/${f##*/}" || fail "$1/runs/${f##*/} differs from the run without Slurm"
    runs=$((runs + 1))
  done
  [ "$runs" -ge 12 ] || fail "only $runs runs in the reference"
  echo "$runs runs bit for bit and exponents.tsv as without Slurm"
}

time_limit() {
  out=$scratch/time_limit
  mkdir -p "$out"
  first=$(submit COOLGAS_FAULT=$hold --time=1 --ntasks=2 --mem-per-cpu=512M --output="$out/first.log" \
    pipelines/cluster/paper.sbatch $tiny OUT="$out") || fail "sbatch refused the first job"
  # Held (--hold) until the first job's stopped runs are listed below: once
  # released it starts as soon as the first has ended (afterany), and would
  # otherwise resume them while they are being looked at.
  again=$(submit --hold --dependency=afterany:"$first" --time=30 --ntasks=2 --mem-per-cpu=512M \
    --output="$out/again.log" pipelines/cluster/paper.sbatch $tiny OUT="$out") || fail "sbatch refused the second job"
  state=$(slurm_cluster_wait_job "$first" 240)
  [ "$state" = TIMEOUT ] || fail "the held job ended $state, not TIMEOUT: $(tail -n 3 "$out/first.log")"
  # After the limit's line, the held runs' own: SIGTERM handled, checkpoint written.
  sed -n '/CANCELLED AT .* DUE TO TIME LIMIT/,$p' "$out/first.log" | grep -q 'interrupted by SIGTERM.*checkpoint written' ||
    fail "no run wrote its checkpoint on the time limit's SIGTERM: $(tail -n 5 "$out/first.log")"
  held=$(grep -c 'fault: holding' "$out/first.log")
  stopped=$(grep -c 'interrupted by SIGTERM.*checkpoint written' "$out/first.log")
  ran=$(scontrol show job "$first" | sed -n 's/.*RunTime=\([^ ]*\).*/\1/p')
  echo "first job: TIMEOUT after $ran (--time=1); $held runs held, $stopped stopped by SIGTERM with a checkpoint"
  # The runs it stopped, each a .part with its checkpoint, and the file's inode.
  for part in "$out"/runs/*.h5.part; do
    [ -f "$part.checkpoint" ] || fail "${part##*/} has no checkpoint" >&2
    echo "${part%.part} $(stat -c %i "$part")"
  done >"$out/stopped.txt" || exit 1
  [ -s "$out/stopped.txt" ] || fail "the first job left no stopped run"
  scontrol release "$again" || fail "scontrol release $again failed"
  state=$(slurm_cluster_wait_job "$again" 300)
  [ "$state" = COMPLETED ] || fail "the second job ended $state: $(tail -n 3 "$out/again.log")"
  while read -r run inode; do
    [ "$(stat -c %i "$run")" = "$inode" ] || fail "${run##*/} was begun again, not resumed (a new file)"
  done <"$out/stopped.txt"
  echo "second job: $(wc -l <"$out/stopped.txt") stopped runs resumed in their files, the rest made"
  same_as_reference "$out"
}

killed_step() {
  out=$scratch/killed_step
  run=$out/runs/size_L12_s1.h5
  mkdir -p "$out"
  # A checkpoint at every stop of the output grid, so the last one is near the point held.
  first=$(submit COOLGAS_FAULT=$hold COOLGAS_CHECKPOINT_INTERVAL=0 --time=30 --ntasks=1 --mem-per-cpu=512M \
    --output="$out/first.log" pipelines/cluster/paper.sbatch $tiny OUT="$out" "$run") || fail "sbatch refused the first job"
  slurm_cluster_until 120 grep -qs 'fault: holding' "$out/first.log" || fail "the run was not held: $(tail -n 3 "$out/first.log")"
  [ -f "$run.part.checkpoint" ] || fail "no checkpoint beside the held run"
  inode=$(stat -c %i "$run.part")
  step=$(squeue -h -s -j "$first" -o %i | grep -v batch | head -n 1)
  [ -n "$step" ] || fail "no step of job $first"
  scancel --signal=KILL "$step" || fail "scancel --signal=KILL $step failed"
  state=$(slurm_cluster_wait_job "$first" 120)
  [ "$state" = FAILED ] || fail "the job of the killed step ended $state, not FAILED"
  grep -q 'task 0: Killed' "$out/first.log" || fail "the step was not killed: $(tail -n 3 "$out/first.log")"
  [ -f "$run.part" ] && [ ! -f "$run" ] || fail "the killed run left no $run.part"
  again=$(submit --time=30 --ntasks=1 --mem-per-cpu=512M --output="$out/again.log" \
    pipelines/cluster/paper.sbatch $tiny OUT="$out" "$run") || fail "sbatch refused the second job"
  state=$(slurm_cluster_wait_job "$again" 120)
  [ "$state" = COMPLETED ] || fail "the resubmission ended $state: $(tail -n 3 "$out/again.log")"
  [ "$(stat -c %i "$run")" = "$inode" ] || fail "the run was begun again, not resumed (a new file)"
  slurm_cluster_until 300 test -f "$scratch/reference.verdict" || fail "no reference after 300 s"
  h5diff "$scratch/reference/runs/${run##*/}" "$run" || fail "the resumed run differs from the run without Slurm"
  echo "step $step killed (SIGKILL) while held; resumed into the same file, bit for bit as without Slurm"
}

# The estimate's request of a run: "MINUTES GB" (hours as whole minutes, at least 1).
request() {
  "$bin/coolgas-simulate" --estimate "$1" | awk -F'\t' 'NR == 2 {
    m = $4 * 60; m = (m == int(m)) ? m : int(m) + 1; print (m < 1 ? 1 : m), $3 }'
}

per_run() {
  out=$scratch/per_run
  mkdir -p "$out"
  ANALYSIS='--ntasks=2 --mem-per-cpu=512M --time=30' sh "$root/pipelines/cluster/submit-runs.sh" $tiny OUT="$out" \
    >"$out/jobs.tsv" || fail "submit-runs.sh failed"
  jobs=0
  while IFS="$(printf '\t')" read -r name id options; do
    [ "$name" != analysis ] || { analysis=$id; continue; }
    set -- $(request "$out/scenes/$name.toml")
    info=$(scontrol show job "$id")
    echo "$info" | grep -q "TimeLimit=$(printf '%02d:%02d:00' $(($1 / 60)) $(($1 % 60))) " || fail "$name: not the estimate's $1 minutes: $(echo "$info" | grep -o 'TimeLimit=[^ ]*')"
    echo "$info" | grep -q "MinMemoryCPU=$2G " || fail "$name: not the estimate's $2 GB: $(echo "$info" | grep -o 'MinMemoryCPU=[^ ]*')"
    jobs=$((jobs + 1))
  done <"$out/jobs.tsv"
  [ "$jobs" -ge 12 ] || fail "only $jobs run jobs submitted"
  state=$(slurm_cluster_wait_job "$analysis" 300)
  [ "$state" = COMPLETED ] || fail "the analysis job ended $state: $(tail -n 3 "$out"/slurm/analysis-*.log)"
  while IFS="$(printf '\t')" read -r name id options; do
    state=$(slurm_cluster_job_state "$id")
    [ "$state" = COMPLETED ] || fail "the job of $name ended $state"
  done <"$out/jobs.tsv"
  echo "$jobs runs, one job each with the estimate's --time and --mem-per-cpu, then the analysis"
  same_as_reference "$out"
}

chains() {
  out=$scratch/chains
  # Not a number of minutes: refused in one line before anything is done.
  MAX_TIME=12h sh "$root/pipelines/cluster/submit-runs.sh" $tiny OUT="$out" >"$out.refused" 2>&1 && fail "MAX_TIME=12h accepted"
  [ "$(wc -l <"$out.refused")" -eq 1 ] && grep -q "MAX_TIME = '12h' is not a whole number of minutes" "$out.refused" ||
    fail "MAX_TIME=12h: $(cat "$out.refused")"
  # The snapshot run at the paper's size and length, beside the tiny ones.
  DRY_RUN=1 MAX_TIME=720 sh "$root/pipelines/cluster/submit-runs.sh" $tiny OUT="$out" SNAP_L=272 SNAP_T_END=1e6 \
    >"$out.tsv" || fail "the dry run failed"
  tab=$(printf '\t')
  lasts=""
  for scene in "$out"/scenes/*.toml; do
    name=${scene##*/}
    name=${name%.toml}
    set -- $(request "$scene")
    links=$((($1 + 719) / 720)) time=$1 signal=""
    [ "$links" -eq 1 ] || time=720
    [ "$time" -lt 30 ] || signal=" --signal=TERM@300"
    expected="" after=""
    link=1
    while [ "$link" -le "$links" ]; do
      expected="$expected$name${tab}dry-$name-$link$tab--job-name=coolgas-$name --time=$time --mem-per-cpu=$2G$signal${after:+ --dependency=afterany:$after}
"
      after=dry-$name-$link link=$((link + 1))
    done
    [ "$(grep "^$name$tab" "$out.tsv")" = "$(printf '%s' "$expected")" ] ||
      fail "$name: planned $(grep "^$name$tab" "$out.tsv" | tr '\n' ' '); expected $expected"
    [ "$name" != snap_s1 ] || [ "$links" -ge 2 ] || fail "the snapshot run at L = 272 asks for $1 minutes, no chain"
    lasts="$lasts:$after"
  done
  grep -q "^analysis${tab}dry-analysis$tab--job-name=coolgas-analysis --dependency=afterok" "$out.tsv" ||
    fail "no analysis job after the runs: $(tail -n 1 "$out.tsv")"
  for l in $(echo "$lasts" | tr ':' ' '); do
    grep "^analysis" "$out.tsv" | grep -q -- ":$l[: ]" || fail "the analysis does not wait for $l"
  done
  echo "chains and requests as the estimates say: $(grep -c "^snap_s1$tab" "$out.tsv") jobs for the snapshot run at L = 272"
}

check reference
check time_limit
check killed_step
check per_run
check chains
for pid in $checks; do wait "$pid"; done
status=0
for name in reference time_limit killed_step per_run chains; do
  verdict=$(cat "$scratch/$name.verdict" 2>/dev/null || echo "FAILED: no verdict")
  echo "$name: $verdict"
  case $verdict in
    ok*) grep . "$scratch/$name.log" | sed 's/^/  /' ;;
    *) status=1; tail -n 20 "$scratch/$name.log" | sed 's/^/  /' ;;
  esac
done
echo "all checks in $(($(date +%s) - started)) s"
exit "$status"
