#!/bin/sh
# timed-run.sh WALL_FILE COMMAND [ARGS...]
# Runs COMMAND and, if it succeeds, writes its wall time in seconds to WALL_FILE
# (the accuracy pipeline plots it). The pipelines call it as
#   $(LAUNCH) sh timed-run.sh run.wall_s coolgas-simulate ...
# so that on a cluster the time measured is that of the run, not of the queue.
# Its CPU time (user + system of COMMAND and the processes it waited for, from
# the shell's `times`; 0.01 s resolution) goes beside it, in run.cpu_s for a
# WALL_FILE run.wall_s (else WALL_FILE.cpu_s): on a shared machine wall time
# depends on the load, CPU time much less.
# A run made in slices (stopped by a signal or a failure, continued by the
# next make with --resume) costs the CPU time of all of them: each slice's
# is appended to run.cpu_s.slices whatever its outcome (SIGINT, SIGTERM and
# SIGHUP are caught so that the slice is counted once the command, which
# gets them too, has stopped; only SIGKILL loses a slice's time), and on
# success run.cpu_s is their sum (the file is then removed). The wall time
# is that of the last slice.
wall_file=$1
shift
case $wall_file in
  *.wall_s) cpu_file=${wall_file%.wall_s}.cpu_s ;;
  *) cpu_file=$wall_file.cpu_s ;;
esac
slices=$cpu_file.slices
# Caught, these do nothing: the shell runs a trap only once the command it
# waits for has ended, whose exit code is kept, and then counts the slice.
trap ':' INT TERM HUP
start=$(date +%s.%N)
rc=0
"$@" || rc=$?
end=$(date +%s.%N)
# The second line of `times` holds the children's user and system time, each
# as MINUTESmSECONDSs. (`times` runs in this shell, not in a pipe: a subshell
# has no children's time yet.)
times > "$cpu_file.times"
awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, p, "m"); s += p[1] * 60 + p[2] } printf "%.2f\n", s }' \
  "$cpu_file.times" >> "$slices"
rm -f "$cpu_file.times"
[ "$rc" -eq 0 ] || exit "$rc"
echo "$start $end" | awk '{ printf "%.3f\n", $2 - $1 }' > "$wall_file"
awk '{ s += $1 } END { printf "%.2f\n", s }' "$slices" > "$cpu_file.tmp" && mv "$cpu_file.tmp" "$cpu_file"
rm -f "$slices"
