# Error against wall time of coolgas-smoluchowski's methods, one panel per
# kernel, one curve per method and knob (the accuracy table's blocks, named in
# its "# block:" header lines, five per kernel in a fixed order).
# Usage: gnuplot -e "in='smoluchowski_accuracy.tsv'; out='smoluchowski_accuracy.png'" smoluchowski.gp
if (!exists("in")) in = 'out/smoluchowski_accuracy.tsv'
if (!exists("out")) out = 'out/smoluchowski_accuracy.png'
names = system("grep '^# block: ' '" . in . "' | sed 's/^# block: //'")
per_kernel = 5
kernels = words(names) / per_kernel
kernel_of(b) = system("echo '" . word(names, b) . "' | cut -d/ -f1")
curve_of(b) = system("echo '" . word(names, b) . "' | cut -d/ -f2-")

set terminal pngcairo size 1200, 450 * ((kernels + 1) / 2) font ",10"
set output out
set multiplot layout (kernels + 1) / 2, 2
set logscale xy
set format y "10^{%L}"
set xlabel "wall time (s, one core)"
set ylabel "error (mass-weighted L1 of binned N(m))"
set key bottom left font ",8"
set grid
# columns: 1 M, 2 rtol, 3 atol, 4 ratio, 5 wall_s, 6 rhs_evaluations, 7 error, 8 mean_mass_error
do for [k = 0 : kernels - 1] {
  first = k * per_kernel
  set title kernel_of(first + 1)
  plot for [b = 0 : per_kernel - 1] in index (first + b) using 5:($7 > 0 ? $7 : 1e-17) \
       with linespoints pt (b + 4) title curve_of(first + b + 1)
}
unset multiplot
