#!/bin/sh
# timed-run.sh WALL_FILE COMMAND [ARGS...]
# Runs COMMAND and, if it succeeds, writes its wall time in seconds to WALL_FILE
# (the accuracy pipeline plots it). The pipelines call it as
#   $(LAUNCH) sh timed-run.sh run.wall_s coolgas-simulate ...
# so that on a cluster the time measured is that of the run, not of the queue.
wall_file=$1
shift
start=$(date +%s.%N)
"$@" || exit $?
end=$(date +%s.%N)
echo "$start $end" | awk '{ printf "%.3f\n", $2 - $1 }' > "$wall_file"
