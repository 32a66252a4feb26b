# Paper Fig. 4: the largest cluster mass M_max(t)/N (coolgas-clusters --series)
# for the gas (each table one run: the snapshot run and the runs of Fig. 2a)
# and, when ba is not empty, for ballistic aggregation. When contact is not
# empty (the same gas runs by coolgas-clusters --definition contact), a second
# panel shows the gas by that definition under the paper's unit cells (BA's
# aggregates, the same by either, in both).
# The gas's M_max jumps rather than growing as a power law: each gas curve
# gets its steepest rise over 0.4 decades drawn as a thick chord over its
# span and an open circle where the same run's E(t) leaves Haff's law
# (pipelines/mmax-jump.sh: mmax_X.tsv -> jump_mmax_X.tsv). BA curves get
# their power-law fits over ba_window (coolgas-fit: mmax_X.tsv -> fit_mmax_X.tsv).
plots = system("dirname " . ARG0)
load plots . "/common.gp"
beside(t, kind) = system("echo " . q(t) . " | sed 's,/mmax_,/" . kind . "_mmax_,'")
qq(s) = '"' . s . '"'  # for titles with an apostrophe
label(t) = sprintf("L = %s, {/Symbol f} = %.3f", meta(t, "L"), real(meta(t, "phi")))
Nof(t) = real(meta(t, "N"))
if (!exists("contact")) contact = ""
ng = words(gas); nb = words(ba); panels = words(contact) > 0 ? 2 : 1
eval term(1300, panels == 2 ? 1450 : 750)
set output out
if (!exists("ba_window")) ba_window = ""
set multiplot layout panels, 1 title sprintf("Largest cluster M_{max}(t): gas (r_0 = %s, {/Symbol d} = %s)%s\n" . \
    "gas, no power-law fit: thick = a jump (steepest rise over 0.4 decades, slope {/Symbol \263} 2), circle = E(t) leaves Haff's law%s", \
    meta(word(gas, 1), "r0"), meta(word(gas, 1), "delta"), (nb > 0 ? " and ballistic aggregation (BA)" : ""), \
    (nb > 0 ? "\nBA: power-law fits over t = ".ba_window : ""))
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set grid
set key outside right top Left reverse
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "M_{max}(t) / N  (largest cluster's share of the particles)"
set xrange [0.01:*]
# Each table's numbers are read once into arrays: a function of the file in
# the plot command would run its shell commands at every point (minutes).
# Gas run i's table by the unit cells is k = i, by contact k = ng + i.
ngk = panels * ng
gas_list(k) = k <= ng ? "gas" : "contact"
gas_index(k) = k <= ng ? k : k - ng
array g_N[ngk]; array g_f0[ngk]; array g_jump[ngk]; array g_s[ngk]; array g_tj[ngk]; array g_lo[ngk]; array g_hi[ngk]
array g_flo[ngk]; array g_inhom[ngk]; array g_ti[ngk]
do for [k = 1 : ngk] {
  t = word(k <= ng ? gas : contact, gas_index(k)); j = beside(t, "jump")
  g_N[k] = Nof(t); g_f0[k] = tsvval(j, "fraction_0"); g_jump[k] = tsvval(j, "jump"); g_s[k] = tsvval(j, "slope_max")
  g_tj[k] = tsvval(j, "t_jump"); g_lo[k] = tsvval(j, "t_from"); g_hi[k] = tsvval(j, "t_to")
  g_flo[k] = tsvval(j, "fraction_from"); g_inhom[k] = tsvval(j, "inhom"); g_ti[k] = tsvval(j, "t_inhom")
  # the open circle's place: a one-point data block
  eval sprintf("set print $inhom%d", k); print sprintf("%.9g %.9g", g_ti[k], tsvval(j, "fraction_inhom")); unset print
}
array b_N[nb > 0 ? nb : 1]; array b_a[nb > 0 ? nb : 1]; array b_ae[nb > 0 ? nb : 1]; array b_A[nb > 0 ? nb : 1]
array b_lo[nb > 0 ? nb : 1]; array b_hi[nb > 0 ? nb : 1]
do for [i = 1 : nb] {
  t = word(ba, i); f = beside(t, "fit")
  b_N[i] = Nof(t); b_a[i] = -tsvval(f, "theta"); b_ae[i] = tsvval(f, "theta_err"); b_A[i] = tsvval(f, "A")
  b_lo[i] = tsvval(f, "t_min"); b_hi[i] = tsvval(f, "t_max")
}
data(list, i, N, style, what) = "word(" . list . ", " . i . ") using 1:($1 > 0 ? $6 / " . sprintf("%.17g", N) . \
  " : NaN) with linespoints ls " . style . " title " . q(what)
# gas table k: its curve, then (when the rule finds a jump) the chord of its
# steepest rise, translucent over the points, and (when E(t) left Haff's
# law) the open circle.
gas_curve(k, i) = data(gas_list(k), i, g_N[k], i, "gas " . label(word(gas, i)) . (g_f0[k] > 0.5 ? " (percolates at t = 0)" : "")) . \
  (g_jump[k] == 1 ? sprintf(", [%.9g:%.9g] %.9g * (x / %.9g)**%.9g with lines lc rgb '#70%s' lw 7 dt 1 title %s", \
     g_lo[k], g_hi[k], g_flo[k], g_lo[k], g_s[k], style_rgb[i][2:7], qq(sprintf("  steepest rise t^{%.1f}, t_{jump} = %.0f", g_s[k], g_tj[k]))) : "") . \
  (g_inhom[k] == 1 ? sprintf(", $inhom%d using 1:2 with points ls %d pt 6 ps 3 lw 2 title %s", k, i, \
     qq(sprintf("  E(t) leaves Haff's law: t = %.0f", g_ti[k]))) : "")
ba_curve(i) = data("ba", i, b_N[i], ng + i, "BA " . label(word(ba, i))) . \
  sprintf(", [%.9g:%.9g] %.9g * x**%.9g / %.9g with lines ls %d lw 1 dt 1 title %s", b_lo[i], b_hi[i], b_A[i], b_a[i], \
     b_N[i], ng + i, q(sprintf("  fit t^{%.2f ± %.2f}", b_a[i], b_ae[i])))
# A share of the particles: at most 1 (a fit line past it is cut there); the
# lower end just below the smallest share drawn.
set yrange [*:1]
set autoscale yfixmin
set offsets 0, 0, 0, graph 0.03
# Both panels' axes over the same width, whatever their keys' widths.
if (panels == 2) { set lmargin at screen 0.08; set rmargin at screen 0.62 }
do for [p = 1 : panels] {
  if (panels == 2) {
    set title (p == 1 ? "(a) the paper's unit cells" : \
      sprintf("(b) particles in contact (bonded closer than %s {/Symbol s})", word(meta(word(contact, 1), "contact"), 4)))
  }
  curves = ""
  do for [i = 1 : ng] { curves = curves . (i > 1 ? ", " : "") . gas_curve((p - 1) * ng + i, i) }
  do for [i = 1 : nb] { curves = curves . ", " . ba_curve(i) }
  eval "plot " . curves
}
unset multiplot
