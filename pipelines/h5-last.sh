#!/bin/sh
# h5-last.sh RUN.h5 DATASET
# Prints the last value of a one-dimensional dataset of an HDF5 file, e.g.
#   sh h5-last.sh run.h5 /observables/collisions/value
# (the collisions of a coolgas-simulate run up to t_end). Uses h5dump
# (hdf5-tools). On failure: one line on stderr, exit code 2.
file=$1
dataset=$2
# -y: no "(i):" indices; -w 0: no line wrapping.
if ! dump=$(h5dump -y -w 0 -d "$dataset" "$file" 2>&1); then
  why=$(printf '%s\n' "$dump" | sed -n 's/.*h5dump error: //p' | head -n 1)
  echo "h5-last.sh: cannot read dataset '$dataset' of '$file': ${why:-h5dump failed}" >&2
  exit 2
fi
# The values are the words between "DATA {" and the closing "}".
printf '%s\n' "$dump" | awk -v what="'$dataset' of '$file'" '
  /DATA \{/ { data = 1; next }
  data && /\}/ { exit }
  data { gsub(",", " "); for (i = 1; i <= NF; i++) last = $i }
  END { if (last == "") { print "h5-last.sh: dataset " what " holds no values" > "/dev/stderr"; exit 2 } print last }
'
