#!/bin/sh
# contact-percolation.sh BIN DIR
# Where contact clusters (coolgas-clusters --definition contact:CUTOFF)
# percolate in the equilibrium hard-sphere gas, the state the paper's runs
# start from: the largest cluster's share of the particles against the
# cutoff at the paper's phi = 0.208, and against phi at the default cutoff
# 1.1, in boxes of side 20, 34 and 68, as a TSV table on stdout. BIN holds
# the programs, DIR takes the runs (elastic, seed 1, 10 dumps at t = 2 ... 20
# after the start's 5 collision times of equilibration; minutes on one core).
# Below the threshold the share falls as the box grows (finite clusters); above
# it, it stays near a constant (one cluster spans the box): the threshold is
# where the sizes' curves cross. Columns:
#   L N phi cutoff  the box, its particles, its phi, the bond length [sigma]
#   dumps           dumps averaged
#   share share_err mean of largest_fraction over the dumps, its standard error
set -e
bin=$1 dir=$2
[ -d "$dir" ] || { echo "usage: contact-percolation.sh BIN DIR (DIR an existing folder for the runs)" >&2; exit 2; }
printf 'L\tN\tphi\tcutoff\tdumps\tshare\tshare_err\n'
printf '# format: coolgas-table 2\n'
printf '# tool: pipelines/contact-percolation.sh\n'
printf '# version: %s\n' "$("$bin/coolgas-clusters" --version | head -n 1)"
printf '# runs: elastic, seed 1, dumps t = 2, 4, ..., 20 (system.equilibrate = 5 before t = 0)\n'

# run L PHI: the equilibrium run's file (made once).
run() {
  out="$dir/eq_L$1_phi$2.h5"
  if [ ! -f "$out" ]; then
    printf '[system]\nL = %s\nphi = %s\nseed = 1\n[run]\nt_end = 20\n[output]\ndumps_per_decade = 1\n%s\n' \
      "$1" "$2" 'dump_times = [2, 4, 6, 8, 10, 12, 14, 16, 18, 20]' > "$dir/eq.toml"
    "$bin/coolgas-simulate" "$dir/eq.toml" --quiet --force -o "$out"
  fi
  echo "$out"
}

# row L PHI CUTOFF: the mean share over the dumps from t = 2 on.
row() {
  file=$(run "$1" "$2")
  "$bin/coolgas-clusters" "$file" --series --definition "contact:$3" --time 2,4,6,8,10,12,14,16,18,20 2> /dev/null |
    awk -v L="$1" -v phi="$2" -v c="$3" -F '\t' '
      NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
      /^#/ { if ($0 ~ /^# N: /) N = substr($0, 6); next }
      { f = $col["largest_fraction"]; s += f; s2 += f * f; n++ }
      END { m = s / n; v = n > 1 ? (s2 - n * m * m) / (n - 1) : 0; if (v < 0) v = 0
            printf "%s\t%s\t%s\t%s\t%d\t%.6g\t%.3g\n", L, N, phi, c, n, m, sqrt(v / n) }'
}

for L in 20 34 68; do
  for c in 1.10 1.12 1.14 1.16 1.17 1.18 1.185 1.19 1.195 1.20 1.22; do row "$L" 0.208 "$c"; done
done
for L in 20 34 68; do
  for phi in 0.22 0.24 0.26 0.27 0.28 0.285 0.29 0.295 0.30 0.32; do row "$L" "$phi" 1.1; done
done
