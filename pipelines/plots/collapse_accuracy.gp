# What accuracy costs in coolgas-collapse: (a) z and (b) theta of the collapse
# of n seeds per L (one table per run, so the errors are the jackknife over
# whole runs) against n, one curve per set of sizes; (c) those errors against
# the core-seconds of the runs used, with lines falling as 1/sqrt(seeds);
# (d) z of the first set's runs cut at x_end = t/L^(5/2), against x_end.
# gnuplot -e "in='collapse_accuracy.tsv'; tend='collapse_tend.tsv'; out='collapse_accuracy.png'" collapse_accuracy.gp
plots = system("dirname " . ARG0)
load plots . "/common.gp"
eval term(1500, 1150)
set output out
sets = meta(in, "sets")
nsets = words(sets)
# a set's name '20-27-34' as 'L = 20, 27, 34'
sizes(s) = "L = " . system("echo " . s . " | sed 's/-/, /g'")
# the column c of the first row of set s (the fewest seeds)
first(s, c) = real(system("awk -F '\t' '$1 == \"" . s . "\" { print $" . c . "; exit }' " . q(in)))
set multiplot layout 2, 2 title sprintf("coolgas-collapse --optimize of n seeds per L: the error and its cost (runs to x = t/L^{5/2} = %s, {/Symbol d} = %s)", \
    meta(in, "x_end"), meta(in, "delta"))
set grid
set key below
set logscale x 2
set xtics (2, 3, 4, 6, 8, 12, 16)
set xlabel "seeds per L"
set offsets graph 0.08, graph 0.08, graph 0.1, graph 0.1
# columns: 1 sizes, 2 seeds, 3 theta, 4 theta_err, 5 z, 6 z_err, 7 quality, 8 cpu_s
set title "(a) z ± jackknife error over whole runs"
set ylabel "dynamical exponent z"
plot for [i = 1:nsets] in using 2:(strcol(1) eq word(sets, i) ? $5 : NaN):6 with yerrorlines ls i title sizes(word(sets, i)), \
     2.5 with lines ls 7 lw 2 dt 3 title "5/2 (paper)"
set title "(b) {/Symbol q} ± jackknife error over whole runs"
set ylabel "energy exponent {/Symbol q}"
plot for [i = 1:nsets] in using 2:(strcol(1) eq word(sets, i) ? $3 : NaN):4 with yerrorlines ls i title sizes(word(sets, i)), \
     1.2 with lines ls 7 lw 2 dt 3 title "6/5 (paper)"

set title "(c) error against cost (labels: seeds per L)"
set logscale xy
set autoscale fix
set offsets graph 0.05, graph 0.15, graph 0.15, graph 0.15
set xtics auto
set xtics add (2, 5, 20, 50, 200, 500)
set ytics add (0.002, 0.005, 0.02, 0.05, 0.2, 0.5, 2, 5)
set format y "%g"
set xlabel "core-seconds of the runs used  [CPU s]"
set ylabel "jackknife standard error"
set key below maxrows 3
# The guides start at the fewest seeds and fall as 1/sqrt(seeds), i.e. as
# 1/sqrt(cost): the cost grows in proportion to the seeds. Styles: z of set i
# is line style i, theta of set i line style nsets + i.
array c0[nsets]; array z0[nsets]; array t0[nsets]
do for [i = 1:nsets] { c0[i] = first(word(sets, i), 8); z0[i] = first(word(sets, i), 6); t0[i] = first(word(sets, i), 4) }
plot for [i = 1:nsets] in using 8:(strcol(1) eq word(sets, i) ? $6 : NaN) with linespoints ls i \
       title sprintf("{/Symbol s}_z, %s", sizes(word(sets, i))), \
     for [i = 1:nsets] in using 8:(strcol(1) eq word(sets, i) ? $4 : NaN) with linespoints ls nsets + i \
       title sprintf("{/Symbol s}_{/Symbol q}, %s", sizes(word(sets, i))), \
     for [i = 1:nsets] z0[i] * sqrt(c0[i] / x) with lines ls i lw 1 dt 3 \
       title (i == 1 ? "∝ 1/√seeds from the fewest seeds" : ""), \
     for [i = 1:nsets] t0[i] * sqrt(c0[i] / x) with lines ls nsets + i lw 1 dt 3 notitle, \
     in using 8:6:(sprintf("%d", $2)) with labels left offset char 0.6, char 0.8 font ",9" notitle

set title sprintf("(d) z against the runs' end, %s, %s seeds each (labels: CPU s)", sizes(meta(tend, "sizes")), \
    system("awk -F '\t' 'NR > 1 && !/^#/ { print $2; exit }' " . q(tend)))
unset logscale y
set logscale x
set autoscale
set autoscale xfix
set offsets graph 0.1, graph 0.15, graph 0.1, graph 0.1
set xtics (1, 2, 3, 5, 10, 20, 30)
set format y "%g"
set xlabel "x_{end} = t_{end}/L^{5/2} of the runs"
set ylabel "dynamical exponent z"
set key below maxrows 1
# columns: 1 x_end, 2 seeds, 3 theta, 4 theta_err, 5 z, 6 z_err, 7 quality, 8 cpu_s
plot tend using 1:5:6 with yerrorlines ls 1 title "z ± jackknife error over whole runs", \
     tend using 1:5:(sprintf("%.0f", $8)) with labels left offset char 0.8, char 0.8 font ",9" notitle, \
     2.5 with lines ls 7 lw 2 dt 3 title "5/2 (paper)"
unset multiplot
