# Paper Fig. 4: the largest cluster mass M_max(t) (coolgas-clusters --series)
# for the gas (each table one run: the snapshot run and the runs of Fig. 2a)
# and, when ba is not empty, for ballistic aggregation, with power-law fits
# over window (coolgas-fit tables beside them: mmax_X.tsv -> fit_mmax_X.tsv).
plots = system("dirname " . ARG0)
load plots . "/common.gp"
fitof(t) = system("echo " . q(t) . " | sed 's,/mmax_,/fit_mmax_,'")
a(t) = -tsvval(fitof(t), "theta")
ae(t) = tsvval(fitof(t), "theta_err")
A(t) = tsvval(fitof(t), "A")
lo(t) = tsvval(fitof(t), "t_min")
hi(t) = tsvval(fitof(t), "t_max")
label(t) = sprintf("L = %s, {/Symbol f} = %.3f", meta(t, "L"), real(meta(t, "phi")))
Nof(t) = real(meta(t, "N"))
ng = words(gas); nb = words(ba)

eval term(1300, 700)
set output out
if (!exists("ba_window")) ba_window = ""
set title sprintf("Largest cluster M_{max}(t): gas (r_0 = %s, {/Symbol d} = %s)%s; lines: power-law fits over t = %s%s", \
    meta(word(gas, 1), "r0"), meta(word(gas, 1), "delta"), (nb > 0 ? " and ballistic aggregation" : ""), window, \
    (nb > 0 ? " (BA: ".ba_window.")" : ""))
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set grid
set key outside right top
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "M_{max}(t) / N  (largest cluster's share of the particles)"
set xrange [0.01:*]
# read_fits: for each table of `tables` (prefix P), its N and its fit into
# arrays P_N, P_a, P_ae, P_A, P_lo, P_hi, read once: a function of the file
# in the plot command would run its shell commands at every point (minutes).
read_fits(P) = "n = words(tables); array ".P."_N[n]; array ".P."_a[n]; array ".P."_ae[n]; " . \
  "array ".P."_A[n]; array ".P."_lo[n]; array ".P."_hi[n]; do for [i = 1 : n] { t = word(tables, i); " . \
  P."_N[i] = Nof(t); ".P."_a[i] = a(t); ".P."_ae[i] = ae(t); ".P."_A[i] = A(t); ".P."_lo[i] = lo(t); ".P."_hi[i] = hi(t) }"
tables = gas; eval read_fits("g")
tables = ba; if (nb > 0) { eval read_fits("b") }
gas_curves = "for [i = 1 : ng] word(gas, i) using 1:($1 > 0 ? $6 / g_N[i] : NaN) with linespoints ls i title sprintf('gas %s', label(word(gas, i))), \
  for [i = 1 : ng] [g_lo[i]:g_hi[i]] g_A[i] * x**g_a[i] / g_N[i] with lines ls i lw 1 dt 1 title sprintf('  fit t^{%.2f ± %.2f}', g_a[i], g_ae[i])"
ba_curves = "for [i = 1 : nb] word(ba, i) using 1:($1 > 0 ? $6 / b_N[i] : NaN) with linespoints ls (ng + i) title sprintf('BA %s', label(word(ba, i))), \
  for [i = 1 : nb] [b_lo[i]:b_hi[i]] b_A[i] * x**b_a[i] / b_N[i] with lines ls (ng + i) lw 1 dt 1 title sprintf('  fit t^{%.2f ± %.2f}', b_a[i], b_ae[i])"
if (nb > 0) {
  eval "plot " . gas_curves . ", " . ba_curves
} else {
  eval "plot " . gas_curves
}
