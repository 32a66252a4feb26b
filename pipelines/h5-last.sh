#!/bin/sh
# h5-last.sh RUN.h5 DATASET [T]
# Prints the last value of a one-dimensional dataset of an HDF5 file, e.g.
#   sh h5-last.sh run.h5 /observables/collisions/value
# (the collisions of a coolgas-simulate run up to t_end). With T, DATASET is
# an H5MD observable's value and the value printed is the last one whose
# time (the sibling dataset 'time') is at most T, e.g. the collisions made
# by t = 1000:
#   sh h5-last.sh run.h5 /observables/collisions/value 1000
# Uses h5dump (hdf5-tools). On failure: one line on stderr, exit code 2.
file=$1
dataset=$2
t_max=${3:-}
# The words between "DATA {" and the closing "}" of dataset $1, one a line.
values() {
  # -y: no "(i):" indices; -w 0: no line wrapping.
  if ! dump=$(h5dump -y -w 0 -d "$1" "$file" 2>&1); then
    why=$(printf '%s\n' "$dump" | sed -n 's/.*h5dump error: //p' | head -n 1)
    echo "h5-last.sh: cannot read dataset '$1' of '$file': ${why:-h5dump failed}" >&2
    return 2
  fi
  printf '%s\n' "$dump" | awk '
    /DATA \{/ { data = 1; next }
    data && /\}/ { exit }
    data { gsub(",", " "); for (i = 1; i <= NF; i++) print $i }'
}
if [ -n "$t_max" ] && ! echo "$t_max" | grep -Eq '^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$'; then
  echo "h5-last.sh: the time T = '$t_max' is not a number" >&2
  exit 2
fi
v=$(values "$dataset") || exit 2
if [ -n "$t_max" ]; then
  t=$(values "${dataset%/*}/time") || exit 2
  last=$({ printf '%s\n' "$t"; echo --; printf '%s\n' "$v"; } | awk -v T="$t_max" '
    $0 == "--" { values = 1; next }
    !values { time[++n] = $1; next }
    time[++i] <= T + 0 { last = $1 }
    END { print last }')
  what="at times <= $t_max"
else
  last=$(printf '%s\n' "$v" | tail -n 1)
  what=""
fi
if [ -z "$last" ]; then
  echo "h5-last.sh: dataset '$dataset' of '$file' holds no values${what:+ $what}" >&2
  exit 2
fi
echo "$last"
