# The driven gas (pipelines/effects): T(t)/T0 at two powers with Enskog's
# steady temperature, and the steady velocity distribution Phi(y) against
# the Gaussian.
# gnuplot -e "plots='pipelines/plots'; tables='out/effects/tables'; table='out/effects/effects.tsv'; out='driven.png'" driven.gp
load plots . "/common.gp"
eval term(1400, 600)
set output out
e1 = tables . "/energy_driven_P1.tsv"; e8 = tables . "/energy_driven_P8.tsv"
T0 = real(meta(e1, "T0")); r0 = meta(e1, "r0"); P = real(meta(e1, "driving_power"))
# The theory column of the table's row "T/T0, steady".
theory = real(system("awk -F '\\t' '$2 == \"T/T0, steady\" { print $5 }' " . q(table)))
set multiplot layout 1, 2 title sprintf("The driven gas: white-noise kicks of power P into inelastic spheres (r_0 = %s, {/Symbol d} = 0)", r0)

set title "Temperature: each power settles where the collisions lose what the kicks bring in"
set logscale x
set format x "10^{%L}"
set grid
set key bottom right Left reverse opaque
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "T(t) / T_0"
set xrange [0.1:*]
set yrange [0:*]
plot e1 using 1:($1 > 0 ? 2 * $2 / (3 * T0) : NaN) with lines ls 1 title sprintf("P = %.3g T_0 {/Symbol w}_0", P), \
     e8 using 1:($1 > 0 ? 2 * $2 / (3 * T0) : NaN) with lines ls 2 title sprintf("P = %.3g T_0 {/Symbol w}_0 (8 times)", 8 * P), \
     theory with lines ls 7 lw 1 title "Enskog's energy balance (first Sonine a_2)", \
     4 * theory with lines ls 7 lw 1 dt 2 title "4 times it: T ∝ P^{2/3}, exact at {/Symbol d} = 0"

set title "Velocity distribution in the steady state (the dumps after the relaxation, pooled)"
unset logscale x
set format x "%g"
set logscale y
set format y "10^{%L}"
set xlabel "y = v_{/Symbol a} / v_{rms}"
set ylabel "{/Symbol F}(y)"
set xrange [-6:6]
set yrange [1e-7:1]
set key bottom center
plot tables . "/phi_driven_P1.tsv" using 1:2:3 with yerrorbars ls 1 title "P", \
     tables . "/phi_driven_P8.tsv" using 1:2:3 with yerrorbars ls 2 title "8 P", \
     exp(-x * x / 2) / sqrt(2 * pi) with lines ls 7 lw 1 title "Gaussian"
unset multiplot
