#!/bin/sh
# steady.sh TABLE COLUMN T_FROM [FACTOR [POWER]]
# The mean of FACTOR * COLUMN^POWER (default 1 and 1; COLUMN may be a ratio
# of two columns, A/B) over the rows of a
# coolgas TSV table whose t is at least T_FROM (rows evenly spaced in t, as
# dumps at dump_times are; log-spaced observables would weigh the first
# block's few collision times like the last block's many), and its standard error from 10
# blocks of consecutive rows (the samples of a steady state are correlated
# over a few collision times; block means of ~20 samples each are not):
# prints "MEAN ERROR". Fewer than 20 rows: the error is nan.
set -e
[ $# -ge 3 ] || { echo "usage: steady.sh TABLE COLUMN T_FROM [FACTOR [POWER]]" >&2; exit 2; }
awk -F '\t' -v want="$2" -v from="$3" -v factor="${4:-1}" -v power="${5:-1}" '
  /^#/ || NF == 0 { next }
  !header { split(want, part, "/")
            for (i = 1; i <= NF; i++) { if ($i == part[1]) col = i; if ($i == part[2]) den = i; if ($i == "t") tc = i }
            header = 1
            if (!col || !tc || (part[2] != "" && !den)) { print "steady.sh: no column " want " (or t) in " FILENAME > "/dev/stderr"; bad = 1; exit 2 }
            next }
  $tc + 0 >= from + 0 { x[n++] = factor * (den ? $col / $den : $col) ^ power }
  END {
    if (bad) exit 2
    if (n == 0) { print "steady.sh: no row with t >= " from " in " FILENAME > "/dev/stderr"; exit 2 }
    for (i = 0; i < n; i++) s += x[i]
    m = s / n
    if (n < 20) { printf "%.6g nan\n", m; exit }
    per = int(n / 10)
    for (b = 0; b < 10; b++) { t = 0; for (i = b * per; i < (b + 1) * per; i++) t += x[i]; bm[b] = t / per; bs += bm[b] }
    for (b = 0; b < 10; b++) v += (bm[b] - bs / 10) ^ 2
    printf "%.6g %.6g\n", m, sqrt(v / 9 / 10)
  }' "$1"
