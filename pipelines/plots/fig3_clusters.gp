# Paper Fig. 3: snapshot of the gas (coolgas-snapshot PNG) and the scaled
# cluster-mass distribution N(m,t) M_avg^2 / n against m / M_avg at several
# times (coolgas-clusters), with the power-law fit below the largest cluster
# and the paper's m^{-2.7}. With ba_snapshot and ba_nm set (ballistic
# aggregation), a second row shows BA.
plots = system("dirname " . ARG0)
load plots . "/common.gp"
has_ba = strlen(ba_nm) > 0
tau = tsvval(fit, "theta"); tau_err = tsvval(fit, "theta_err")
fA = tsvval(fit, "A"); flo = tsvval(fit, "t_min"); fhi = tsvval(fit, "t_max")
n = real(meta(nm, "N")) / real(meta(nm, "L"))**3
# block comments: '# t = T; M_avg = A; M_max = B; largest_fraction = F'
blocks = nblocks(nm)
bt(f, i) = bfield(f, i, "t")
bfrac(f, i) = real(bfield(f, i, "largest_fraction"))
bavg(f, i) = real(bfield(f, i, "M_avg"))
Mavg_last = bavg(nm, blocks)

eval term(1400, has_ba ? 1300 : 650)
set output out
set multiplot layout (has_ba ? 2 : 1), 2 title sprintf("Clusters of the granular gas (L = %s, N = %s, {/Symbol f} = %.3f, r_0 = %s)", meta(nm, "L"), meta(nm, "N"), real(meta(nm, "phi")), meta(nm, "r0"))

set title sprintf("(a) gas at t = %s: slab |z - L/2| < 2, the largest clusters in colour", snapshot_time)
unset key; unset tics; unset border; unset xlabel; unset ylabel
set size ratio -1
plot snapshot binary filetype=png with rgbimage
set size noratio; set tics; set border

set title "(b) scaled mass distribution, gas"
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set grid
set key top right
set xlabel "m / M_{avg}"
set ylabel "N(m,t) M_{avg}^2 / n     (n = N / L^3)"
# fitted N = A m^-tau in scaled variables: y = A (x M_avg)^-tau M_avg^2 / n
plot for [i = 1 : blocks] nm index (i - 1) using 5:($6 / n) with points ls i \
       title sprintf("t = %s (largest cluster %.0f %%)", bt(nm, i), 100 * bfrac(nm, i)), \
     [flo / Mavg_last : fhi / Mavg_last] fA * (x * Mavg_last)**(-tau) * Mavg_last**2 / n with lines lw 3 lc rgb "black" \
       title sprintf("fit m^{-%.2f ± %.2f} (t = %s)", tau, tau_err, bt(nm, blocks)), \
     [flo / Mavg_last : fhi / Mavg_last] 2 * fA * (x * Mavg_last)**(-2.7) * Mavg_last**2 / n with lines lw 2 dt 2 lc rgb "gray30" \
       title "m^{-2.7} (paper)"

if (has_ba) {
  set title "(c) ballistic aggregation: aggregates at their true size, the largest in colour"
  unset key; unset tics; unset border; unset logscale; unset grid; unset xlabel; unset ylabel
  set size ratio -1
  plot ba_snapshot binary filetype=png with rgbimage
  set size noratio; set tics; set border
  set title "(d) scaled mass distribution, ballistic aggregation"
  set logscale xy; set grid; set key top right
  set xlabel "m / M_{avg}"
  set ylabel "N(m,t) M_{avg}^2 / n     (n = N / L^3)"
  nb = real(meta(ba_nm, "N")) / real(meta(ba_nm, "L"))**3
  bblocks = nblocks(ba_nm)
  plot for [i = 1 : bblocks] ba_nm index (i - 1) using 5:($6 / nb) with points ls i title sprintf("t = %s", bt(ba_nm, i))
}
unset multiplot
