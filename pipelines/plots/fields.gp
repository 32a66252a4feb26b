# The flow fields behind clustering (coolgas-fields):
#  top row: the density of the middle plane of cells at three times (slab);
#  middle row: the vorticity normal to that plane at the same times;
#  bottom: the shear (transverse) and sound (longitudinal) flow energies over
#  their noise levels, and the density's variance over its value at t = 0,
#  against t (series): the shear flow grows first, the clusters follow.
# Written as PNG or PDF by the name of out (term() of plots/common.gp).
plots = system("dirname " . ARG0)
load plots . "/common.gp"
nb = nblocks(slab)
blockt(i) = real(bfield(slab, i, "t"))
# The density's variance at the first row, the reference of its growth.
var0 = real(system("awk -F'\t' '!/^#/ && $1 != \"t\" && NF > 1 { print $12; exit }' " . q(series)))
L = real(meta(series, "L"))

eval term(1500, 1150)
set output out
set multiplot title sprintf("Vortices, then clusters: L = %s, {/Symbol f} = %.3f, r_0 = %s, {/Symbol d} = %s; %s", \
    meta(series, "L"), real(meta(series, "phi")), meta(series, "r0"), meta(series, "delta"), meta(series, "cells"))
set size square
set xrange [0:L]; set yrange [0:L]
set xtics out; set ytics out
unset key
w = 0.31; hgt = 0.31
do for [i = 1 : nb] {
  set origin (i - 1) * 0.33, 0.66
  set size w, hgt
  set title sprintf("density, t = %g", blockt(i))
  set palette defined (0 "#ffffff", 1 "#fde725", 2 "#21918c", 3 "#440154")
  set cbrange [0:*]
  set cblabel "particles per {/Symbol s}^3"
  plot slab index (i - 1) using 2:3:4 with image
  set origin (i - 1) * 0.33, 0.35
  set title sprintf("vorticity {/Symbol w}_z, t = %g", blockt(i))
  set palette defined (-1 "#2166ac", 0 "#f7f7f7", 1 "#b2182b")
  # Symmetric about 0, at the block's largest |w|.
  stats slab index (i - 1) using 5 nooutput
  m = abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : abs(STATS_max)
  set cbrange [-m:m]
  set cblabel "{/Symbol w}_z  [{/Symbol w}_0]"
  plot slab index (i - 1) using 2:3:5 with image
}
set size nosquare
set origin 0.05, 0.0
set size 0.9, 0.34
unset xrange; unset yrange
set logscale xy
set format x "10^{%L}"
set grid
set key top left
set title "flow energies over their noise levels, and the density's variance over its start"
set xlabel "t  [1/{/Symbol w}_0]"
set ylabel "ratio"
set yrange [0.5:*]
plot series using ($1 > 0 ? $1 : NaN):($9 / $11) with linespoints ls 1 pi 3 title "E_T / noise: shear (vortices)", \
     series using ($1 > 0 ? $1 : NaN):($8 / $10) with linespoints ls 2 pi 3 title "E_L / noise: sound", \
     series using ($1 > 0 ? $1 : NaN):($12 / var0) with linespoints ls 3 pi 3 title "Var(n_c)/<n_c>, over its value at t = 0: clusters", \
     1 with lines dt 2 lc rgb "gray50" title "noise level"
unset multiplot
