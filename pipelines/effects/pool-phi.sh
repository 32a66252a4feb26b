#!/bin/sh
# pool-phi.sh < PHI_TABLE
# Phi(y) of a steady state: the blocks of a `coolgas-velocity` table (one
# per dump, columns t y Phi Phi_err minus_ln_Phi) pooled bin by bin into one
# TSV table with columns y, Phi (the mean over the dumps), Phi_err (its
# standard error from the dumps' scatter, or the Poisson error when one dump
# has the bin) and dumps (how many dumps have the bin). The provenance
# lines pass through; a line "# pooled: N dumps" is added.
set -e
awk -F '\t' '
  BEGIN { printf "y\tPhi\tPhi_err\tdumps\n" }
  /^# t = / { blocks++; next }
  /^#/ { meta[++m] = $0; next }
  $1 == "t" { next }
  NF >= 4 {
    y = $2; if (!(y in n)) order[++k] = y
    n[y]++; s[y] += $3; q[y] += $3 * $3; poisson[y] = $4
  }
  END {
    for (i = 1; i <= m; i++) print meta[i]
    printf "# pooled: %d dumps\n", blocks
    for (i = 1; i <= k; i++) {
      y = order[i]; mean = s[y] / blocks
      err = n[y] > 1 ? sqrt((q[y] / blocks - mean * mean) / (blocks - 1)) : poisson[y] / blocks
      printf "%s\t%.6g\t%.3g\t%d\n", y, mean, err, n[y]
    }
  }'
