# A binary mixture (pipelines/effects): T_1/T_2(t) of the cooling gas, from
# equal temperatures at t = 0 to the cooling state's ratio, with Garzo &
# Dufty's (the table's theory column).
# gnuplot -e "plots='pipelines/plots'; tables='out/effects/tables'; table='out/effects/effects.tsv'; out='mixture.png'" mixture.gp
load plots . "/common.gp"
eval term(1100, 650)
set output out
e = tables . "/energy_mixture.tsv"
theory = real(system("awk -F '\\t' '$1 == \"mixture\" { print $5 }' " . q(table)))
set title sprintf("A binary mixture cooling (r_0 = %s, diameters %s, masses %s, {/Symbol f} = %.2f):\n" . \
                  "the heavier species stays hotter, equipartition broken", \
                  meta(e, "r0"), meta(e, "species_diameter"), meta(e, "species_mass"), real(meta(e, "phi")))
set logscale x
set format x "10^{%L}"
set grid
set key top right Left reverse opaque
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "T_1 / T_2  (small over large)"
set xrange [0.01:*]
set yrange [*:1.02]
plot e using 1:($1 > 0 ? $7 / $9 : NaN) with lines ls 1 title "measured", \
     theory with lines ls 7 lw 1 dt 2 title sprintf("Garzó and Dufty (Maxwellian approximation): %.3f", theory), \
     1 with lines ls 8 lw 1 dt 3 title "equipartition"
