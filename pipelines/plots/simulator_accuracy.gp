# What accuracy costs in coolgas-simulate: the fitted theta against the wall
# time of the run, one curve per cut-off delta, points labelled by N.
# gnuplot -e "in='simulator_accuracy.tsv'; deltas='1e-2 1e-3 1e-4'; out='simulator_accuracy.png'" simulator_accuracy.gp
plots = system("dirname " . ARG0)
load plots . "/common.gp"
set terminal pngcairo size 1000, 650 font "sans,11"
set output out
set title sprintf("coolgas-simulate: fitted {/Symbol q} against wall time ({/Symbol f} = %s, r_0 = %s, t_{end} = %s, fit over t = %s)", \
    meta(in, "phi"), meta(in, "r0"), meta(in, "t_end"), meta(in, "fit_window"))
set logscale x
set grid
set key top right
set xlabel "wall time of the run  [s, one core]"
set ylabel "fitted {/Symbol q}  (E ∝ t^{-{/Symbol q}})"
set offsets graph 0.05, graph 0.15, graph 0.1, graph 0.1
# columns: 1 N, 2 delta, 3 wall_s, 4 theta, 5 theta_err
plot for [i = 1 : words(deltas)] in using 3:(strcol(2) eq word(deltas, i) ? $4 : NaN):5 \
       with yerrorlines pt (i + 5) ps 1.2 lw 2 title sprintf("{/Symbol d} = %s", word(deltas, i)), \
     in using 3:4:(sprintf("N = %d", $1)) with labels left offset char 1, char 0.6 font ",9" notitle, \
     1.2 with lines dt 2 lc rgb "black" title "6/5 (paper)"
