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
# curve(P, list, i, style, kind): run i of list (arrays P_*) and, right after
# it in the key, its fit over its window.
curve(P, list, i, style, kind) = "word(" . list . ", " . i . ") using 1:($1 > 0 ? $6 / " . P . "_N[" . i . "] : NaN) " . \
  "with linespoints ls " . style . " title sprintf('" . kind . " %s', label(word(" . list . ", " . i . "))), " . \
  "[" . P . "_lo[" . i . "]:" . P . "_hi[" . i . "]] " . P . "_A[" . i . "] * x**" . P . "_a[" . i . "] / " . P . "_N[" . i . "] " . \
  "with lines ls " . style . " lw 1 dt 1 title sprintf('  fit t^{%.2f ± %.2f}', " . P . "_a[" . i . "], " . P . "_ae[" . i . "])"
curves = ""
do for [i = 1 : ng] { curves = curves . (i > 1 ? ", " : "") . curve("g", "gas", i, i, "gas") }
do for [i = 1 : nb] { curves = curves . ", " . curve("b", "ba", i, ng + i, "BA") }
# A share of the particles: at most 1 (a fit line past it is cut there).
set yrange [*:1]
eval "plot " . curves
