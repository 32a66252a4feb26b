#!/bin/sh
# submit-runs.sh — a pipeline's runs on Slurm as one job each, every job
# asking for its own run's time and memory, then the analysis as one job
# (paper.sbatch) once every run has succeeded. From the repository root,
# after `make build`:
#   sh pipelines/cluster/submit-runs.sh                                  # the paper scale
#   MAX_TIME=720 sh pipelines/cluster/submit-runs.sh                     # on a queue of 12 hours at most
#   sh pipelines/cluster/submit-runs.sh SCALE=tiny OUT="$PWD/out/tiny"   # a check in minutes
# Arguments go to make, after the defaults BIN="$PWD/build/bin"
# OUT="$PWD/out/paper" (as in paper.sbatch). Environment:
#   MAX_TIME  the queue's longest job, in minutes: a run asking for more
#             becomes a chain of jobs of MAX_TIME each, every one resuming
#             where the one before stopped (--dependency=afterany)
#   ANALYSIS  sbatch options of the analysis job, e.g. '--ntasks=8 --time=12:00:00'
#             (default: paper.sbatch's own #SBATCH lines)
#   DRY_RUN=1 print the jobs without submitting them (ids dry-NAME-LINK)
# sbatch's own variables (SBATCH_PARTITION, SBATCH_ACCOUNT, ...) apply to
# every job. Prints one line per job: the run (or "analysis"), the job id,
# its sbatch options. Logs go to OUT/slurm/NAME-JOBID.log. After a failure,
# once its jobs have left the queue, run it again: it submits only the runs
# not yet complete (each resumes its .part) and a new analysis job.
#
# One job per run, not a job array: the tasks of an array share one request,
# and a scale's runs differ by orders of magnitude (the paper scale's
# requests go from a minute to about 35 hours: make -C pipelines/paper
# estimate), so an array would book every run for the longest. A job per
# run books what its estimate says, lets the scheduler fit the short ones
# into gaps, and lets a run longer than the queue's limit be a chain.
#
# The request is `coolgas-simulate --estimate`'s (docs/studies.md,
# "Planning a run"): mem_GB per core, hours as whole minutes (at least 1),
# both with the estimate's margin of 1.5. A job of 30 minutes or more gets
# SIGTERM 5 minutes before its end (--signal=TERM@300), so that its run
# writes its checkpoint and exits 3 long before the SIGKILL; Slurm may send
# it up to a minute earlier than asked, so a shorter job gets none (it could
# come before the run's expected end) and relies on the SIGTERM at its limit,
# KillWait seconds (30 by default) before the SIGKILL.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
pipeline=pipelines/paper
set -- BIN="$root/build/bin" OUT="$root/out/paper" "$@"
bin=$root/build/bin
for a in "$@"; do
  case $a in BIN=*) bin=${a#BIN=} ;; esac
done
if [ -n "${MAX_TIME:-}" ]; then
  case $MAX_TIME in
    *[!0-9]* | 0*) echo "submit-runs.sh: MAX_TIME = '$MAX_TIME' is not a whole number of minutes >= 1" >&2; exit 2 ;;
  esac
fi
dry=${DRY_RUN:-0}
tab=$(printf '\t')

# A path make printed, from the repository root (make runs in $pipeline).
from_root() { case $1 in /*) echo "$1" ;; *) echo "$pipeline/$1" ;; esac }

# sbatch ID_IN_A_DRY_RUN OPTIONS...: the job's id.
submit() {
  if [ "$dry" = 1 ]; then
    echo "$1"
  else
    shift
    id=$(sbatch --parsable "$@") || exit 1
    echo "${id%%;*}"
  fi
}

runs=$(make -s -C "$pipeline" "$@" run-list) || exit 1
first_target=$(printf '%s\n' "$runs" | head -n 1 | cut -f2)
logs=$(dirname "$(dirname "$(from_root "$first_target")")")/slurm  # OUT/slurm
[ "$dry" = 1 ] || mkdir -p "$logs"

# The runs not yet complete, each with its request: NAME TARGET MINUTES GB,
# the longest first (so that the queue starts them first).
plan=""
while IFS=$tab read -r name target scene; do
  make -q --no-print-directory -C "$pipeline" "$@" "$target" 2>/dev/null && continue
  estimate=$("$bin/coolgas-simulate" --estimate "$(from_root "$scene")") || exit 1
  plan=$plan$(printf '%s\n' "$estimate" | tail -n 1 | awk -v name="$name" -v target="$target" -F"$tab" '{
    minutes = $4 * 60; minutes = (minutes == int(minutes)) ? minutes : int(minutes) + 1
    printf "%s %s %d %d\n", name, target, (minutes < 1 ? 1 : minutes), $3 }')"
"
done <<EOF
$runs
EOF
plan=$(printf '%s' "$plan" | sort -k3,3nr -k1,1)

# Each run: one job, or a chain of MAX_TIME-long jobs, each after the one before.
last_links=""
while read -r name target minutes gb; do
  [ -n "$name" ] || continue
  links=1 time=$minutes
  if [ -n "${MAX_TIME:-}" ] && [ "$minutes" -gt "$MAX_TIME" ]; then
    links=$(((minutes + MAX_TIME - 1) / MAX_TIME)) time=$MAX_TIME
  fi
  signal=""
  [ "$time" -lt 30 ] || signal=" --signal=TERM@300"
  after=""
  link=1
  while [ "$link" -le "$links" ]; do
    options="--job-name=coolgas-$name --time=$time --mem-per-cpu=${gb}G$signal${after:+ --dependency=afterany:$after}"
    # shellcheck disable=SC2086 # the options are words
    id=$(submit "dry-$name-$link" $options --output="$logs/$name-%j.log" pipelines/cluster/run.sbatch "$@" "$target")
    printf '%s\t%s\t%s\n' "$name" "$id" "$options"
    after=$id
    link=$((link + 1))
  done
  last_links="$last_links:$after"
done <<EOF
$plan
EOF

# The analysis: the whole pipeline, its runs complete by then.
options="--job-name=coolgas-analysis${last_links:+ --dependency=afterok$last_links --kill-on-invalid-dep=yes}${ANALYSIS:+ $ANALYSIS}"
# shellcheck disable=SC2086
id=$(submit dry-analysis $options --output="$logs/analysis-%j.log" pipelines/cluster/paper.sbatch "$@")
printf 'analysis\t%s\t%s\n' "$id" "$options"
