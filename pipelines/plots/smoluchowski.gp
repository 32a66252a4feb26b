# The mean-field Smoluchowski equation (paper Eqs. 3-4, ballistic kernel)
# beside the simulated gas: (a) scaled N(m,t) M_avg^2 / M1 against m / M_avg
# (coolgas-smoluchowski blocks; gas: coolgas-clusters blocks, M1 = n);
# (b) M_max(t) and M_avg(t) of the equation, in its own time unit, with the
# fitted power laws (mean field: t^{6/5}), and the gas's M_max(t) on the top axis.
plots = system("dirname " . ARG0)
load plots . "/common.gp"
bt(f, i) = bfield(f, i, "t")
ns = nblocks(nm); ng = nblocks(gas_nm)
n = real(meta(gas_nm, "N")) / real(meta(gas_nm, "L"))**3
amax = -tsvval(fit_max, "theta"); aavg = -tsvval(fit_avg, "theta")
Amax = tsvval(fit_max, "A"); Aavg = tsvval(fit_avg, "A")
lo = tsvval(fit_max, "t_min"); hi = tsvval(fit_max, "t_max")

eval term(1900, 650)
set output out
set multiplot layout 1, 2 title sprintf("Smoluchowski equation, kernel (m_1^{-1/2} + m_2^{-1/2})(m_1^{1/3} + m_2^{1/3})^2, beside the gas (L = %s, {/Symbol f} = %.3f)", meta(gas_nm, "L"), real(meta(gas_nm, "phi")))
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set grid

set title "(a) scaled mass distribution"
set key outside right top font ",10"
set xlabel "m / M_{avg}"
set ylabel "N(m,t) M_{avg}^2 / M_1"
# Values below the floor are left out, so they do not stretch the m axis
# (the solver's far tail, the gas's one spanning cluster); a margin on top
# keeps the smallest masses off the frame.
floor = 1e-8
set yrange [floor:*]
set autoscale xfix
set offsets graph 0.03, graph 0.03, graph 0.06, 0
plot for [i = 1 : ns] nm index (i - 1) using ($6 >= floor ? $5 : NaN):6 with lines ls i \
       title sprintf("Smoluchowski t = %s", bt(nm, i)), \
     for [i = 1 : ng] gas_nm index (i - 1) using ($6 / n >= floor ? $5 : NaN):($6 / n) with points ls (ns + i) \
       title sprintf("gas t = %s", bt(gas_nm, i))
set offsets 0, 0, 0, 0
set autoscale x

set title "(b) cluster growth"
set key outside right top font ",10"
set yrange [1:*]
set xlabel "t  [Smoluchowski time 1/(c_1(0) K_0), ½-gain convention]"
set x2label "t  [gas: initial mean collision times 1/{/Symbol w}_0]"
set x2tics; set logscale x2; set format x2 "10^{%L}"
set xtics nomirror
set ylabel "mass  [particles]"
plot series using 1:($1 > 0 ? $6 : NaN) with lines ls 1 title "Smoluchowski M_{max}", \
     [lo:hi] Amax * x**amax with lines ls 1 lw 4 dt 1 title sprintf("  fit t^{%.3f}", amax), \
     series using 1:($1 > 0 ? $5 : NaN) with lines ls 2 title "Smoluchowski M_{avg}", \
     [lo:hi] Aavg * x**aavg with lines ls 2 lw 4 dt 1 title sprintf("  fit t^{%.3f} (mean field 6/5)", aavg), \
     gas_series using 1:($1 > 0 ? $6 : NaN) axes x2y1 with linespoints ls 3 title "gas M_{max} (top axis)", \
     gas_series using 1:($1 > 0 ? $5 : NaN) axes x2y1 with linespoints ls 4 title "gas M_{avg} (top axis)"
unset multiplot
