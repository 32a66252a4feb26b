# Rough spheres (pipelines/effects): T_rot/T_tr(t) of the cooling gas at
# each beta, from equal temperatures at t = 0 to the cooling state's ratio,
# with the two-temperature theory's ratio (the table's theory column).
# gnuplot -e "plots='pipelines/plots'; tables='out/effects/tables'; table='out/effects/effects.tsv'; out='rough.png'" rough.gp
load plots . "/common.gp"
eval term(1100, 650)
set output out
runs = system("ls " . q(tables) . " | sed -n 's/^energy_rough_b\\(.*\\)\\.tsv$/\\1/p' | sort -g")
n = words(runs)
first = tables . "/energy_rough_b" . word(runs, 1) . ".tsv"
set title sprintf("Rough spheres cooling (r_0 = %s, inertia q = %s, equal temperatures at t = 0):\n" . \
                  "the rotational temperature settles near the fraction of the translational that the theory gives", \
                  meta(first, "r0"), meta(first, "inertia"))
# theory(i): the table's theory for the i-th run's beta.
theory(i) = real(system("awk -F '\\t' '$1 == \"rough spheres\" && $2 ~ /beta = " . word(runs, i) . "$/ { print $5 }' " . q(table)))
array R[n]
do for [i = 1 : n] { R[i] = theory(i) }
set logscale x
set format x "10^{%L}"
set grid
set key outside right top Left reverse
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "T_{rot} / T_{tr}"
set xrange [0.01:*]
plot for [i = 1 : n] tables . "/energy_rough_b" . word(runs, i) . ".tsv" using 1:($1 > 0 ? $9 / $7 : NaN) \
       with lines ls i title sprintf("{/Symbol b} = %s", word(runs, i)), \
     for [i = 1 : n] R[i] with lines ls i lw 1 dt 3 title sprintf("theory, {/Symbol b} = %s: %.3f", word(runs, i), R[i])
