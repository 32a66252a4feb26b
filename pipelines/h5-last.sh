#!/bin/sh
# h5-last.sh RUN.h5 DATASET
# Prints the last value of a one-dimensional dataset of an HDF5 file, e.g.
#   sh h5-last.sh run.h5 /observables/collisions/value
# (the collisions of a coolgas-simulate run at t_end). Uses h5dump (hdf5-tools).
file=$1
dataset=$2
# -y: no "(i):" indices; -w 0: no line wrapping. The values are the words
# between "DATA {" and the closing "}".
h5dump -y -w 0 -d "$dataset" "$file" | awk -v what="$dataset in $file" '
  /DATA \{/ { data = 1; next }
  data && /\}/ { exit }
  data { gsub(",", " "); for (i = 1; i <= NF; i++) last = $i }
  END { if (last == "") { print "h5-last.sh: no values of " what > "/dev/stderr"; exit 2 } print last }
'
