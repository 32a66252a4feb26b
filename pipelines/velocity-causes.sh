#!/bin/sh
# velocity-causes.sh PREFIX BIN SNAP_RUN "ALPHA_TIMES" "BETA_TIMES" "FROMS" ALPHA_FROM ["SIZE_TIMES" SIZE_RUN...]
# Why the velocity rows of the exponent table (alpha, beta, kappa; Pathak et
# al. 2014, Fig. 5) differ from the paper's numbers: the same quantities
# against time and against the window of the tail fit, beside the kinetic
# theory's alpha. Three TSV tables (numbers only: a fit without enough tail
# bins leaves its row out), PREFIX.tsv moved into place first, so that the
# other two (made by the same step) are never older than it:
#   PREFIX.tsv        alpha of SNAP_RUN: t y_from points alpha alpha_err alpha_chi2_dof
#                     alpha_kt alpha_kt_err alpha_kt_chi2_dof, where
#       alpha     straight fit -ln Phi = alpha y + c over the tail bins y >= y_from
#                 (coolgas-velocity --tail: both signs folded, >= 25 samples a bin),
#                 weighted by the bins' errors; errors scaled by sqrt(chi2/dof) when > 1
#       alpha_kt  the same bins fitted with kinetic theory's form for ONE component,
#                 -ln Phi = alpha y - ln(y + 1/alpha) + c (below)
#                 and, in its '# key: value' lines, the kinetic theory's alpha
#   PREFIX_beta.tsv   source L t y_from seeds beta beta_err points: coolgas-velocity's
#                 beta (ln(-ln Phi) against ln y over y >= y_from)
#   PREFIX_kappa.tsv  source L t seeds kappa kappa_err kappa_1: coolgas-velocity's kappa
#                 (speeds) and kappa_1 = <y^4>/<y^2>^2 - 5/3 of ONE component (from the
#                 histogram of Phi: the paper's formula read with v one velocity
#                 component, 4/3 for a Gaussian)
# source 0 is SNAP_RUN (beta at BETA_TIMES and every window, kappa at every
# dump; seeds 1, errors the tool's), source 1 the mean over the seeds of the
# SIZE_RUNs of side L at SIZE_TIMES (beta from the first window; errors the
# seeds' standard error, or the tool's for a single seed).
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
prefix=$1 bin=$2 snap=$3 alpha_times=$4 beta_times=$5 froms=$6 alpha_from=$7
size_times=${8:-}
shift 7; [ $# -gt 0 ] && shift
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
# provenance COLUMNS: the column line and the lines every table shares.
provenance() {
  printf '%s\n' "$1" | tr ' ' '\t'
  printf '# format: coolgas-table 2\n# tool: pipelines/velocity-causes.sh\n# version: %s\n' "$(meta version)"
  printf '# input: %s\n' "$(basename "$snap")"
  for k in N L phi r0 delta; do printf '# %s: %s\n' "$k" "$(meta "$k")"; done
}
# kappa_1 of each dump of a histogram table (coolgas-velocity's default output): "t kappa_1".
kappa_one() {
  awk -F '\t' '
    function flush() { if (t != "" && m2 > 0) printf "%s\t%.6g\n", t, m4 * m0 / (m2 * m2) - 5 / 3 }
    /^# t = / { flush(); t = $0; sub(/^# t = /, "", t); sub(/;.*/, "", t); m0 = m2 = m4 = 0; next }
    /^#/ || $1 == "t" || NF < 3 { next }
    { m0 += $3; m2 += $2 ^ 2 * $3; m4 += $2 ^ 4 * $3 }
    END { flush() }' "$1"
}

# ---- kappa: SNAP_RUN at every dump, then the size runs' seeds.
velocity "$tmp/phi" "$snap"
kappa_one "$tmp/phi" > "$tmp/k1"
{
  provenance "source L t seeds kappa kappa_err kappa_1"
  printf '# source: 0 = %s, 1 = the mean over the seeds of the size runs of side L\n' "$(basename "$snap")"
  printf '# size_times: %s\n' "$size_times"
  awk -F '\t' -v L="$L" 'FNR == NR { k1[$1] = $2; next }
    /^#/ || $1 == "t" || NF < 7 || !($1 in k1) { next }
    { printf "0\t%s\t%s\t1\t%s\t%s\t%s\n", L, $1, $3, $4, k1[$1] }' "$tmp/k1" "$tmp/series"
  if [ -n "$size_times" ] && [ $# -gt 0 ]; then
    for run in "$@"; do
      velocity "$tmp/size" "$run" --series --tail-from "$first_from" --time "$(commas "$size_times")"
      velocity "$tmp/sphi" "$run" --time "$(commas "$size_times")"
      kappa_one "$tmp/sphi" > "$tmp/sk1"
      Lr=$(sed -n 's/^# L: //p' "$tmp/size" | head -n 1)
      # one line a dump: L t kappa kappa_err kappa_1 beta beta_err points
      awk -F '\t' -v L="$Lr" 'FNR == NR { k1[$1] = $2; next } /^#/ || $1 == "t" || NF < 7 { next }
        { print L "\t" $1 "\t" $3 "\t" $4 "\t" k1[$1] "\t" $5 "\t" $6 "\t" $7 }' "$tmp/sk1" "$tmp/size"
    done > "$tmp/seeds"
    awk -F '\t' '
      { k = $1 SUBSEP $2; if (!(k in n)) order[++m] = k; n[k]++; s[k] += $3; ss[k] += $3 * $3; e[k] = $4; s1[k] += $5 }
      END { for (i = 1; i <= m; i++) { k = order[i]; split(k, p, SUBSEP); c = n[k]
              v = c > 1 ? (ss[k] - s[k] * s[k] / c) / (c - 1) / c : e[k] * e[k]
              printf "1\t%s\t%s\t%d\t%.6g\t%.3g\t%.6g\n", p[1], p[2], c, s[k] / c, sqrt(v > 0 ? v : 0), s1[k] / c } }' "$tmp/seeds"
  fi
} > "$tmp/kappa"

# ---- beta: the tool's own fit, once per window (SNAP_RUN), and the seeds' means from the first window.
{
  provenance "source L t y_from seeds beta beta_err points"
  printf '# source: 0 = %s, 1 = the mean over the seeds of the size runs of side L (from y_from = %s)\n' \
    "$(basename "$snap")" "$first_from"
  printf '# beta_times: %s\n# y_froms: %s\n' "$beta_times" "$froms"
  for f in $froms; do
    velocity "$tmp/beta" "$snap" --series --tail-from "$f" --time "$(commas "$beta_times")"
    awk -F '\t' -v f="$f" -v L="$L" '/^#/ || $1 == "t" || NF < 7 || $5 == "nan" { next }
      { printf "0\t%s\t%s\t%s\t1\t%s\t%s\t%s\n", L, $1, f, $5, $6, $7 }' "$tmp/beta"
  done
  if [ -s "$tmp/seeds" ]; then
    awk -F '\t' -v f="$first_from" '$6 == "nan" { next }
      { k = $1 SUBSEP $2; if (!(k in n)) order[++m] = k; n[k]++; s[k] += $6; ss[k] += $6 * $6; e[k] = $7; p[k] += $8 }
      END { for (i = 1; i <= m; i++) { k = order[i]; split(k, q, SUBSEP); c = n[k]
              v = c > 1 ? (ss[k] - s[k] * s[k] / c) / (c - 1) / c : e[k] * e[k]
              printf "1\t%s\t%s\t%s\t%d\t%.6g\t%.3g\t%.0f\n", q[1], q[2], f, c, s[k] / c, sqrt(v > 0 ? v : 0), p[k] / c } }' "$tmp/seeds"
  fi
} > "$tmp/beta_table"

# ---- alpha and alpha_kt: one --tail table from the smallest window, refitted per window.
velocity "$tmp/tail" "$snap" --tail --tail-from "$min_from" --time "$(commas "$alpha_times")"
{
  provenance "t y_from points alpha alpha_err alpha_chi2_dof alpha_kt alpha_kt_err alpha_kt_chi2_dof"
  printf '# alpha_times: %s\n# y_froms: %s\n# alpha_from: %s\n' "$alpha_times" "$froms" "$alpha_from"
  printf '# beta_table: %s\n# kappa_table: %s\n' "$(basename "$prefix")_beta.tsv" "$(basename "$prefix")_kappa.tsv"
  awk -v r="$r0" 'BEGIN {
    d = 3; pi = atan2(0, -1)
    a2 = 16 * (1 - r) * (1 - 2 * r * r) / (9 + 24 * d - r * (41 - 8 * d) + 30 * (1 - r) * r * r)
    A = 3 * sqrt(pi / 2) / ((1 - r * r) * (1 + 3 * a2 / 16))
    printf "# kinetic_theory: van Noije & Ernst 1998, f(c) ~ exp(-A c), c = |v|/sqrt(2T/m); alpha = A/sqrt(2) in y = v_x/v_rms\n"
    printf "# kinetic_theory_a2: %.4f\n# kinetic_theory_A: %.4f\n", a2, A
    printf "# alpha_kinetic_theory: %.4f\n", A / sqrt(2)
    printf "# alpha_kinetic_theory_no_sonine: %.4f\n", 3 * sqrt(pi / 2) / (1 - r * r) / sqrt(2) }'
  awk -v froms="$froms" '
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
    # Each window of one dump; fewer than 3 bins (or none past 2 fitted values) leave no row.
    function flush(   j, i) {
      if (t == "") return
      for (j = 1; j <= nf; j++) {
        n = 0
        for (i = 1; i <= N; i++) if (Y[i] >= F[j] - 1e-9) { n++; y[n] = Y[i]; l[n] = Lp[i]; e[n] = E[i] }
        if (n < 3) continue
        fit_line(); fit_kt()
        printf "%s\t%s\t%d\t%.5g\t%.3g\t%.3g\t%.5g\t%.3g\t%.3g\n", t, F[j], n, fa, fe, fchi, ka, ke, kchi
      }
    }
    BEGIN { nf = split(froms, F, " ") }
    /^# t = / { flush(); t = $0; sub(/^# t = /, "", t); sub(/;.*/, "", t); N = 0; next }
    /^#/ || $1 == "t" || NF < 4 { next }
    { N++; Y[N] = $2; Lp[N] = $3; E[N] = $4 }
    END { flush() }' "$tmp/tail"
} > "$tmp/alpha"

mv "$tmp/alpha" "$prefix.tsv"
mv "$tmp/beta_table" "${prefix}_beta.tsv"
mv "$tmp/kappa" "${prefix}_kappa.tsv"
# (mv keeps the time each was written, the alpha table's last)
touch "${prefix}_beta.tsv" "${prefix}_kappa.tsv"
