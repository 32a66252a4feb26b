# E(t)/E0 of one run with its power-law fit and the paper's t^(-6/5).
# usage: gnuplot -e "table='energy.tsv'; fit='theta.tsv'; out='energy.png'" energy.gp
set terminal pngcairo size 900,650 font "sans,12"
set output out
set logscale xy
set format y "10^{%L}"
set format x "10^{%L}"
set xlabel "t  [initial mean collision times]"
set ylabel "E(t) / E(0)"
set key bottom left
set grid
# Fit results: the one data row of the coolgas-fit table.
stats fit u 1 nooutput
theta = STATS_min
stats fit u 3 nooutput
A = STATS_min
stats table u 1:2 every ::0::0 nooutput
E0 = STATS_min_y
set title sprintf("Freely cooling granular gas (r_0 = 0.1, {/Symbol d} = 10^{-4}, {/Symbol f} = 0.208): {/Symbol q} = %.3f", theta)
plot table u 1:4 every ::1 w lp pt 7 ps 0.6 lc rgb "#1f77b4" title "simulation", \
     [100:2000] A * x**(-theta) / E0 w l lw 2 lc rgb "#d62728" title sprintf("fit t^{-%.3f}", theta), \
     [10:2000] 2.5 * x**(-1.2) w l dt 2 lc rgb "black" title "t^{-6/5} (paper)"
