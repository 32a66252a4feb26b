#!/bin/sh
# estimate.sh L T_END [PHI] — memory and wall time of one coolgas-simulate run,
# for a scheduler's request (pipelines/cluster/paper.sbatch).
#   N        = PHI L^3 / (pi/6)
#   memory   = 180 bytes per particle (the measured peak at N = 8e6: README,
#              Performance) times 1.5, plus 256 MB, rounded up to whole GB
#   time     = collisions / rate, with collisions per particle 138 (t/1000)^0.57
#              (the worked example's gas, L = 34: 37 at t = 100, 138 at t = 1000;
#              later the finite-size regime grows them more slowly, so this is an
#              upper bound) and 3e5 collisions per second (README: 5e5 at
#              N = 1e5; large N run slower from cache misses), times 1.5
# Prints: L N mem_GB time_hours (one line, tab-separated).
set -e
L=$1 t_end=$2 phi=${3:-0.208}
awk -v L="$L" -v t="$t_end" -v phi="$phi" 'BEGIN {
  N = phi * L * L * L / (3.141592653589793 / 6)
  mem = int((1.5 * 180 * N + 256e6) / 1e9) + 1
  per_particle = 138 * (t / 1000) ^ 0.57
  hours = 1.5 * N * per_particle / 3e5 / 3600
  printf "%s\t%.0f\t%d\t%.2f\n", L, N, mem, hours
}'
