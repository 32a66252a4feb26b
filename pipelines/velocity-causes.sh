#!/bin/sh
# velocity-causes.sh BIN SNAP_RUN "ALPHA_TIMES" "BETA_TIMES" "FROMS" ALPHA_FROM ["SIZE_TIMES" SIZE_RUN...]
# Why the velocity rows of the exponent table (alpha, beta, kappa; Pathak et
# al. 2014, Fig. 5) differ from the paper's numbers: the same quantities
# against time and against the window of the tail fit, beside the kinetic
# theory's alpha. One TSV table on stdout, columns
#   quantity  L  t  y_from  value  error  points  chi2_dof
# (a cell that does not apply is nan) with rows
#   alpha        straight fit -ln Phi = alpha y + c over the tail bins y >= y_from
#                (coolgas-velocity --tail: both signs folded, >= 25 samples a bin),
#                weighted by the bins' errors; error scaled by sqrt(chi2/dof) when > 1
#   alpha_kt     the same bins fitted with kinetic theory's form for ONE component,
#                -ln Phi = alpha y - ln(y + 1/alpha) + c (below)
#   beta         coolgas-velocity's beta (ln(-ln Phi) against ln y over y >= y_from)
#   kappa        coolgas-velocity's kappa (speeds) at every dump of SNAP_RUN
#   kappa_1      <y^4>/<y^2>^2 - 5/3 of ONE component (the histogram of Phi), the
#                paper's formula read with v one velocity component: 4/3 for a Gaussian
#   kappa_seeds, beta_seeds   mean over the seeds of each box side L (SIZE_RUNs) at
#                SIZE_TIMES; error the seeds' standard error, points the seeds
# ALPHA_TIMES, BETA_TIMES are times of SNAP_RUN's dumps (each snapped to the
# nearest dump; t = 0, the equilibrated elastic start, is the Maxwellian
# reference of every window), FROMS the windows' starts y_from, ALPHA_FROM
# the window of the exponent table's alpha row (recorded as '# alpha_from').
#
# Kinetic theory (van Noije & Ernst, Granular Matter 1, 57 (1998)): in the
# homogeneous cooling state the scaled speed distribution has the tail
# f(c) ~ exp(-A c), c = |v|/v0, v0 = sqrt(2T/m), with A = d beta1/mu2 from the
# balance of the cooling term (mu2/d) c df/dc and the loss term -beta1 c f of
# the scaled Boltzmann (Enskog) equation; in d = 3, beta1 = pi and
# mu2 = (1 - r0^2) sqrt(2 pi) (1 + 3 a2/16) (Enskog's pair correlation
# multiplies both and cancels), so A = 3 sqrt(pi/2) / ((1 - r0^2)(1 + 3 a2/16)),
# with the Sonine coefficient
# a2 = 16 (1 - r0)(1 - 2 r0^2) / (9 + 24 d - r0 (41 - 8 d) + 30 (1 - r0) r0^2).
# The paper's y is one component over its rms, y = v_x / sqrt(T/m) = sqrt(2) c_x,
# and one component of exp(-A |c|) has the marginal
#   P(c_x) ~ integral_{|c_x|}^inf 2 pi s exp(-A s) ds ~ (A |c_x| + 1) exp(-A |c_x|),
# so Phi(y) ~ (y + 1/alpha) exp(-alpha y) with alpha = A / sqrt(2): the
# asymptotic slope of -ln Phi is alpha, its local slope alpha - 1/(y + 1/alpha)
# is lower at every finite y. r0 = 0.1 gives a2 = 0.177, A = 3.676 and
# alpha = 2.599 (2.686 without the Sonine factor), the paper's "2.60".
set -e
bin=$1 snap=$2 alpha_times=$3 beta_times=$4 froms=$5 alpha_from=$6
size_times=${7:-}
shift 6; [ $# -gt 0 ] && shift
vel=$bin/coolgas-velocity
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
commas() { echo "$1" | tr -s ' ' ',' | sed 's/^,//; s/,$//'; }
# The tool's table, or its error on stderr and a failed step.
velocity() {
  out=$1; shift
  if ! "$vel" "$@" > "$out" 2> "$tmp/err"; then cat "$tmp/err" >&2; exit 1; fi
}
# alpha's window is one of the windows; the tail table starts at the smallest.
case " $froms " in *" $alpha_from "*) ;; *) froms="$froms $alpha_from" ;; esac
first_from=${froms%% *}
min_from=$(echo "$froms" | awk '{ m = $1; for (i = 2; i <= NF; i++) if ($i + 0 < m + 0) m = $i; print m }')

velocity "$tmp/series" "$snap" --series
meta() { sed -n "s/^# $1: //p" "$tmp/series" | head -n 1; }
L=$(meta L) r0=$(meta r0)

printf 'quantity\tL\tt\ty_from\tvalue\terror\tpoints\tchi2_dof\n'
printf '# format: coolgas-table 2\n'
printf '# tool: pipelines/velocity-causes.sh\n'
printf '# version: %s\n' "$(meta version)"
printf '# input: %s\n' "$(basename "$snap")"
for k in N L phi r0 delta; do printf '# %s: %s\n' "$k" "$(meta "$k")"; done
printf '# alpha_times: %s\n# beta_times: %s\n# y_froms: %s\n# alpha_from: %s\n# size_times: %s\n' \
  "$alpha_times" "$beta_times" "$froms" "$alpha_from" "$size_times"
awk -v r="$r0" 'BEGIN {
  d = 3; pi = atan2(0, -1)
  a2 = 16 * (1 - r) * (1 - 2 * r * r) / (9 + 24 * d - r * (41 - 8 * d) + 30 * (1 - r) * r * r)
  A = 3 * sqrt(pi / 2) / ((1 - r * r) * (1 + 3 * a2 / 16))
  printf "# kinetic_theory: van Noije & Ernst 1998, f(c) ~ exp(-A c), c = |v|/sqrt(2T/m); alpha = A/sqrt(2) in y = v_x/v_rms\n"
  printf "# kinetic_theory_a2: %.4f\n# kinetic_theory_A: %.4f\n", a2, A
  printf "# alpha_kinetic_theory: %.4f\n", A / sqrt(2)
  printf "# alpha_kinetic_theory_no_sonine: %.4f\n", 3 * sqrt(pi / 2) / (1 - r * r) / sqrt(2) }'

# alpha and alpha_kt: one --tail table from the smallest window, refitted per window.
velocity "$tmp/tail" "$snap" --tail --tail-from "$min_from" --time "$(commas "$alpha_times")"
awk -v froms="$froms" -v L="$L" '
  function fit_line(   i, w, sw, swy, swyy, swl, swyl, det, c, chi) {
    sw = swy = swyy = swl = swyl = 0
    for (i = 1; i <= n; i++) { w = 1 / (e[i] * e[i]); sw += w; swy += w * y[i]; swyy += w * y[i] * y[i]; swl += w * l[i]; swyl += w * y[i] * l[i] }
    det = sw * swyy - swy * swy
    fa = (sw * swyl - swy * swl) / det; c = (swl - fa * swy) / sw
    chi = 0; for (i = 1; i <= n; i++) chi += (l[i] - fa * y[i] - c) ^ 2 / e[i] ^ 2
    fchi = chi / (n - 2); fe = sqrt(sw / det * (fchi > 1 ? fchi : 1))
  }
  # chi^2 of the kinetic-theory form at exponent al, its constant c fitted (a weighted mean).
  function chi_kt(al,   i, w, sw, swr, c, chi) {
    sw = swr = 0
    for (i = 1; i <= n; i++) { r[i] = l[i] + log(y[i] + 1 / al) - al * y[i]; w = 1 / e[i] ^ 2; sw += w; swr += w * r[i] }
    c = swr / sw; chi = 0
    for (i = 1; i <= n; i++) chi += (r[i] - c) ^ 2 / e[i] ^ 2
    return chi
  }
  # A scan in steps of 0.001 (chi^2 is smooth with one minimum here); the error
  # is the half width where chi^2 rises by max(1, chi2/dof) (Delta chi^2 = 1 after scaling).
  function fit_kt(   al, best, s, lo, hi) {
    best = -1
    for (al = 0.5; al <= 8; al += 0.001) { s = chi_kt(al); if (best < 0 || s < best) { best = s; ka = al } }
    kchi = best / (n - 2); s = kchi > 1 ? kchi : 1
    for (lo = ka; lo > 0.3 && chi_kt(lo) - best < s; lo -= 0.001);
    for (hi = ka; hi < 10 && chi_kt(hi) - best < s; hi += 0.001);
    ke = (hi - lo) / 2
  }
  function flush(   j, i) {
    if (t == "") return
    for (j = 1; j <= nf; j++) {
      n = 0
      for (i = 1; i <= N; i++) if (Y[i] >= F[j] - 1e-9) { n++; y[n] = Y[i]; l[n] = Lp[i]; e[n] = E[i] }
      if (n >= 3) {
        fit_line(); fit_kt()
        printf "alpha\t%s\t%s\t%s\t%.4f\t%.4f\t%d\t%.3g\n", L, t, F[j], fa, fe, n, fchi
        printf "alpha_kt\t%s\t%s\t%s\t%.4f\t%.4f\t%d\t%.3g\n", L, t, F[j], ka, ke, n, kchi
      } else {
        printf "alpha\t%s\t%s\t%s\tnan\tnan\t%d\tnan\n", L, t, F[j], n
        printf "alpha_kt\t%s\t%s\t%s\tnan\tnan\t%d\tnan\n", L, t, F[j], n
      }
    }
  }
  BEGIN { nf = split(froms, F, " ") }
  /^# t = / { flush(); t = $0; sub(/^# t = /, "", t); sub(/;.*/, "", t); N = 0; next }
  /^#/ || $1 == "t" || NF < 4 { next }
  { N++; Y[N] = $2; Lp[N] = $3; E[N] = $4 }
  END { flush() }' "$tmp/tail"

# beta: the tool's own fit, once per window.
for f in $froms; do
  velocity "$tmp/beta" "$snap" --series --tail-from "$f" --time "$(commas "$beta_times")"
  awk -F '\t' -v f="$f" -v L="$L" '/^#/ || $1 == "t" || NF < 7 { next }
    { printf "beta\t%s\t%s\t%s\t%s\t%s\t%s\tnan\n", L, $1, f, ($5 == "nan" ? "nan" : sprintf("%.4f", $5)), ($6 == "nan" ? "nan" : sprintf("%.4f", $6)), $7 }' "$tmp/beta"
done

# kappa at every dump; kappa_1 from the histogram of one component at BETA_TIMES.
awk -F '\t' -v L="$L" '/^#/ || $1 == "t" || NF < 7 { next }
  { printf "kappa\t%s\t%s\tnan\t%.4f\t%.4f\tnan\tnan\n", L, $1, $3, $4 }' "$tmp/series"
velocity "$tmp/phi" "$snap" --time "$(commas "$beta_times")"
awk -F '\t' -v L="$L" '
  function flush() { if (t != "" && m2 > 0) printf "kappa_1\t%s\t%s\tnan\t%.4f\tnan\tnan\tnan\n", L, t, m4 * m0 / (m2 * m2) - 5 / 3 }
  /^# t = / { flush(); t = $0; sub(/^# t = /, "", t); sub(/;.*/, "", t); m0 = m2 = m4 = 0; next }
  /^#/ || $1 == "t" || NF < 3 { next }
  { m0 += $3; m2 += $2 ^ 2 * $3; m4 += $2 ^ 4 * $3 }
  END { flush() }' "$tmp/phi"

# kappa and beta of the size runs: the mean over each L's seeds and its standard error.
[ -n "$size_times" ] && [ $# -gt 0 ] || exit 0
for run in "$@"; do
  velocity "$tmp/size" "$run" --series --tail-from "$first_from" --time "$(commas "$size_times")"
  Lr=$(sed -n 's/^# L: //p' "$tmp/size" | head -n 1)
  awk -F '\t' -v L="$Lr" '/^#/ || $1 == "t" || NF < 7 { next } { print L "\t" $1 "\t" $3 "\t" $5 }' "$tmp/size"
done > "$tmp/seeds"
awk -F '\t' -v f="$first_from" '
  { k = $1 SUBSEP $2; if (!(k in n)) order[++m] = k; n[k]++; sk[k] += $3; skk[k] += $3 * $3
    if ($4 != "nan") { nb[k]++; sb[k] += $4; sbb[k] += $4 * $4 } }
  function se(s, ss, c,   v) { if (c < 2) return "nan"; v = (ss - s * s / c) / (c - 1) / c; return sprintf("%.4f", sqrt(v > 0 ? v : 0)) }
  END {
    for (i = 1; i <= m; i++) { k = order[i]; split(k, p, SUBSEP)
      printf "kappa_seeds\t%s\t%s\tnan\t%.4f\t%s\t%d\tnan\n", p[1], p[2], sk[k] / n[k], se(sk[k], skk[k], n[k]), n[k]
      if (nb[k] > 0) printf "beta_seeds\t%s\t%s\t%s\t%.4f\t%s\t%d\tnan\n", p[1], p[2], f, sb[k] / nb[k], se(sb[k], sbb[k], nb[k]), nb[k] }
  }' "$tmp/seeds"
