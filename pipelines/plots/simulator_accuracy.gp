# What accuracy costs in coolgas-simulate: (a) theta over the scaling window
# [100, 0.1 L^(5/2)] against L; (b) its deviation from theta_ref (the largest
# L) and its standard error against the core-seconds of the runs; (c) the bias
# of the cut-off delta against the collisions a run needs.
# gnuplot -e "sizes='simulator_accuracy.tsv'; deltas='simulator_delta.tsv'; out='simulator_accuracy.png'" simulator_accuracy.gp
plots = system("dirname " . ARG0)
load plots . "/common.gp"
eval term(1800, 620)
set output out
ref = meta(sizes, "theta_ref")
# the fit window's start: the first word of '# fit_window: 100:0.1 L^2.5 ...'
t0 = meta(sizes, "fit_window")[1:strstrt(meta(sizes, "fit_window"), ":") - 1]
set multiplot layout 1, 3 title sprintf("coolgas-simulate: what accuracy costs ({/Symbol f} = %s, r_0 = %s; E ∝ t^{-{/Symbol q}} fitted over %s ≤ t ≤ 0.1 L^{5/2}, the scaling regime)", \
    meta(sizes, "phi"), meta(sizes, "r0"), t0)
set grid
set key below
set logscale x
set offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1
theta_ref = real(word(ref, 1))

# columns of sizes: 1 L, 2 t_end, 3 seeds, 4 theta, 5 theta_err, 6 theta_sd,
# 7 error, 8 error_err, 9 cpu_s, 10 cpu_s_run
set title sprintf("(a) {/Symbol q} against box size ({/Symbol d} = %s, seeds per L: %s)", meta(sizes, "delta"), \
    system("awk 'NR > 1 && !/^#/ { printf \"%s%s\", s, $3; s = \"/\" }' " . q(sizes)))
set xlabel "box size L  [{/Symbol s}]"
set ylabel "{/Symbol q}  (E ∝ t^{-{/Symbol q}}), mean of the seeds ± standard error"
plot sizes using 1:4:5:xtic(1) with yerrorbars ls 1 title "{/Symbol q}(L) ± seed spread/√seeds", \
     theta_ref with lines ls 2 lw 1 title sprintf("{/Symbol q}_{ref} = %s ± %s, the mean of the largest L", word(ref, 1), word(ref, 3)), \
     1.2 with lines ls 7 dt 3 lw 2 title "6/5 (paper)"

set title sprintf("(b) error of {/Symbol q} against cost (L = %d gives {/Symbol q}_{ref})", \
    int(system("awk 'NR > 1 && !/^#/ { L = $1 } END { print L }' " . q(sizes))))
set logscale y
set autoscale fix
set offsets graph 0.05, graph 0.15, graph 0.1, graph 0.1
set format y "%g"
set xlabel "core-seconds of the seeds of L  [CPU s]"
set ylabel "error of {/Symbol q}"
set xtics auto
set xtics add (2, 5, 20, 50, 200, 500)
set ytics add (0.002, 0.005, 0.02, 0.05, 0.2, 0.5)
plot sizes using 9:($7 == 0 ? NaN : abs($7)):8 with yerrorlines ls 1 title "|{/Symbol q} - {/Symbol q}_{ref}| ± both standard errors", \
     sizes using 9:5 with linespoints ls 2 title "standard error (seed spread/√seeds)", \
     sizes using 9:5:(sprintf("L = %d", $1)) with labels left offset char 0.8, char -0.8 font ",9" notitle

set title sprintf("(c) bias of the cut-off {/Symbol d} against its cost (L = %s, t_{end} = %s, same seeds)", \
    meta(deltas, "L"), meta(deltas, "t_end"))
unset logscale
set autoscale
unset ytics; set ytics
unset xtics; set xtics
set format y "%g"
set offsets graph 0.05, graph 0.2, graph 0.1, graph 0.1
set xlabel "collisions per run  [10^6]"
set ylabel sprintf("{/Symbol q}({/Symbol d}) - {/Symbol q}({/Symbol d} = %s), mean over seeds", meta(deltas, "delta_min"))
# columns of deltas: 1 delta, 2 seeds, 3 theta, 4 theta_err, 5 bias, 6 bias_err,
# 7 collisions, 8 collisions_rel, 9 cpu_s_run
plot deltas using ($7 / 1e6):5:6 with yerrorlines ls 3 dt 1 ps 1.3 title "bias ± standard error of the paired differences", \
     deltas using ($7 / 1e6):5:(sprintf("{/Symbol d} = %s\n%.1f core-s", strcol(1), $9)) with labels left offset char 1, char 1.5 font ",9" notitle, \
     0 with lines ls 7 lw 1 dt 3 notitle
unset multiplot
