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
wall_file=$1
shift
case $wall_file in
  *.wall_s) cpu_file=${wall_file%.wall_s}.cpu_s ;;
  *) cpu_file=$wall_file.cpu_s ;;
esac
start=$(date +%s.%N)
"$@" || exit $?
end=$(date +%s.%N)
echo "$start $end" | awk '{ printf "%.3f\n", $2 - $1 }' > "$wall_file"
# The second line of `times` holds the children's user and system time, each
# as MINUTESmSECONDSs. (`times` runs in this shell, not in a pipe: a subshell
# has no children's time yet.)
times > "$cpu_file"
awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, p, "m"); s += p[1] * 60 + p[2] } printf "%.2f\n", s }' \
  "$cpu_file" > "$cpu_file.tmp" && mv "$cpu_file.tmp" "$cpu_file"
