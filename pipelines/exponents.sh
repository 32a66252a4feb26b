#!/bin/sh
# exponents.sh TABLES SNAP_RUN LATE_TIME L_MAX SNAP_L "PARAM_SETS" "BA_FITS" "STRUCTURE_RUNS" "MMAX_RUNS" "BA_MMAX_RUNS"
# The quantities a figure pipeline measured, one row each, judged against
# the paper (Pathak, Jabeen, Das, Rajesh 2014): a TSV table with columns
#   quantity figure measured error paper paper_error tolerance deviation regime verdict note
# quantity is a short name; paper is the paper's value, a bound "> b" or
# "< b" where it says only which side, or "-"; tolerance is how far from it
# a value still agrees (the tol_* below); deviation = (measured - paper) /
# sqrt(error^2 + paper_error^2) where all are numbers; regime says whether
# the run reached the regime the paper measures the quantity in ("yes", or
# "no: why"), judged with the paper's crossover to finite-size behaviour at
# x = t / L^(5/2) ~ 0.1 (its Fig. 1); verdict is "agrees", "differs", "not
# decided" or "-" by the rules of pipelines/row-verdict.sh, the only place they
# are stated; note holds the window, the method and, for a row that differs
# where a rule can tell, why ("because ..."). A note never repeats the
# verdict in other words: the words of a row are its verdict column's.
# TABLES is the pipeline's tables folder, SNAP_RUN the run of Figs. 3-5,
# LATE_TIME the time its late-time values are read at, L_MAX the largest L
# of Fig. 1, SNAP_L the box side of Figs. 3-5 (each Fig. 2 row reads its
# box side from its energy table, as the sets may differ in L),
# STRUCTURE_RUNS the runs whose growing lengths were fitted (lt_RUN.tsv,
# fit_lt_RUN.tsv, fit_lc_RUN.tsv of pipelines/structure.mk), MMAX_RUNS the gas
# runs of Fig. 4 (jump_mmax_RUN.tsv of pipelines/mmax-jump.sh), BA_MMAX_RUNS its
# BA runs (fit_mmax_RUN.tsv, jump_mmax_RUN.tsv). Fig. 1's collapse is read
# twice: tables/collapse.tsv fits theta and z together (the free fit),
# tables/collapse_z_theta.tsv holds z theta = d and fits z, the paper's method.
# Where TABLES/contact/ holds the same cluster tables by contact clusters
# (pipelines/contact-clusters.mk), tau and the Fig. 4 rows are given by them too.
set -e
tables=$1 snap=$2 late=$3 L_max=$4 snap_L=$5 sets=$6 ba_fits=${7:-} structure_runs=${8:-} mmax_runs=${9:-} ba_mmax=${10:-}
here=$(dirname "$0")
value() { sh "$here/tsv-value.sh" "$@"; }
# Column $2 of table $1 in the row whose t is nearest $3.
at_time() {
  awk -F '\t' -v want="$2" -v t="$3" '
    function names(line) { n = split(line, name, "\t"); for (i = 1; i <= n; i++) { if (name[i] == want) col = i; if (name[i] == "t") tc = i } header = 1 }
    /^#/ { line = substr($0, 3); if (index(line, ":") == 0 && !header) names(line); next }
    NF > 0 && !header { names($0); next }
    NF > 0 { d = $tc - t; if (d < 0) d = -d; if (best == "" || d < best) { best = d; v = $col } }
    END { print v }' "$1"
}
calc() { awk "BEGIN { printf \"%.6g\", $1 }"; }
short() { awk "BEGIN { printf \"%.3g\", $1 }"; }
dec3() { awk "BEGIN { printf \"%.3f\", $1 }"; }
# x = t / L^(5/2) and whether it is before the finite-size crossover (x <= 0.1,
# to the 3 digits shown: a window chosen to end at x = 0.1 is inside)
before_crossover() {  # t L what
  x=$(short "$1 / ($2 ^ 2.5)")
  if awk "BEGIN { exit !($x <= 0.1) }"; then echo yes
  else echo "no: $3 at t = $(short "$1") has x = t/L^(5/2) = $x > 0.1 in L = $2 (finite-size regime)"; fi
}
# Local slope -d ln E / d ln t of an E(t) table over the quarter decade from t.
local_slope() {  # table t
  awk -F '\t' -v t0="$2" '
    FNR == 1 || /^#/ || NF == 0 || $1 <= 0 { next }
    $1 >= t0 && !a { ta = $1; ea = $2; a = 1 }
    $1 >= t0 * 1.778 && !b { tb = $1; eb = $2; b = 1 }
    END { if (a && b) printf "%.3g", -log(eb / ea) / log(tb / ta); else print "nan" }' "$1"
}
# The paper measures theta once E(t) has left Haff's t^-2 decay: a window
# whose start still decays faster than t^-3/2 (the largest exponent any
# theory proposes, Burgers') is still in the crossover. Then the finite-size test.
scaling_regime() {  # energy_table fit_table L
  s=$(local_slope "$1" "$(value "$2" t_min)")
  if awk "BEGIN { exit !(\"$s\" == \"nan\" || $s > 1.5) }"; then
    echo "no: at the window's start E(t) still falls as t^-$s, faster than t^-3/2 (not yet past the crossover from Haff's law)"
  else before_crossover "$(value "$2" t_max)" "$3" "the window's end"; fi
}
# The regime verdict of a run whose largest cluster at t = 0 is the fraction
# $1 > 0.5, by the definition of the table $2 (coolgas-clusters: its
# "# definition:" line, cells where it has none): the cause, with the unit
# cells' occupancy n = N / L^3 particles per cell.
percolates() {  # fraction table
  def=$(value "$2" definition '#')
  case $def in
    contact:*) echo "no: the largest cluster holds $(short "$1") of the particles already at t = 0 (bonds of ${def#contact:} sigma span the box from the start)" ;;
    *) echo "no: the largest cluster holds $(short "$1") of the particles already at t = 0 (the unit cells percolate: their occupancy, n = $(dec3 "$(value "$2" N '#') / ($(value "$2" L '#') ^ 3)") particles per cell, is above the site-percolation threshold 0.3116)" ;;
  esac
}
# The bond length of a contact table's definition, sigma.
cutoff_of() { d=$(value "$1" definition '#'); echo "${d#contact:}"; }
is_num() { echo "$1" | grep -Eq '^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$'; }

# How far from the paper's value a row still agrees (pipelines/row-verdict.sh).
# theta: 6/5 against Burgers' 3/2 and against BA's 1.206-1.283, which a
# tolerance of 0.03 tells apart; z: 5/2 against Burgers' 2 (the collapse
# fits z to a tenth at best at these sizes); z theta: z's times 6/5; eta,
# beta, alpha and the Smoluchowski exponents: a tenth, the paper's own
# digits; tau: the paper's exponents 2.7 and 0.2 are read off log-log slopes
# over a decade or two of m; the largest cluster's share: a tenth.
tol_theta=0.03 tol_z=0.25 tol_z_theta=0.3 tol_eta=0.1 tol_tau=0.2 tol_share=0.1 tol_beta=0.1
tol_alpha=0.1 tol_smoluchowski=0.1
# M_max's steepest rise: a jump when steeper than t^2 (the rule of
# pipelines/mmax-jump.sh, far above mean field's t^(6/5) and BA's ~t^1).
jump_slope=2

# verdict MEASURED ERROR PAPER PAPER_ERROR TOLERANCE REGIME: the row's verdict word.
verdict() { sh "$here/row-verdict.sh" "$@"; }
# row QUANTITY FIGURE MEASURED ERROR PAPER PAPER_ERROR TOLERANCE REGIME [NOTE]
row() {
  dev=-
  if is_num "$3" && is_num "$4" && is_num "$5" && is_num "$6"; then
    dev=$(awk "BEGIN { s = sqrt($4 * $4 + $6 * $6); if (s > 0) printf \"%.2f\", ($3 - $5) / s; else print \"-\" }")
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$5" "$6" "$7" "$dev" "$8" \
    "$(verdict "$3" "$4" "$5" "$6" "$7" "$8")" "${9:--}"
}

collapse=$tables/collapse.tsv paper_collapse=$tables/collapse_z_theta.tsv
printf 'quantity\tfigure\tmeasured\terror\tpaper\tpaper_error\ttolerance\tdeviation\tregime\tverdict\tnote\n'
printf '# format: coolgas-table 2\n'
printf '# tool: pipelines/exponents.sh\n'
printf '# version: %s\n' "$(value "$collapse" version '#')"
# The program that made the runs (it may be older than the analysis, e.g. on reanalysis).
printf '# simulator_version: %s\n' "$(sed -n 's/^# simulator_version: //p' "$tables"/energy_*.tsv | sort -u | paste -sd ';' -)"
printf '# date: %s\n' "$(date -u +%Y-%m-%d)"
printf '# late_time: %s\n' "$late"
printf '# rules: pipelines/row-verdict.sh\n'

# Fig. 1: a collapse spans both sides of the crossover x ~ 1 when it reaches
# x < 0.1 and x > 1. x_range TABLE: the smallest and largest x of its points.
x_range() { awk -F '\t' 'FNR > 1 && !/^#/ && NF > 0 { if (lo == "" || $1 < lo) lo = $1; if ($1 > hi) hi = $1 } END { printf "%.3g %.3g", lo, hi }' "$1"; }
spans_crossover() {  # xlo xhi
  if awk "BEGIN { exit !($1 < 0.1 && $2 > 1) }"; then echo yes; else echo "no: the scaled data span x = $1 to $2, not both x < 0.1 and x > 1"; fi
}
set -- $(x_range "$collapse"); xhi=$2 collapse_regime=$(spans_crossover "$1" "$2")
set -- $(x_range "$paper_collapse"); pxhi=$2 paper_regime=$(spans_crossover "$1" "$2")
pc() { value "$paper_collapse" "$1" '#'; }
fc() { value "$collapse" "$1" '#'; }
row "theta, collapse" 1 "$(fc theta)" "$(fc theta_err)" 1.2 0 $tol_theta "$collapse_regime" \
  "E L^(z theta) against t/L^z, theta and z fitted together (the free fit)"
# The paper's method: its Fig. 1 plots E L^3 against t/L^(5/2), so z theta
# is held at d = 3 and z alone is fitted. Its theta is 3/z: with theta fixed
# by the power-law part of E(t) this z is about 3/theta, as well known as
# theta, and a test of the relation rather than a second measurement of z.
ratio=$(awk -v q="$(pc quality)" -v f="$(fc quality)" 'BEGIN { if (f > 0) printf "%.3g", q / f; else print "nan" }')
row "z, collapse with z theta = 3" 1 "$(pc z)" "$(pc z_err)" 2.5 0 $tol_z "$paper_regime" \
  "the paper's method: E L^3 against t/L^z, z fitted, theta = 3/z = $(dec3 "$(pc theta)"); collapse quality $ratio times the free fit's"
row "z, free collapse" 1 "$(fc z)" "$(fc z_err)" 2.5 0 $tol_z "$collapse_regime" \
  "fitted with theta: the power-law part of E(t) collapses at any z and only the crossovers fix it (its spread: the robustness block)"
# The product z theta, the exponent of L in E L^(z theta): mean field (and the
# paper's Fig. 1) has z theta = d = 3. Its error comes from the same
# replicas as theta's and z's, which are correlated.
row "z theta, free collapse" 1 "$(fc z_theta)" "$(fc z_theta_err)" 3 0 $tol_z_theta "$collapse_regime" "mean field: z theta = d"
# eta from the paper's collapse, whose x = t/L^z reaches furthest for the
# small boxes' late times; the free fit's eta beside it.
ew=$(pc eta_window) && ewlo=${ew%%:*}
if ! is_num "$(pc eta)"; then reg="no: fewer than 3 scaled points lie in x = $ew (the data reach x = $pxhi)"
elif awk "BEGIN { exit !(${ewlo:-0} >= 1) }"; then reg=yes; else reg="no: the fit window starts at x = ${ewlo:-0} < 1"; fi
free_eta=$(if is_num "$(fc eta)"; then echo "the free fit gives $(dec3 "$(fc eta)") +- $(dec3 "$(fc eta_err)")"
  else echo "the free fit's data reach x = $xhi"; fi)
row "eta, f(x) ~ x^-eta" 1 "$(pc eta)" "$(pc eta_err)" 1.83 0 $tol_eta "$reg" \
  "fitted in the window x = $ew of the collapse with z theta = 3, its points pooled (so its error is too small); $free_eta"
fit=$tables/fit_size_Lmax.tsv
row "theta, power-law fit at L = $L_max" 1 "$(value "$fit" theta)" "$(value "$fit" theta_err)" 1.2 0 $tol_theta \
  "$(scaling_regime "$tables/energy_size_L$L_max.tsv" "$fit" "$L_max")" "t = $(short "$(value "$fit" t_min)"):$(short "$(value "$fit" t_max)")"

# Fig. 2: each parameter set's fit. A set whose row differs says why, from
# tables/theta_causes.tsv (pipelines/theta-causes.mk): the local slope of
# E(t) in its window and theta over other windows.
causes=$tables/theta_causes.tsv
# The first row of theta_causes.tsv with these values: model phi r0 delta L
# window [fewest runs] (the pipeline's own run comes first; a set's seeds, if
# the scale runs more, after it).
causes_row() {
  [ -f "$causes" ] || return 0
  awk -F '\t' -v m="$1" -v phi="$2" -v r0="$3" -v d="$4" -v L="$5" -v w="$6" -v runs="${7:-1}" '
    function near(a, b) { return (a - b) * (a - b) <= (0.003 * b) * (0.003 * b) }
    FNR == 1 || /^#/ || NF == 0 { next }
    $1 == m && near($2, phi) && near($3, r0) && near($4, d) && $5 == L && $7 == w && $6 >= runs { print; exit }' "$causes"
}
# Field $2 (1-based) of row $1.
fld() { echo "$1" | cut -f "$2"; }
# A time: whole numbers from 100 on, else 3 digits.
tfmt() { awk "BEGIN { t = $1; if (t >= 100) printf \"%.0f\", t; else printf \"%.3g\", t }"; }
# Why a set's theta differs from 6/5 ("because ..."), or nothing when the causes step has no rows for it.
fig2_cause() {  # set L theta theta_err
  phi=$(echo "$1" | sed 's/^phi//; s/_.*//') r0=$(echo "$1" | sed 's/.*_r//; s/_.*//') d=$(echo "$1" | sed 's/.*_d//')
  w0=$(causes_row 0 "$phi" "$r0" "$d" "$2" 0) w1=$(causes_row 0 "$phi" "$r0" "$d" "$2" 1) w2=$(causes_row 0 "$phi" "$r0" "$d" "$2" 2)
  [ -n "$w0" ] && [ -n "$w1" ] && [ -n "$w2" ] || return 0
  t1=$(fld "$w1" 11) e1=$(fld "$w1" 12) t2=$(fld "$w2" 11) e2=$(fld "$w2" 12)
  t0=$3 e0=$4
  # A plateau would give the same theta over every window: the windows
  # differ (by more than 3 combined errors) or they do not.
  if awk "BEGIN { d1 = $t1 - $t0; d2 = $t2 - $t0; s1 = $e1 * $e1 + $e0 * $e0; s2 = $e2 * $e2 + $e0 * $e0
                  exit !(d1 * d1 > 9 * s1 || d2 * d2 > 9 * s2) }"; then
    trend=$(awk "BEGIN { a = $t2 - 1.2; b = $t0 - 1.2; if (a * a < b * b) print \"the last half decade is nearer 6/5: a larger box, whose window ends later, would tell whether the slope stays there\"; else print \"the last half decade is no nearer 6/5\" }")
    printf 'because E(t) has no power-law plateau in the window (its local slope falls to %s at t = %s and is %s at the end, tables/theta_causes.tsv), so theta depends on the window: %s +- %s from a start sqrt(10) later, %s +- %s over the last half decade (%s)' \
      "$(dec3 "$(fld "$w0" 14)")" "$(tfmt "$(fld "$w0" 15)")" "$(dec3 "$(fld "$w0" 16)")" \
      "$(dec3 "$t1")" "$(dec3 "$e1")" "$(dec3 "$t2")" "$(dec3 "$e2")" "$trend"
  else
    printf 'theta is the same over every window (%s +- %s from a start sqrt(10) later, %s +- %s over the last half decade, tables/theta_causes.tsv): not a choice of window' \
      "$(dec3 "$t1")" "$(dec3 "$e1")" "$(dec3 "$t2")" "$(dec3 "$e2")"
  fi
  # More seeds of the set: how far one run's theta is from another's.
  ws=$(causes_row 0 "$phi" "$r0" "$d" "$2" 0 2)
  [ -n "$ws" ] || return 0
  n=$(fld "$ws" 6) sd=$(fld "$ws" 13) m=$(fld "$ws" 11)
  # The mean's error: the seeds' standard error, or its fit error if larger.
  se=$(awk "BEGIN { e = $sd / sqrt($n); f = $(fld "$ws" 12); print (f > e) ? f : e }")
  what=$(awk "BEGIN { if ($sd > $4) print \"so one run's theta is uncertain by that, not by its fit error\"; else print \"within one run's fit error\" }")
  printf '; its %s seeds scatter by %s over the same window (%s %s); their mean E(t) gives %s +- %s' \
    "$n" "$(dec3 "$sd")" "$what" "$(dec3 "$4")" "$(dec3 "$m")" "$(dec3 "$se")"
}
for p in $sets; do
  fit=$tables/fit_param_$p.tsv
  name=$(echo "$p" | sed 's/_/, /g; s/^phi/phi = /; s/, r/, r0 = /; s/, d/, delta = /')
  L=$(value "$tables/energy_param_$p.tsv" L '#')
  reg=$(scaling_regime "$tables/energy_param_$p.tsv" "$fit" "$L")
  th=$(value "$fit" theta) the=$(value "$fit" theta_err)
  note="t = $(short "$(value "$fit" t_min)"):$(short "$(value "$fit" t_max)")"
  if [ "$(verdict "$th" "$the" 1.2 0 $tol_theta "$reg")" = differs ]; then
    cause=$(fig2_cause "$p" "$L" "$th" "$the")
    [ -z "$cause" ] || note="$note; $cause"
  fi
  row "theta at $name" 2 "$th" "$the" 1.2 0 $tol_theta "$reg" "$note"
done

# Figs. 3-5: the snapshot run at the late time. tau by the paper's unit cells
# and by particles in contact (pipelines/contact-clusters.mk, tables/contact/):
# N(m) of a definition that spans the box from t = 0 is that of the pieces
# beside one cluster that holds most of the particles, not the paper's regime.
late_regime=$(before_crossover "$late" "$snap_L" "the late time")
contact=$tables/contact
# tau_row NAME TABLES_DIR NOTE
tau_row() {
  f=$(at_time "$2/mmax_$snap.tsv" largest_fraction 0)
  if awk "BEGIN { exit !($f > 0.5) }"; then reg=$(percolates "$f" "$2/mmax_$snap.tsv"); else reg=$late_regime; fi
  row "$1" 3 "$(value "$2/fit_nm_gas.tsv" theta)" "$(value "$2/fit_nm_gas.tsv" theta_err)" 2.7 0 $tol_tau "$reg" \
    "below the largest cluster, m = $(value "$2/fit_nm_gas.tsv" window '#')$3"
}
tau_row "tau, N(m) ~ m^-tau, unit cells" "$tables" ""
if [ -f "$contact/fit_nm_gas.tsv" ]; then
  tau_row "tau, N(m) ~ m^-tau, contact clusters" "$contact" "; particles closer than $(cutoff_of "$contact/mmax_$snap.tsv") sigma \
bonded, the largest cluster holding $(short "$(at_time "$contact/mmax_$snap.tsv" largest_fraction 0)") at t = 0 and \
$(short "$(at_time "$contact/mmax_$snap.tsv" largest_fraction "$late")") at t = $late"
fi
f0=$(at_time "$tables/mmax_$snap.tsv" largest_fraction 0)
# Where the definition percolates at t = 0, the note says so with the
# share at t = 0 and late in every box of the same gas and at the other
# densities (tables/largest_share.tsv, pipelines/theta-causes.mk).
share_cause() {
  st=$tables/largest_share.tsv
  [ -f "$st" ] || return 0
  awk -F '\t' -v phi0="$(value "$tables/mmax_$snap.tsv" phi '#')" '
    function near(a, b) { return (a - b) * (a - b) <= (0.003 * b) * (0.003 * b) }
    function span(lo, hi) { return (sprintf("%.2f", lo) == sprintf("%.2f", hi)) ? sprintf("%.2f", lo) : sprintf("%.2f-%.2f", lo, hi) }
    FNR == 1 || /^#/ || NF == 0 { next }
    near($1, phi0) { if (!k++) { n = $4; a0 = b0 = $5; al = bl = $7; lmin = lmax = $2; tl = th = $6; smin = smax = $7 }
                     if ($6 < tl) tl = $6; if ($6 > th) th = $6
                     if ($5 < a0) a0 = $5; if ($5 > b0) b0 = $5; if ($7 < al) al = $7; if ($7 > bl) bl = $7
                     if ($2 < lmin) { lmin = $2; smin = $7 } if ($2 > lmax) { lmax = $2; smax = $7 }; next }
    $4 < 0.3116 { below = below sprintf("%s%.2g at t = 0 and %.2f at t = %.0f at phi = %.3g (n = %.3f)", below == "" ? "" : ", ", $5, $7, $6, $1, $4) }
    END { if (!k) exit
          dmin = smin - 0.75; dmax = smax - 0.75
          printf "the unit-cell definition spans the box from t = 0 at phi = %.3g (n = %.3f particles per cell, above the site-percolation threshold 0.3116): the largest cluster holds %s at t = 0 and %s at t = %s in every box L = %g-%g (%.2f at L = %g, %.2f at L = %g: %s)", phi0, n, span(a0, b0), span(al, bl), (tl == th) ? sprintf("%.0f", tl) : sprintf("%.0f-%.0f", tl, th), lmin, lmax, smin, lmin, smax, lmax, (dmax * dmax < dmin * dmin - 0.0004) ? "nearer 0.75 in the larger box" : "no nearer 0.75 in the larger box"
          if (below != "") printf "; below the threshold it holds %s", below }' "$st"
}
note="at t = $late"
if awk "BEGIN { exit !($f0 > 0.5) }"; then
  reg=$(percolates "$f0" "$tables/mmax_$snap.tsv")
  cause=$(share_cause)
  [ -z "$cause" ] || note="$note; $cause"
else reg=$late_regime; fi
row "largest cluster's share" 3 "$(at_time "$tables/mmax_$snap.tsv" largest_fraction "$late")" - 0.75 - $tol_share "$reg" "$note"
vs=$tables/velocity_series.tsv
# The velocity rows' notes come from pipelines/velocity-causes.sh (the same
# quantities against t and the tail fit's window, kinetic theory's alpha):
# alpha in velocity_causes.tsv, beta and kappa in velocity_causes_{beta,kappa}.tsv.
va=$tables/velocity_causes.tsv vb=$tables/velocity_causes_beta.tsv vk=$tables/velocity_causes_kappa.tsv
# vc TABLE CONDITION T COLUMN: COLUMN of the row that meets CONDITION (awk, on
# c["name"], the row's value in the column of that name) whose t is nearest T.
vc() {
  awk -F '\t' -v t="$3" -v want="$4" '
    FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    /^#/ { next }
    { for (k in col) c[k] = $col[k] }
    '"$2"' { d = c["t"] - t; if (d < 0) d = -d; if (best == "" || d < best) { best = d; v = c[want] } }
    END { print (v == "" ? "nan" : v) }' "$1"
}
vmeta() { value "$va" "$1" '#'; }
# pm VALUE ERROR: "v +- e" to 3 digits
pm() { awk -v v="$1" -v e="$2" 'BEGIN { if (e == "nan" || e == "") printf "%.3g", v; else printf "%.3g +- %.2g", v, e }'; }
froms=$(vmeta y_froms) f1=${froms%% *} ftail=$(vmeta alpha_from)
# beta: the tool's estimator (ln(-ln Phi) against ln y from y = 1.5) reads a
# Gaussian's -ln Phi = y^2/2 + ln sqrt(2 pi) as y^1.45, and as y^1.67 from y = 2.5:
# the Maxwellian start (t = 0) of the same run at the same window is its reference.
b=$(at_time "$vs" beta "$late") be=$(at_time "$vs" beta_err "$late")
start() { vc "$vb" "c[\"source\"] == 0 && c[\"t\"] == 0 && c[\"y_from\"] == $1" 0 "$2"; }
g=$(start "$f1" beta) ge=$(start "$f1" beta_err)
# The window where the Gaussian start reads nearest the paper's 5/3, and the late beta there.
fg=$(awk -F '\t' 'FNR > 1 && !/^#/ && $1 == 0 && $3 == 0 { d = $6 - 5 / 3; if (d < 0) d = -d; if (b == "" || d < b) { b = d; f = $4 } }
  END { print (f == "" ? "nan" : f) }' "$vb")
late_at() { vc "$vb" "c[\"source\"] == 0 && c[\"y_from\"] == $fg" "$late" "$1"; }
bt=$(late_at beta) bte=$(late_at beta_err) gt=$(start "$fg" beta) gte=$(start "$fg" beta_err)
# What the tail is against the Gaussian start read by the same fit (within 2 errors: Gaussian).
shape=$(awk -v b="$b" -v be="$be" -v g="$g" -v ge="$ge" 'BEGIN {
  if (b == "nan" || g == "nan") { print "too few tail bins"; exit }
  d = b - g; s = sqrt(be * be + ge * ge)
  if (d * d <= 4 * s * s) print "Phi(y) at this time is Gaussian within errors"
  else if (d < 0) print "the tail is overpopulated against the Gaussian"
  else print "the tail is thinner than the Gaussian" }')
row "beta, -ln Phi ~ y^beta" 5 "$b" "$be" 1.66667 0 $tol_beta "$late_regime" \
  "at t = $late, y >= $f1: $shape; the same fit gives $(pm "$g" "$ge") for the Maxwellian start (t = 0)\
$(if [ "$fg" != "$f1" ] && [ "$fg" != nan ] && [ "$bt" != nan ] && [ "$gt" != nan ]; then
  echo "; from y >= $fg, where the Gaussian start reads as y^$(pm "$gt" "$gte"), near 5/3, the late tail gives $(pm "$bt" "$bte")"; fi) \
(tables/velocity_causes_beta.tsv)"
# alpha: the last early dump's tail points (coolgas-velocity --tail) fitted as
# -ln Phi = alpha y + c, weighted by their errors: "alpha err t".
early_alpha() {
  awk -F '\t' '/^# t = / { n = 0; sw = swy = swyy = swl = swyl = 0; t = $0; sub(/^# t = /, "", t); sub(/;.*/, "", t) }
    /^#/ || NF < 4 || $1 == "t" { next }
    { w = 1 / ($4 * $4); sw += w; swy += w * $2; swyy += w * $2 * $2; swl += w * $3; swyl += w * $2 * $3; n++ }
    END { d = sw * swyy - swy * swy; if (n < 3 || d <= 0) { print "nan nan " t; exit }
          printf "%.4g %.2g %s\n", (sw * swyl - swy * swl) / d, sqrt(sw / d), t }' "$1"
}
set -- $(early_alpha "$tables/tail_early.tsv")
# The row: kinetic theory's tail for one component, Phi ~ (y + 1/alpha) exp(-alpha y)
# (velocity-causes.sh), fitted where it fits (y >= VCAUSE_ALPHA_FROM); the
# straight line from y = 1.5 above (the former row) runs through the thermal
# part, still near the Gaussian, and its chi2/dof says so.
te=$3
at_from() { vc "$va" "c[\"y_from\"] == $1" "$te" "$2"; }
a=$(at_from "$ftail" alpha_kt) ae=$(at_from "$ftail" alpha_kt_err) akt=$(vmeta alpha_kinetic_theory)
# The fit's dependence on the window: its range over the windows from y = 2 on at that dump.
tn=$(vc "$va" 1 "$te" t)
spread=$(awk -F '\t' -v t="$tn" 'FNR > 1 && !/^#/ && $1 == t && $2 >= 2 {
    if (lo == "" || $7 < lo) { lo = $7; flo = $2 } if (hi == "" || $7 > hi) { hi = $7; fhi = $2 } }
  END { if (lo != "" && flo != fhi) printf "%.2f (y >= %s) to %.2f (y >= %s)", lo, flo, hi, fhi }' "$va")
theory=$(awk -v a="$a" -v ae="$ae" -v k="$akt" 'BEGIN { if (a == "nan") { print "too few tail bins"; exit }
  printf "kinetic theory (van Noije & Ernst) %.3f, (measured - it)/sigma = %.1f", k, (a - k) / ae }')
chi=$(at_from "$f1" alpha_chi2_dof)
row "alpha, Phi ~ (y + 1/alpha) e^(-alpha y)" 5 "$a" "$ae" 2.65 0 $tol_alpha yes \
  "kinetic theory's one-component tail, y >= $ftail at t = $te; $theory; \
$(if [ -n "$spread" ]; then echo "other windows give $spread; "; fi)the straight fit -ln Phi = alpha y + c from y >= $f1 \
gives $(pm "$1" "$(at_from "$f1" alpha_err)") at chi2/dof $(short "$chi")$(awk -v c="$chi" 'BEGIN { if (c != "nan" && c > 2) \
printf ": -ln Phi is curved there, still near the Gaussian" }') (tables/velocity_causes.tsv)"
# kappa: the error of one run (the delta method over its particles) is far below
# the scatter between seeds once clusters carry the velocities, so the row is
# the seeds' mean of the largest box at its time nearest the late time, with
# its standard error; the snapshot run's own value is in the note.
k=$(at_time "$vs" kappa "$late") ke=$(at_time "$vs" kappa_err "$late")
peak=$(awk -F '\t' 'FNR > 1 && !/^#/ && $1 == 0 && (p == "" || $5 > p) { p = $5; t = $3 } END { printf "%.3g at t = %.3g", p, t }' "$vk")
Lk=$(awk -F '\t' 'FNR > 1 && !/^#/ && $1 == 1 && $2 > m { m = $2 } END { print m + 0 }' "$vk")
seeds=$(awk -F '\t' -v L="$Lk" 'FNR > 1 && !/^#/ && $1 == 1 && $2 == L { n++; printf "%s%.2g +- %.2g at t = %.3g", (n > 1 ? ", " : ""), $5, $6, $3 }' "$vk")
size_at() { vc "$vk" "c[\"source\"] == 1 && c[\"L\"] == $Lk" "$late" "$1"; }
ns=$(size_at seeds) tk=$(size_at t) sv=$(size_at kappa) se=$(size_at kappa_err)
if [ "$ns" = nan ] || [ "$ns" -lt 2 ]; then sv=nan se=nan reg="no: fewer than 2 seeds of one size"
else reg=$(before_crossover "$tk" "$Lk" "the seeds' time"); fi
row "kappa, mean of the seeds at L = $Lk" 5 "$sv" "$se" "> 0" - - "$reg" \
  "at t = $(short "$tk"), $ns seeds; the paper: above 0, saturating; the snapshot run (L = $(vmeta L)) gives $(pm "$k" "$ke") at t = $late, \
after its peak $peak; the seeds' means: $seeds (one component, as the paper's P(v,t) reads v, the same formula gives \
$(short "$(vc "$vk" "c[\"source\"] == 0" "$late" kappa_1)"), 4/3 for a Gaussian; tables/velocity_causes_kappa.tsv)"
smoluchowski="the mean-field Smoluchowski equation with the paper's kernel, solved numerically (no error)"
row "Smoluchowski M_max ~ t^a" S "$(calc "-($(value "$tables/fit_smoluchowski_M_max.tsv" theta))")" - 1.2 0 $tol_smoluchowski yes "$smoluchowski"
row "Smoluchowski M_avg ~ t^a" S "$(calc "-($(value "$tables/fit_smoluchowski_M_avg.tsv" theta))")" - 1.2 0 $tol_smoluchowski yes "$smoluchowski"

# The growing length: L ~ t^(1/z) fitted as L = A t^-theta, so z = -1/theta and
# z_err = theta_err / theta^2 (fit errors, which treat the correlated points of
# one run as independent). The paper has no direct measurement; its z = 5/2
# comes from the E(t) collapse, which the next row compares with (the free
# fit's z): a length measures the coarsening only while it is well inside the
# box, L < L_box/4 at the window's end.
z_coll=$(fc z) z_coll_err=$(fc z_err)
length_regime() {  # lt_table fit_table column L_box
  t_end=$(value "$2" t_max)
  len=$(at_time "$1" "$3" "$t_end")
  if awk "BEGIN { exit !($len < $4 / 4) }"; then echo yes
  else echo "no: box-limited, $3 = $(short "$len") at t = $(short "$t_end") is above L/4 = $(short "$4 / 4")"; fi
}
for r in $structure_runs; do
  lt=$tables/lt_$r.tsv L_box=$(value "$lt" L '#')
  for kind in lt:L_t:"L_t = 2 pi/<k>" lc:L_C:"L_C, the first zero of C(r)"; do
    k=${kind%%:*} col=${kind#*:} col=${col%%:*} what=${kind##*:}
    fit=$tables/fit_${k}_$r.tsv th=$(value "$fit" theta)
    z=$(calc "-1 / ($th)") ze=$(calc "$(value "$fit" theta_err) / (($th) ^ 2)")
    reg=$(length_regime "$lt" "$fit" "$col" "$L_box")
    row "z from $col at L = $L_box" struct "$z" "$ze" 2.5 0 $tol_z "$reg" \
      "$what ~ t^(1/z), t = $(short "$(value "$fit" t_min)"):$(short "$(value "$fit" t_max)"), fit errors"
    # Against the collapse's z: their difference, with the combined error.
    d=$(calc "$z - ($z_coll)") de=$(calc "sqrt(($ze) ^ 2 + ($z_coll_err) ^ 2)")
    if [ "$reg" = yes ] && [ "$collapse_regime" != yes ]; then reg="no: the E(t) collapse, ${collapse_regime#no: }"; fi
    row "z from $col minus the free collapse's z" struct "$d" "$de" 0 0 $tol_z "$reg" "at L = $L_box"
  done
done

# Fig. 4: the rapid growth of M_max in each gas run (pipelines/mmax-jump.sh
# states the rules), the onset of inhomogeneous cooling in the same run, and
# whether the two coincide, as the paper says. Then BA's power law M_max ~ t^a
# and its steepest chord by the gas's rule (the paper: t^0.94 ... t^1.03,
# rising with phi; mean field t^(6/5)).
rise="d ln M_max/d ln t over 0.4 decades (mean field 6/5)"
# jump_rows JUMP_TABLE: the rows of one gas run by the definition of its
# table (tables/jump_mmax_RUN.tsv: unit cells; tables/contact/...: contact).
# The contact rows have names of their own (their definition in them, within
# the table's 50 characters): M_max rise, t_jump and lg(t_jump/t_inhom)
# (lg = log10); t_inhom is the run's own, in the unit cells' rows only.
jump_rows() {
  j=$1
  jv() { value "$j" "$1"; }
  L=$(value "$j" L '#') phi=$(short "$(value "$j" phi '#')")
  s=$(short "$(jv slope_max)") span=$(short "$(jv span)")
  jump_note="$rise; the paper: a rapid increase, a jump by pipelines/mmax-jump.sh's rule (steeper than t^$jump_slope)"
  case $(value "$j" definition '#') in
    contact:*) name="contact, phi = $phi, L = $L" q_rise="M_max rise" q_lg="lg(t_jump/t_inhom)"
      jump_note="$jump_note; particles closer than $(cutoff_of "$j") sigma bonded" ;;
    *) name="gas phi = $phi, L = $L" q_rise="M_max's steepest rise" q_lg="log10(t_jump/t_inhom)" ;;
  esac
  if awk "BEGIN { exit !($(jv fraction_0) > 0.5) }"; then
    row "$q_rise, $name" 4 "$s" - "> $jump_slope" - - "$(percolates "$(jv fraction_0)" "$j")" "$jump_note"
    return
  fi
  if [ "$(jv jump)" = 1 ]; then jump_reg=$(before_crossover "$(jv t_jump)" "$L" "the jump")
  elif awk "BEGIN { exit !($span > 0.5) }"; then jump_reg="no: dumps $span decades apart cannot resolve a jump (the rule needs 5 dumps a decade)"
  else jump_reg="no: no jump within the run (t <= $(short "$(jv t_end)")): M_max grows at most as t^$s, below the rule's t^2"; fi
  row "$q_rise, $name" 4 "$s" - "> $jump_slope" - - "$jump_reg" "$jump_note"
  row "t_jump, $name" 4 "$(short "$(jv t_jump)")" - - - - "$jump_reg" \
    "the centre of the steepest rise: M_max/N $(short "$(jv fraction_from)") to $(short "$(jv fraction_to)") over t = $(short "$(jv t_from)"):$(short "$(jv t_to)")"
  peak=$(short "$(jv theta_peak)")
  if [ "$(jv inhom)" = 1 ]; then inhom_reg=yes
  elif awk "BEGIN { exit !($peak < 1.5) }"; then inhom_reg="no: E(t) never falls faster than t^-3/2 (at most t^-$peak): no Haff regime to leave"
  else inhom_reg="no: E(t) still falls faster than t^-3/2 at the run's end (a lower bound)"; fi
  [ "$q_rise" = "M_max rise" ] || row "t_inhom, $name" 4 "$(short "$(jv t_inhom)")" - - - - "$inhom_reg" \
    "E(t) leaves Haff's law: -d ln E/d ln t below 3/2 after its peak $peak"
  # Resolution: t_jump sits on the dumps' grid, so half a dump spacing (the
  # chord is two); the paper's "coincide" can mean no more than that, so it
  # is the tolerance too.
  d=$(calc "log($(jv t_jump) / $(jv t_inhom)) / log(10)") de=$(calc "$(jv span) / 4")
  if [ "$jump_reg" = yes ] && [ "$inhom_reg" != yes ]; then reg=$inhom_reg; else reg=$jump_reg; fi
  row "$q_lg, $name" 4 "$d" "$de" 0 0 "$de" "$reg" \
    "log10 of t_jump/t_inhom; the paper: they coincide; error and tolerance half a dump spacing; t_jump/t_inhom = $(short "10 ^ $d")"
}
for r in $mmax_runs; do
  jump_rows "$tables/jump_mmax_$r.tsv"
  [ ! -f "$contact/jump_mmax_$r.tsv" ] || jump_rows "$contact/jump_mmax_$r.tsv"
done
for r in $ba_mmax; do
  fit=$tables/fit_mmax_$r.tsv phi=$(short "$(value "$tables/jump_mmax_$r.tsv" phi '#')")
  row "a_BA, M_max ~ t^a, BA phi = $phi" 4 "$(calc "-($(value "$fit" theta))")" "$(value "$fit" theta_err)" - - - yes \
    "t = $(short "$(value "$fit" t_min)"):$(short "$(value "$fit" t_max)"); the paper: 0.94 to 1.03 over its phi"
  row "M_max's steepest rise, BA phi = $phi" 4 "$(short "$(value "$tables/jump_mmax_$r.tsv" slope_max)")" - "< $jump_slope" - - yes \
    "$rise, the gas's rule; the paper: a power law t^0.94 to t^1.03, so no chord as steep as a jump (t^$jump_slope)"
  fit=$tables/fit_mavg_$r.tsv
  row "M_avg ~ t^a, BA phi = $phi" 4 "$(calc "-($(value "$fit" theta))")" "$(value "$fit" theta_err)" - - - yes \
    "the mean aggregate mass, t = $(short "$(value "$fit" t_min)"):$(short "$(value "$fit" t_max)"); the paper: 1.06 at phi = 0.005 to 1.19 at 0.313"
done

# BA's velocity tail at its last tail time (the block header's beta of coolgas-velocity --tail).
if [ -f "$tables/tail_ba.tsv" ]; then
  set -- $(sed -n 's/^# t = \([^;]*\);.*beta = \([^ ]*\) +- \([^ ]*\) .*/\1 \2 \3/p' "$tables/tail_ba.tsv" | tail -n 1)
  row "beta_BA, -ln Phi ~ y^beta" 5 "$(short "$2")" "$(short "$3")" 0.70 0 $tol_beta yes \
    "at t = $(short "$1"), phi = $(short "$(value "$tables/tail_ba.tsv" phi '#')"); the paper: 0.70, not 2/theta_BA"
fi

# BA's cluster-size distribution below its mean mass (the gas's tau row is Fig. 3's other half).
if [ -f "$tables/fit_nm_ba.tsv" ]; then
  fit=$tables/fit_nm_ba.tsv
  row "tau_BA, N(m) ~ m^-tau" 3 "$(value "$fit" theta)" "$(value "$fit" theta_err)" 0.2 0 $tol_tau yes \
    "m = 1 to M_avg = $(short "$(value "$fit" t_max)") at t = $(short "$(sed -n 's/^# time: //p' "$tables/nm_ba.tsv" | tail -n 1)"); the paper: 0.2, then an exponential tail"
fi

# Ballistic aggregation: the paper gives theta_BA = 1.283 +- 0.005 at phi = 0.005 and 1.206 +- 0.005 at 0.208.
# A row that differs says why, from the aggregation runs of several boxes and
# seeds in tables/theta_causes.tsv (pipelines/theta-causes.mk).
ba_cause() {  # fit
  [ -f "$causes" ] || return 0
  L=$(value "$(echo "$1" | sed 's,fit_energy_ba_,energy_ba_,')" L '#')
  awk -F '\t' -v L="$L" '
    FNR == 1 || /^#/ || NF == 0 || $1 != 1 { next }
    $7 == 0 { same = same sprintf("%s%.3f at L = %g (%d run%s)", same == "" ? "" : ", ", $11, $5, $6, $6 > 1 ? sprintf("s, single runs scatter by %.3f", $13) : "")
              if ($5 == L) { lo = $8; hi = $9 }
              if (nb++ == 0 || $11 < mn) mn = $11; if (nb == 1 || $11 > mx) mx = $11; if ($12 > me) me = $12 }
    $7 == 4 && $5 == L { own_end = $9 }
    $7 == 4 && $9 > tend { tend = $9; th = $11; te = $12; tl = $5; tlo = $8 }
    END { if (same == "") exit
          trend = (nb < 2) ? "" : (mx - mn <= 3 * me) ? ": no trend with L" : ": it changes with L"
          printf "because theta_BA depends on where the window ends, and it ends at t = %.3g%s: over t = %g:%g the mean E(t) of each box gives %s%s; to t = %g (L = %g) theta_BA = %.3f +- %.3f (tables/theta_causes.tsv)",
            hi, (own_end != "" && own_end <= 1.01 * hi) ? ", where this box'"'"'s run ends (its aggregates must stay narrower than about L/2)" : "", lo, hi, same, trend, tend, tl, th, te }' "$causes"
}
for fit in $ba_fits; do
  phi=$(basename "$fit" .tsv | sed 's/^fit_energy_ba_phi//; s/_s[0-9]*$//')
  case $phi in 0.208) paper=1.206 pe=0.005 ;; 0.005) paper=1.283 pe=0.005 ;; *) paper=- pe=- ;; esac
  th=$(value "$fit" theta) the=$(value "$fit" theta_err)
  tol=$tol_theta; [ "$paper" != - ] || tol=-
  note="t = $(short "$(value "$fit" t_min)"):$(short "$(value "$fit" t_max)")"
  if [ "$(verdict "$th" "$the" "$paper" "$pe" "$tol" yes)" = differs ]; then
    cause=$(ba_cause "$fit")
    [ -z "$cause" ] || note="$note; $cause"
  fi
  row "theta_BA at phi = $phi" BA "$th" "$the" "$paper" "$pe" "$tol" yes "$note"
done
