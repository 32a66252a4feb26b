# theta(d): the decay exponent of the inelastic gas and of ballistic
# aggregation in each dimension (pipelines/dimensions/table.sh's rows
# "theta, ..."), against the two theories the paper weighs: BA's mean field
# 2d/(d+2) and Burgers' equation (2/3 in d = 1, d/2 for 2 <= d <= 4). They
# coincide in d = 1 and 2; d = 3 decides.
# gnuplot -e "plots='pipelines/plots'; table='dimensions.tsv'; out='theta_dimension.png'" theta_dimension.gp
load plots . "/common.gp"
eval term(900, 650)
set output out
set title "Energy decay E(t) = A t^{-{/Symbol q}} in d dimensions: measured against both theories\n" . \
  "(the paper's argument: the theories differ only in d = 3)"
set xlabel "dimension d"
set ylabel "{/Symbol q}"
set xrange [0.6:3.4]
set yrange [0.4:1.8]
set xtics 1
set grid
set key top left Left reverse box opaque
# One row per (model, d): the gas's d = 3 has two rows (one per theory).
rows(what, shift) = "< awk -F '\\t' '$1 == \"" . what . "\" && !seen[$2]++ { print $2 + " . sprintf("%g", shift) . ", $3, $4 }' " . q(table)
burgers(d) = d < 2 ? 1 / 0 : d / 2.0
plot 2 * x / (x + 2) with lines ls 1 dt 1 title "ballistic aggregation's mean field, 2d/(d+2)", \
     [2:3.4] burgers(x) with lines ls 2 dt 1 title "Burgers' equation, d/2 (2 {/Symbol \243} d {/Symbol \243} 4)", \
     "+" using (1):(2.0 / 3) every ::0::0 with points ls 2 pt 6 ps 2.5 lw 2 title "Burgers' equation in d = 1: 2/3", \
     rows("theta, inelastic gas", -0.06) using 1:2:3 with yerrorbars ls 3 dt 1 pt 7 ps 1.5 title "inelastic gas (r_0 = 0.1 in 2D and 3D, 0.9 in 1D)", \
     rows("theta, ballistic aggregation", 0.06) using 1:2:3 with yerrorbars ls 4 dt 1 pt 5 ps 1.5 title "ballistic aggregation"
