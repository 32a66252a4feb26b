# Paper Fig. 5: scaled velocity distribution Phi(y), y = v/v_rms, at early
# (homogeneous) and late (clustered) times against the Gaussian; inset: the
# kurtosis kappa(t) (b); (c): -ln Phi(y) for y >= tail_from with the fit
# c y^beta (coolgas-velocity --tail), gas and, if tail_ba is set, BA.
plots = system("dirname " . ARG0)
load plots . "/common.gp"
has_ba = strlen(tail_ba) > 0
bt(f, i) = bfield(f, i, "t")
bbeta(f, i) = bfield(f, i, "beta")
ne = nblocks(early); nl = nblocks(late); nt = nblocks(tail_gas)
gauss(y) = exp(-y**2 / 2) / sqrt(2 * pi)

eval term(1800, 600)
set output out
set multiplot layout 1, 3 title sprintf("Velocity distribution of the granular gas (L = %s, N = %s, {/Symbol f} = %.3f, r_0 = %s)", meta(early, "L"), meta(early, "N"), real(meta(early, "phi")), meta(early, "r0"))

set title "(a) scaled distribution {/Symbol F}(y) of one velocity component"
set logscale y
set format y "10^{%L}"
set grid
set key bottom center font ",10"
set xlabel "y = v_{/Symbol a} / v_{rms}"
set ylabel "{/Symbol F}(y)"
set yrange [1e-6:1]
set xrange [-7:7]
plot for [i = 1 : ne] early index (i - 1) using 2:3 with points ls i ps 0.6 title sprintf("t = %s (early)", bt(early, i)), \
     for [i = 1 : nl] late index (i - 1) using 2:3 with points ls (ne + i) ps 0.6 title sprintf("t = %s (late)", bt(late, i)), \
     gauss(x) with lines lw 2 lc rgb "black" title "Gaussian"

set title "(b) kurtosis {/Symbol k} = <v^4>/<v^2>^2 - 5/3"
set logscale x; unset logscale y
set format x "10^{%L}"; set format y "%g"
set xrange [0.01:*]; set yrange [*:*]
set key top right
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "{/Symbol k}(t)"
plot series using 1:($1 > 0 ? $3 : NaN):4 with yerrorlines pt 7 ps 0.6 lc rgb "black" title "gas", \
     0 with lines dt 2 lc rgb "gray40" title "Gaussian"

set title sprintf("(c) tails: -ln {/Symbol F}(y) ∝ y^{/Symbol b}%s", has_ba ? " (gas and BA)" : "")
set logscale xy
set format x "%g"; set format y "%g"
set key top left font ",10"
# axes fitted to the data (a decade each way would leave two tick labels)
stats tail_gas using 2:3 nooutput
ylo = STATS_min_x; yhi = STATS_max_x; flo = STATS_min_y; fhi = STATS_max_y
if (has_ba) { stats tail_ba using 2:3 nooutput; ylo = (STATS_min_x < ylo ? STATS_min_x : ylo); yhi = (STATS_max_x > yhi ? STATS_max_x : yhi); \
              flo = (STATS_min_y < flo ? STATS_min_y : flo); fhi = (STATS_max_y > fhi ? STATS_max_y : fhi) }
set xrange [ylo / 1.08 : yhi * 1.08]; set yrange [flo / 1.15 : fhi * 1.15]
set xtics ("1" 1, "1.5" 1.5, "2" 2, "2.5" 2.5, "3" 3, "4" 4, "5" 5, "6" 6, "8" 8, "10" 10)
set ytics ("0.5" 0.5, "1" 1, "1.5" 1.5, "2" 2, "3" 3, "4" 4, "5" 5, "6" 6, "8" 8, "10" 10, "15" 15, "20" 20, "30" 30)
set xlabel "y = |v_{/Symbol a}| / v_{rms}"
set ylabel "-ln {/Symbol F}(y)"
plot for [i = 1 : nt] tail_gas index (i - 1) using 2:3:4 with yerrorbars ls i ps 0.6 title sprintf("gas t = %s", bt(tail_gas, i)), \
     for [i = 1 : nt] tail_gas index (i - 1) using 2:5 with lines ls i title sprintf("fit {/Symbol b} = %.2f", real(bbeta(tail_gas, i))), \
     (has_ba ? tail_ba : tail_gas) index 0 using 2:(has_ba ? $3 : NaN) with points ls 7 ps 0.7 title (has_ba ? "BA" : "")
unset multiplot
