#!/bin/sh
# mmax-jump.sh MMAX_TABLE ENERGY_TABLE
# The rapid growth of the largest cluster (paper Fig. 4) and the onset of
# inhomogeneous cooling of the same run, as a one-row TSV table on stdout.
# MMAX_TABLE is coolgas-clusters --series of a run (t, M_max, largest_fraction),
# ENERGY_TABLE coolgas-energy of the same run (t, E).
#
# The rules (Pathak et al. 2014: "a rapid increase in M_max at a time that
# coincides with the onset of the inhomogeneous cooling regime"):
#  - steepest rise: for each dump t_i, the chord to the first dump at least
#    0.4 decades later, t_j; its slope s = ln(M_j/M_i) / ln(t_j/t_i). The
#    largest s is slope_max, and t_jump = sqrt(t_i t_j) is its centre. A
#    chord over 0.4 decades (two dump intervals at 5 dumps a decade) averages
#    out the dump-to-dump noise of small clusters (slopes up to ~1.3 before
#    the jump in the demo's runs).
#  - jump = 1 when slope_max >= 2 (far above the mean-field t^(6/5) and ballistic
#    aggregation's ~t^1), the chord spans at most 0.5 decades (dumps dense
#    enough to see a jump) and the largest cluster holds at most half of the
#    particles at t = 0 (else the cluster definition percolates from the start).
#  - inhomogeneous cooling: the local slope theta = -d ln E / d ln t over a
#    quarter decade (each sample to the first at least 10^0.25 later, at their
#    geometric centre); theta_peak is its largest value (Haff's law
#    E ~ (1 + t/t0)^-2 steepens towards t^-2 until clustering slows the
#    decay). t_inhom is the first centre at or after the peak where theta < 3/2,
#    the project's mark of having left Haff's regime (pipelines/exponents.sh:
#    no theory of the inhomogeneous regime decays faster than t^-3/2).
#    inhom = 1 when theta_peak >= 3/2 and such a time exists; 0 when the decay
#    never was that steep (t_inhom is then the peak's time) or is still that
#    steep at the run's end (t_inhom is then the last centre).
#  - fraction_inhom: M_max/N at t_inhom, interpolated in ln t and ln M_max
#    between the dumps around it (where Fig. 4 marks it).
set -e
mmax=$1 energy=$2
meta() { sed -n "s/^# $1: //p" "$mmax" | head -n 1; }
printf 't_jump\tslope_max\tt_from\tt_to\tfraction_from\tfraction_to\tspan\tfraction_0\tjump\t'
printf 't_inhom\ttheta_peak\tt_peak\tfraction_inhom\tinhom\tt_end\n'
printf '# format: coolgas-table 2\n'
printf '# tool: pipelines/mmax-jump.sh\n'
printf '# input: %s\n# input: %s\n' "$mmax" "$energy"
for k in version seed N L phi r0 delta definition; do printf '# %s: %s\n' "$k" "$(meta "$k")"; done
printf '# rule: steepest chord of ln M_max vs ln t over >= 0.4 decades; jump if its slope >= 2, span <= 0.5 decades, largest_fraction(0) <= 0.5\n'
printf '# rule_energy: t_inhom = first quarter-decade centre at or after the steepest decay with -d ln E/d ln t < 1.5\n'
awk -F '\t' '
  # columns by name from the column line of each file (format 2)
  FNR == 1 { delete col; for (i = 1; i <= NF; i++) col[$i] = i; file++; next }
  /^#/ || NF == 0 { next }
  file == 1 { n++; t[n] = $col["t"]; m[n] = $col["M_max"]; f[n] = $col["largest_fraction"]; next }
  file == 2 && $col["t"] > 0 && $col["E"] > 0 { ne++; te[ne] = $col["t"]; e[ne] = $col["E"] }
  # the first index after i whose time is at least t_i * ratio (0 if none)
  function later(ts, count, i, ratio,   j) {
    for (j = i + 1; j <= count; j++) if (ts[j] >= ts[i] * ratio * (1 - 1e-9)) return j
    return 0
  }
  function num(x) { return x == "" ? "nan" : sprintf("%.6g", x) }
  END {
    best = ""
    for (i = 1; i <= n; i++) {
      if (t[i] <= 0 || m[i] <= 0) continue
      j = later(t, n, i, 10 ^ 0.4); if (!j) break
      s = log(m[j] / m[i]) / log(t[j] / t[i])
      if (best == "" || s > best) { best = s; bi = i; bj = j }
    }
    if (best == "") { print "mmax-jump.sh: fewer than two dumps 0.4 decades apart with t > 0 in " ARGV[1] > "/dev/stderr"; exit 2 }
    span = log(t[bj] / t[bi]) / log(10)
    jump = (best >= 2 && span <= 0.5 && f[1] <= 0.5) ? 1 : 0
    peak = ""
    for (i = 1; i <= ne; i++) {
      j = later(te, ne, i, 10 ^ 0.25); if (!j) break
      c[i] = sqrt(te[i] * te[j]); th[i] = -log(e[j] / e[i]) / log(te[j] / te[i]); nc = i
      if (peak == "" || th[i] > peak) { peak = th[i]; pi = i }
    }
    if (peak == "") { print "mmax-jump.sh: fewer than two samples a quarter decade apart in " ARGV[2] > "/dev/stderr"; exit 2 }
    ti = ""
    for (i = pi; i <= nc; i++) if (th[i] < 1.5) { ti = c[i]; break }
    inhom = (ti != "" && peak >= 1.5) ? 1 : 0
    if (ti == "") ti = c[nc]
    # M_max/N at t_inhom, between the dumps around it
    fi = ""
    for (i = 2; i <= n; i++) if (t[i - 1] > 0 && t[i - 1] <= ti && ti <= t[i]) {
      w = log(ti / t[i - 1]) / log(t[i] / t[i - 1]); fi = exp((1 - w) * log(f[i - 1]) + w * log(f[i])); break
    }
    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%d\t", num(sqrt(t[bi] * t[bj])), num(best), num(t[bi]), num(t[bj]), \
      num(f[bi]), num(f[bj]), num(span), num(f[1]), jump
    printf "%s\t%s\t%s\t%s\t%d\t%s\n", num(ti), num(peak), num(c[pi]), num(fi), inhom, num(t[n])
  }' "$mmax" "$energy"
