# What decides the exponent table's theta rows of Fig. 2, theta_BA and the
# largest cluster's share (pipelines/theta-causes.mk): the local slope
# -d ln E/d ln t against t, each fit window drawn as a bar at the height of
# its theta (a fit's theta is the slope's mean over the window, so where the
# slope has no plateau the bar's height depends on where the window lies);
# and the largest cluster's share against the particles per unit cell.
# Variables: causes, share (the two tables), tables (their folder, for the
# slope_*.tsv), phis, r0s, sizes, boxes (lists), phi0, r00, delta0, out.
plots = system("dirname " . ARG0)
load plots . "/common.gp"

eval term(1800, 1100)
set output out
set multiplot layout 2, 3 title "What decides {/Symbol q}: the local slope -d ln E/d ln t (smoothed over ±1/4 decade) with each fit window as a bar at its {/Symbol q}\n(thick: the pipeline's window; thin: its last half decade); the largest cluster's share against the occupied unit cells"
set logscale x
set format x "10^{%L}"
set grid
set key top right
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "-d ln E / d ln t"
set yrange [0.8:2.0]
set xrange [1:*]
# row selection in the causes table (columns: 1 model 2 phi 3 r0 4 delta 5 L 6 runs 7 window 8 t_min 9 t_max 11 theta)
near(a, b) = abs(a - b) <= 0.003 * abs(b)
# (gnuplot's real() cannot read 1e-4: awk writes it out)
num(s) = real(system("awk 'BEGIN { printf \"%.17g\", " . s . " }'"))
d0 = num(delta0)
gas(phi, r0) = ($1 == 0 && near($2, phi) && near($3, r0) && near($4, d0))
bar(ok) = ok ? $8 : NaN
lines = "0.0 notitle, 1.2 with lines lw 2 lc rgb 'black' title '6/5 (BA mean field)', 1.5 with lines lw 1 dt 2 lc rgb 'black' title '3/2 (Burgers)'"
slope(name) = tables . "/slope_" . name . ".tsv"
pset(phi, r0) = "param_phi" . phi . "_r" . r0 . "_d" . delta0

set title sprintf("(a) Fig. 1's gas in each box; bar: t = 100 to x = t/L^{5/2} = 0.1")
eval "plot " . lines . ", " . \
  "for [i = 1 : words(sizes)] slope('size_L' . word(sizes, i)) using 1:2 with lines ls i title 'L = ' . word(sizes, i), " . \
  "for [i = 1 : words(sizes)] causes using (bar(gas(real(phi0), real(r00)) && $5 == real(word(sizes, i)) && $7 == 3)):11:($9 - $8):(0) with vectors nohead lc rgb style_rgb[i] dt 1 lw 5 notitle, " . \
  "for [i = 1 : words(sizes)] causes using (bar(gas(real(phi0), real(r00)) && $5 == real(word(sizes, i)) && $7 == 2)):11:($9 - $8):(0) with vectors nohead lc rgb style_rgb[i] dt 1 lw 2 notitle"

set title sprintf("(b) Fig. 2: volume fraction {/Symbol f} (r_0 = %s)", r00)
eval "plot " . lines . ", " . \
  "for [i = 1 : words(phis)] slope(pset(word(phis, i), r00)) using 1:2 with lines ls i title '{/Symbol f} = ' . word(phis, i), " . \
  "for [i = 1 : words(phis)] causes using (bar(gas(real(word(phis, i)), real(r00)) && $7 == 0)):11:($9 - $8):(0) with vectors nohead lc rgb style_rgb[i] dt 1 lw 5 notitle, " . \
  "for [i = 1 : words(phis)] causes using (bar(gas(real(word(phis, i)), real(r00)) && $7 == 2)):11:($9 - $8):(0) with vectors nohead lc rgb style_rgb[i] dt 1 lw 2 notitle"

set title sprintf("(c) Fig. 2: restitution r_0 ({/Symbol f} = %s)", phi0)
eval "plot " . lines . ", " . \
  "for [i = 1 : words(r0s)] slope(pset(phi0, word(r0s, i))) using 1:2 with lines ls i title 'r_0 = ' . word(r0s, i), " . \
  "for [i = 1 : words(r0s)] causes using (bar(gas(real(phi0), real(word(r0s, i))) && $7 == 0)):11:($9 - $8):(0) with vectors nohead lc rgb style_rgb[i] dt 1 lw 5 notitle, " . \
  "for [i = 1 : words(r0s)] causes using (bar(gas(real(phi0), real(word(r0s, i))) && $7 == 2)):11:($9 - $8):(0) with vectors nohead lc rgb style_rgb[i] dt 1 lw 2 notitle"

set title sprintf("(d) ballistic aggregation ({/Symbol f} = %s) by box; thin bar: to the run's end", phi0)
set yrange [0.8:1.6]
set xrange [1:*]
if (words(boxes) > 0) {
  eval "plot 1.2 with lines lw 2 lc rgb 'black' title '6/5 (mean field)', 1.206 with lines lw 1 dt 2 lc rgb '#d55e00' title 'paper 1.206 ± 0.005', " . \
    "for [i = 1 : words(boxes)] slope('babox_L' . word(boxes, i)) using 1:2 with lines ls i title sprintf('L = %s', word(boxes, i)), " . \
    "for [i = 1 : words(boxes)] causes using (($1 == 1 && $5 == real(word(boxes, i)) && $7 == 0) ? $8 : NaN):11:($9 - $8):(0) with vectors nohead lc rgb style_rgb[i] dt 1 lw 5 notitle, " . \
    "for [i = 1 : words(boxes)] causes using (($1 == 1 && $5 == real(word(boxes, i)) && $7 == 4) ? $8 : NaN):11:($9 - $8):(0) with vectors nohead lc rgb style_rgb[i] dt 1 lw 2 notitle"
} else {
  set label 1 "no aggregation runs (BA = 0)" at graph 0.5, 0.5 center
  plot NaN notitle
  unset label 1
}

# (e), (f): the share table (columns: 1 phi 2 L 3 N 4 n 5 share_0 6 t_late 7 share_late)
late = meta(share, "late_time")
unset logscale x
set format x "%g"
set yrange [0:1]
set xrange [0:0.45]
set key top left
set ylabel "largest cluster's share M_{max}/N"
set xlabel "particles per unit cell n = N/floor(L)^3"
set arrow 1 from 0.3116, graph 0 to 0.3116, graph 1 nohead dt 2 lw 2 lc rgb 'black'
set label 2 "site percolation\nthreshold 0.3116" at 0.3116, graph 0.2 right offset -0.5, 0
set title "(e) the share at t = 0 and late, against the cells' occupancy"
plot share using 4:5 with points pt 7 ps 1.5 lc rgb '#0072b2' title 't = 0', \
     share using 4:7 with points pt 5 ps 1.5 lc rgb '#d55e00' title 'late (the dump nearest t = ' . late . ')', \
     0.75 with lines dt 3 lw 2 lc rgb 'black' title "paper's 0.75"
unset arrow 1; unset label 2
set xlabel "box side L"
set key bottom right
set xrange [0 : real(word(sizes, words(sizes))) * 1.15]
set title sprintf("(f) the share in each box at {/Symbol f} = %s", phi0)
plot share using (near($1, real(phi0)) ? $2 : NaN):5 with points pt 7 ps 1.5 lc rgb '#0072b2' title 't = 0', \
     share using (near($1, real(phi0)) ? $2 : NaN):7 with points pt 5 ps 1.5 lc rgb '#d55e00' title 'late (the dump nearest t = ' . late . ')', \
     0.75 with lines dt 3 lw 2 lc rgb 'black' title "paper's 0.75"
unset multiplot
