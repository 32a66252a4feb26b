# What accuracy costs in coolgas-collapse: (a) z and (b) theta of the collapse
# of n seeds per L (one table per run, so the errors are the jackknife over
# whole runs) against n; (c) those errors against the core-seconds of the runs
# used, with lines falling as 1/sqrt(seeds).
# gnuplot -e "in='collapse_accuracy.tsv'; out='collapse_accuracy.png'" collapse_accuracy.gp
plots = system("dirname " . ARG0)
load plots . "/common.gp"
eval term(1800, 620)
set output out
set multiplot layout 1, 3 title sprintf("coolgas-collapse --optimize of n seeds per L: the error and its cost (L = %s, runs to x = t/L^{5/2} = %s, {/Symbol d} = %s)", \
    meta(in, "L"), meta(in, "x_end"), meta(in, "delta"))
set grid
set key below
set logscale x 2
set xlabel "seeds per L"
set offsets graph 0.08, graph 0.08, graph 0.1, graph 0.1
# columns: 1 seeds, 2 theta, 3 theta_err, 4 z, 5 z_err, 6 quality, 7 cpu_s
set title "(a) z ± jackknife error over whole runs"
set ylabel "dynamical exponent z"
plot in using 1:4:5:xtic(1) with yerrorlines ls 1 title "z of the collapse", \
     2.5 with lines ls 7 lw 2 dt 3 title "5/2 (paper)"
set title "(b) {/Symbol q} ± jackknife error over whole runs"
set ylabel "energy exponent {/Symbol q}"
plot in using 1:2:3:xtic(1) with yerrorlines ls 2 title "{/Symbol q} of the collapse", \
     1.2 with lines ls 7 lw 2 dt 3 title "6/5 (paper)"

set title "(c) error against cost"
set logscale xy
set autoscale fix
set offsets graph 0.05, graph 0.15, graph 0.15, graph 0.15
set xtics auto
set xtics add (2, 5, 20, 50, 200, 500)
set ytics add (0.002, 0.005, 0.02, 0.05, 0.2, 0.5)
set format y "%g"
set xlabel "core-seconds of the runs used  [CPU s]"
set ylabel "jackknife standard error"
# The guides start at the fewest seeds and fall as 1/sqrt(seeds), i.e. as
# 1/sqrt(cost): the cost grows in proportion to the seeds.
first(col) = real(system("awk 'NR > 1 && !/^#/ { print $" . col . "; exit }' " . q(in)))
c0 = first(7); z0 = first(5); t0 = first(3)
plot in using 7:5 with linespoints ls 1 title "{/Symbol s}_z", \
     z0 * sqrt(c0 / x) with lines ls 1 lw 1 dt 3 title "{/Symbol s}_z ∝ 1/√seeds", \
     in using 7:3 with linespoints ls 2 title "{/Symbol s}_{/Symbol q}", \
     t0 * sqrt(c0 / x) with lines ls 2 lw 1 dt 3 title "{/Symbol s}_{/Symbol q} ∝ 1/√seeds", \
     in using 7:5:(sprintf("%d", $1)) with labels left offset char 0.6, char 0.8 font ",9" notitle, \
     in using 7:3:(sprintf("%d", $1)) with labels left offset char 0.6, char 0.8 font ",9" notitle
unset multiplot
