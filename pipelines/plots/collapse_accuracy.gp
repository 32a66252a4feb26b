# What accuracy costs in coolgas-collapse: the uncertainty of theta and z
# against the number of seeds per L (and the wall time of those runs).
# gnuplot -e "in='collapse_accuracy.tsv'; out='collapse_accuracy.png'" collapse_accuracy.gp
plots = system("dirname " . ARG0)
load plots . "/common.gp"
set terminal pngcairo size 1500, 600 font "sans,11"
set output out
set multiplot layout 1, 2 title sprintf("coolgas-collapse --optimize: seeds per L against the uncertainty (L = %s, t_{end} = %s)", meta(in, "L"), meta(in, "t_end"))
set grid
set logscale x 2
set xlabel "seeds per L"
set xrange [0.7:*]
set offsets 0, 0, graph 0.1, graph 0.1
set title "(a) fitted exponents"
set ylabel "exponent"
set key top right
plot in using 1:2:3 with yerrorlines pt 7 lw 2 title "{/Symbol q} (paper 6/5)", \
     in using 1:4:5 with yerrorlines pt 5 lw 2 title "z (paper 5/2)"
set title "(b) bootstrap uncertainty and cost"
set logscale y
set ylabel "standard error"
set y2label "wall time of the runs  [s, one core]"
set y2tics; set logscale y2; set ytics nomirror
stats in using 1:3 nooutput
e1 = STATS_max_y
plot in using 1:3 with linespoints pt 7 lw 2 title "{/Symbol s}_{/Symbol q}", \
     in using 1:5 with linespoints pt 5 lw 2 title "{/Symbol s}_z", \
     in using 1:7 axes x1y2 with linespoints pt 9 lw 1 dt 2 lc rgb "black" title "wall time (right axis)"
unset multiplot
