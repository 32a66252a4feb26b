# Paper Fig. 4: the largest cluster mass M_max(t)/N (coolgas-clusters --series)
# for the gas (each table one run: the snapshot run and the runs of Fig. 2a)
# and, when ba is not empty, for ballistic aggregation.
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
ng = words(gas); nb = words(ba)

eval term(1300, 750)
set output out
if (!exists("ba_window")) ba_window = ""
set title sprintf("Largest cluster M_{max}(t): gas (r_0 = %s, {/Symbol d} = %s)%s\n" . \
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
array g_N[ng]; array g_f0[ng]; array g_jump[ng]; array g_s[ng]; array g_tj[ng]; array g_lo[ng]; array g_hi[ng]
array g_flo[ng]; array g_inhom[ng]; array g_ti[ng]
do for [i = 1 : ng] {
  t = word(gas, i); j = beside(t, "jump")
  g_N[i] = Nof(t); g_f0[i] = tsvval(j, "fraction_0"); g_jump[i] = tsvval(j, "jump"); g_s[i] = tsvval(j, "slope_max")
  g_tj[i] = tsvval(j, "t_jump"); g_lo[i] = tsvval(j, "t_from"); g_hi[i] = tsvval(j, "t_to")
  g_flo[i] = tsvval(j, "fraction_from"); g_inhom[i] = tsvval(j, "inhom"); g_ti[i] = tsvval(j, "t_inhom")
  # the open circle's place: a one-point data block
  eval sprintf("set print $inhom%d", i); print sprintf("%.9g %.9g", g_ti[i], tsvval(j, "fraction_inhom")); unset print
}
array b_N[nb > 0 ? nb : 1]; array b_a[nb > 0 ? nb : 1]; array b_ae[nb > 0 ? nb : 1]; array b_A[nb > 0 ? nb : 1]
array b_lo[nb > 0 ? nb : 1]; array b_hi[nb > 0 ? nb : 1]
do for [i = 1 : nb] {
  t = word(ba, i); f = beside(t, "fit")
  b_N[i] = Nof(t); b_a[i] = -tsvval(f, "theta"); b_ae[i] = tsvval(f, "theta_err"); b_A[i] = tsvval(f, "A")
  b_lo[i] = tsvval(f, "t_min"); b_hi[i] = tsvval(f, "t_max")
}
data(list, i, style, what) = "word(" . list . ", " . i . ") using 1:($1 > 0 ? $6 / " . sprintf("%.17g", \
  (list eq "gas" ? g_N[i] : b_N[i])) . " : NaN) with linespoints ls " . style . " title " . q(what)
# gas run i: its curve, then (when the rule finds a jump) the chord of its
# steepest rise, translucent over the points, and (when E(t) left Haff's
# law) the open circle.
gas_curve(i) = data("gas", i, i, "gas " . label(word(gas, i)) . (g_f0[i] > 0.5 ? " (percolates at t = 0)" : "")) . \
  (g_jump[i] == 1 ? sprintf(", [%.9g:%.9g] %.9g * (x / %.9g)**%.9g with lines lc rgb '#70%s' lw 7 dt 1 title %s", \
     g_lo[i], g_hi[i], g_flo[i], g_lo[i], g_s[i], style_rgb[i][2:7], qq(sprintf("  steepest rise t^{%.1f}, t_{jump} = %.0f", g_s[i], g_tj[i]))) : "") . \
  (g_inhom[i] == 1 ? sprintf(", $inhom%d using 1:2 with points ls %d pt 6 ps 3 lw 2 title %s", i, i, \
     qq(sprintf("  E(t) leaves Haff's law: t = %.0f", g_ti[i]))) : "")
ba_curve(i) = data("ba", i, ng + i, "BA " . label(word(ba, i))) . \
  sprintf(", [%.9g:%.9g] %.9g * x**%.9g / %.9g with lines ls %d lw 1 dt 1 title %s", b_lo[i], b_hi[i], b_A[i], b_a[i], \
     b_N[i], ng + i, q(sprintf("  fit t^{%.2f ± %.2f}", b_a[i], b_ae[i])))
curves = ""
do for [i = 1 : ng] { curves = curves . (i > 1 ? ", " : "") . gas_curve(i) }
do for [i = 1 : nb] { curves = curves . ", " . ba_curve(i) }
# A share of the particles: at most 1 (a fit line past it is cut there); the
# lower end just below the smallest share drawn.
set yrange [*:1]
set autoscale yfixmin
set offsets 0, 0, 0, graph 0.03
eval "plot " . curves
