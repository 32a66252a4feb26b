#!/bin/sh
# estimate.sh L T_END [PHI [R0 [DELTA [DUMPS_PER_DECADE [DUMP_TIMES]]]]]
# Memory, time and disk of one coolgas-simulate run of the paper's gas
# (r0 = 0.1, delta = 1e-4 unless given; R0 = aggregation: ballistic
# aggregation), for a scheduler's request (pipelines/cluster/paper.sbatch)
# and the paper scale's plan (make -C pipelines/paper estimate).
# DUMP_TIMES: the scene's output.dump_times, comma-separated ("" for none).
# Prints: L N mem_GB hours dumps disk_GB peak_GB cpu_h (one line,
# tab-separated): mem_GB and hours with the margin of a request, peak_GB and
# cpu_h (the expected CPU hours of the run) without.
#
# Every figure comes from a measurement on this project's machine:
#   N        = PHI L^3 / (pi/6)
#   memory   = 180 bytes per particle (gas) or 187 (aggregation), the measured
#              peaks at N = 8e6 and 1e6 (tests/bench/README.md), times 1.5,
#              plus 256 MB, rounded up to whole GB
#   dumps    = t = 0, the grid 10^(k/DUMPS_PER_DECADE) from t = 0.01 below
#              T_END, DUMP_TIMES off that grid, and T_END (simulate/run/time_grid.cc)
#   disk     = dumps x N x 47 bytes (gas: the largest measured compressed
#              dump, late clustered, L = 34 at t = 1e5; 45.5 at L = 68,
#              t = 3e5; 42 for a homogeneous one at N = 1e6) or x 62
#              (aggregation: id, mass and diameter added, not measured
#              compressed: counted at 47 + 20 x 42/61 for their raw 20 bytes)
#   time     = collisions / rate x 1.5 (the margin of a request), with
#     collisions per particle C(t, L) of the paper's gas measured in the
#     runs size_L34_s1 and size_L68_s1 of SCALE = demo's scenes at t_end =
#     1e5 and 3e5 (observables/collisions_per_particle, read at quarter
#     decades; table below). The rule for the other boxes: C is the same for
#     every L >= 68 up to t = 3162 (x = t/L^(5/2) = 0.083 at L = 68, before its
#     finite-size crossover); later its local slope d ln C / d ln t is the
#     one the L = 68 run had at the same x (at the time t (68/L)^(5/2)), or
#     0.606 (its slope over t = 100-3162, before the crossover) while that
#     time is before 3162. Checked on the measured pair, the same rule from
#     L = 34 (same L-independent C to t = 562, slope 0.530 before) gives C at
#     L = 68 between 23 % low (t = 3162) and 30 % high (t = 3e4 - 1e5).
#     Other phi, r0, delta: C times the ratio C_set / C_gas measured at
#     L = 34, t = 1e4 (runs of the same scene with that one value changed;
#     table below), 1 with a note on stderr for a set not measured. Rate,
#     per CPU second on the shared machine (other jobs on both cores), of
#     whole runs of the workstation's Fig. 1 scene (set-up and dumps
#     included; user + system time of pipelines/timed-run.sh's NAME.cpu_s,
#     niced): 6.61e5 collisions for N <= 1.3e5 (L = 68 to t = 1e4: 3.497e7
#     collisions in 52.9 s) and 4.07e5 for larger N (L = 136, N = 999 267,
#     to t = 1e3: 7.815e7 collisions in 192.0 s), taken for N = 8e6 too, not
#     measured. The same runs check the collision counts: 559.9 and 156.4
#     per particle, the table's 559.9 and 153.7 (+1.8 %). (The rates stated
#     here before, 3.63e5 and 1.88e5, from an older build under other load,
#     were 1.8 and 2.2 times too slow: they planned 1 872 CPU-s for a
#     workstation run at L = 100 to t = 1e5 that took 672 and 696; these
#     rates plan 865.)
#     Set-up: 5 equilibration collisions per particle.
#     Aggregation: at most N - 1 merges (a bound), at the merge rate and
#     with the set-up time per particle of W3b (build/bench/aggregation_bench
#     at N = 8e6 to t = 1e5, tests/bench/README.md, wall times within 11 %
#     of CPU): 35 971 merges per second and 153.2 s of set-up at phi =
#     0.208; 12 813 and 688.5 s at phi = 0.005 (its dilute equilibration);
#     for the phi between, both interpolated in log phi, and the set-up
#     scaled with N.
set -e
L=$1 t_end=$2 phi=${3:-0.208} r0=${4:-0.1} delta=${5:-1e-4} per_decade=${6:-1} dump_times=${7:-}
awk -v L="$L" -v t="$t_end" -v phi="$phi" -v r0="$r0" -v delta="$delta" -v per_decade="$per_decade" \
    -v dump_times="$dump_times" '
function interp(tt, n, T, C,   i, f) {  # log-log interpolation in a table
  if (tt <= T[1]) return C[1]
  for (i = 2; i <= n; i++)
    if (tt <= T[i]) { f = log(tt / T[i-1]) / log(T[i] / T[i-1]); return exp(log(C[i-1]) + f * log(C[i] / C[i-1])) }
  return C[n]
}
function slope68(tt,   i) {  # local slope of the L = 68 curve at time tt
  for (i = 2; i <= n68; i++) if (tt <= T68[i]) return log(C68[i] / C68[i-1]) / log(T68[i] / T68[i-1])
  return log(C68[n68] / C68[n68-1]) / log(T68[n68] / T68[n68-1])
}
# C(t, L) of the paper gas by the rule above, integrated over quarter decades.
function collisions(tt, LL,   c, a, b, mid) {
  if (LL < 68) return interp(tt, n34, T34, C34)
  if (tt <= t_same) return interp(tt, n68, T68, C68)
  c = interp(t_same, n68, T68, C68)
  for (a = t_same; a < tt; a = b) {
    b = a * 10 ^ 0.25; if (b > tt) b = tt
    mid = sqrt(a * b) * (68 / LL) ^ 2.5
    c *= (b / a) ^ (mid > t_same ? slope68(mid) : s0)
  }
  return c
}
function add(T, C, n, row,   p) { split(row, p, " "); T[n] = p[1]; C[n] = p[2] }
BEGIN {
  pi = 3.141592653589793
  # collisions per particle, size_L34_s1 and size_L68_s1 (demo scenes)
  n34 = split("1 1.0,10 8.5,100 37.1,316.2 67.0,1000 138.3,1778 241.0,3162 381.8,5623 456.9,1e4 530.3,1.778e4 595.5,3.162e4 662.6,5.623e4 712.5,1e5 745.5", r34, ",")
  for (i = 1; i <= n34; i++) add(T34, C34, i, r34[i])
  n68 = split("1 1.1,10 8.5,100 37.1,316.2 73.8,1000 153.7,1778 220.4,3162 301.2,5623 413.9,1e4 559.9,1.778e4 725.5,3.162e4 874.9,5.623e4 1052.1,1e5 1143.6,1.778e5 1213.3,3e5 1271.5", r68, ",")
  for (i = 1; i <= n68; i++) add(T68, C68, i, r68[i])
  t_same = 3162; s0 = 0.606
  # C_set / C_gas at L = 34, t = 1e4 (keys: phi r0 delta)
  ratio["0.208 0.1 1e-4"] = 1  # C = 530.3 at t = 1e4
  ratio["0.052 0.1 1e-4"] = 0.093  # C = 49.08 at t = 1e4
  ratio["0.104 0.1 1e-4"] = 0.233  # C = 123.3 at t = 1e4
  ratio["0.156 0.1 1e-4"] = 0.675  # C = 358.2 at t = 1e4
  ratio["0.208 0.3 1e-4"] = 0.372  # C = 197.4 at t = 1e4
  ratio["0.208 0.5 1e-4"] = 0.272  # C = 144.1 at t = 1e4
  ratio["0.208 0.7 1e-4"] = 0.237  # C = 125.6 at t = 1e4
  ratio["0.208 0.9 1e-4"] = 0.364  # C = 193.2 at t = 1e4
  ratio["0.208 0.1 1e-3"] = 0.388  # C = 205.8 at t = 1e4
  ratio["0.208 0.1 1e-5"] = 2.288  # C = 1213.1 at t = 1e4
  rate_small = 6.61e5; rate_large = 4.07e5  # collisions per CPU second

  N = phi * L * L * L / (pi / 6)
  ba = (r0 == "aggregation")
  # dumps: t = 0, the log grid below t_end, dump_times off the grid, t_end
  dumps = 2
  for (k = int(-2 * per_decade) - 1; 10 ^ (k / per_decade) < t * (1 - 1e-12); k++)
    if (10 ^ (k / per_decade) >= 0.01 * (1 - 1e-12)) { dumps++; grid[sprintf("%.6g", 10 ^ (k / per_decade))] = 1 }
  m = split(dump_times, extra, ",")
  for (i = 1; i <= m; i++) if (extra[i] + 0 > 0 && extra[i] + 0 < t && !(sprintf("%.6g", extra[i] + 0) in grid)) dumps++

  if (ba) {
    peak = 187 * N
    f = (log(phi) - log(0.005)) / (log(0.208) - log(0.005))  # between the two phi of W3b
    seconds = N / exp(log(12813) + f * log(35971 / 12813)) + N / 8e6 * exp(log(688.5) + f * log(153.2 / 688.5))
    bytes = 62
  } else {
    peak = 180 * N
    key = phi " " r0 " " delta
    if (!(key in ratio)) { printf "estimate.sh: no measured collision ratio for phi %s, r0 %s, delta %s: taken as 1\n", phi, r0, delta > "/dev/stderr"; ratio[key] = 1 }
    per_particle = ratio[key] * collisions(t, L) + 5
    seconds = N * per_particle / 2 / (N <= 1.3e5 ? rate_small : rate_large)
    bytes = 47
  }
  mem = int((1.5 * peak + 256e6) / 1e9) + 1
  printf "%s\t%.0f\t%d\t%.2f\t%d\t%.1f\t%.2f\t%.4f\n", L, N, mem, 1.5 * seconds / 3600, dumps, dumps * N * bytes / 1e9, peak / 1e9, seconds / 3600
}'
