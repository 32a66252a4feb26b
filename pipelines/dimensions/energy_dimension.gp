# E(t) of the inelastic gas and of ballistic aggregation in each dimension
# (energy_MODEL_dD.tsv, the mean over the seeds), with each power-law fit
# drawn over its window (fit_MODEL_dD.tsv).
# gnuplot -e "plots='pipelines/plots'; tables='out/tables'; out='energy_dimension.png'" energy_dimension.gp
load plots . "/common.gp"
eval term(1300, 700)
set output out
set title "Energy per particle E(t) in d = 1, 2, 3: the inelastic gas and ballistic aggregation\n" . \
  "thick lines: the power-law fit A t^{-{/Symbol q}} over its window"
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set grid
set key outside right top Left reverse
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "E(t) / E(0)"
set xrange [0.1:*]
runs = system("ls " . q(tables) . " | sed -n 's/^energy_\\(.*\\)\\.tsv$/\\1/p'")
n = words(runs)
array A[n]; array th[n]; array lo[n]; array hi[n]; array E0[n]
do for [i = 1 : n] {
  f = tables . "/fit_" . word(runs, i) . ".tsv"
  A[i] = tsvval(f, "A"); th[i] = tsvval(f, "theta"); lo[i] = tsvval(f, "t_min"); hi[i] = tsvval(f, "t_max")
  E0[i] = real(system("awk -F '\\t' '!/^#/ && $1 == 0 { print $2; exit }' " . q(tables . "/energy_" . word(runs, i) . ".tsv")))
}
name(r) = (r[1:2] eq "ba" ? "BA" : "gas") . ", d = " . r[strlen(r):strlen(r)]
plot for [i = 1 : n] tables . "/energy_" . word(runs, i) . ".tsv" using 1:($1 > 0 ? $2 / E0[i] : NaN) \
       with lines ls i lw 1.5 title sprintf("%s: {/Symbol q} = %.3f over t = %.3g-%.3g", name(word(runs, i)), th[i], lo[i], hi[i]), \
     for [i = 1 : n] [lo[i]:hi[i]] A[i] * x**(-th[i]) / E0[i] with lines ls i lw 5 notitle
