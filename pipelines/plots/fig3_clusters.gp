# Paper Fig. 3: snapshot of the gas (coolgas-snapshot PNG) and the scaled
# cluster-mass distribution N(m,t) M_avg^2 / n against m / M_avg at several
# times (coolgas-clusters), with the power-law fit below the largest cluster
# and the paper's m^{-2.7}: by the paper's unit cells (nm, fit) and, when
# contact_nm and contact_fit are set, beside it by particles in contact
# (coolgas-clusters --definition contact). With ba_snapshot and ba_nm set
# (ballistic aggregation), a second row shows BA.
plots = system("dirname " . ARG0)
load plots . "/common.gp"
has_ba = strlen(ba_nm) > 0
if (!exists("contact_nm")) contact_nm = ""
has_contact = strlen(contact_nm) > 0
n = real(meta(nm, "N")) / real(meta(nm, "L"))**3
# block comments: '# t = T; M_avg = A; M_max = B; largest_fraction = F'
bt(f, i) = bfield(f, i, "t")
bfrac(f, i) = real(bfield(f, i, "largest_fraction"))
bavg(f, i) = real(bfield(f, i, "M_avg"))
# The gas's scaled N(m) of the table `dist` with its fit `dfit`, by the
# definition named `what` (set these three, then eval nm_panel).
nm_panel = "blocks = nblocks(dist); Mavg_last = bavg(dist, blocks); " . \
  "tau = tsvval(dfit, 'theta'); tau_err = tsvval(dfit, 'theta_err'); " . \
  "fA = tsvval(dfit, 'A'); flo = tsvval(dfit, 't_min'); fhi = tsvval(dfit, 't_max'); " . \
  "set logscale xy; set format x '10^{%L}'; set format y '10^{%L}'; set grid; set key top right; " . \
  "set xlabel 'm / M_{avg}'; set ylabel 'N(m,t) M_{avg}^2 / n     (n = N / L^3)'; " . \
  "plot for [i = 1 : blocks] dist index (i - 1) using 5:($6 / n) with points ls i " . \
  "  title sprintf('t = %s (largest cluster %.0f %%)', bt(dist, i), 100 * bfrac(dist, i)), " . \
  "  [flo / Mavg_last : fhi / Mavg_last] fA * (x * Mavg_last)**(-tau) * Mavg_last**2 / n with lines lw 3 lc rgb 'black' " . \
  "  title sprintf('fit m^{-%.2f ± %.2f} (t = %s)', tau, tau_err, bt(dist, blocks)), " . \
  "  [flo / Mavg_last : fhi / Mavg_last] 2 * fA * (x * Mavg_last)**(-2.7) * Mavg_last**2 / n with lines lw 2 dt 2 lc rgb 'gray30' " . \
  "  title 'm^{-2.7} (paper)'"
# fitted N = A m^-tau in scaled variables: y = A (x M_avg)^-tau M_avg^2 / n

cols = has_contact ? 3 : 2
eval term(has_contact ? 2100 : 1400, has_ba ? 1300 : 650)
set output out
set multiplot layout (has_ba ? 2 : 1), cols title sprintf("Clusters of the granular gas (L = %s, N = %s, {/Symbol f} = %.3f, r_0 = %s)", meta(nm, "L"), meta(nm, "N"), real(meta(nm, "phi")), meta(nm, "r0"))

set title sprintf("(a) gas at t = %s: slab |z - L/2| < 2, the largest clusters (unit cells) in colour", snapshot_time)
unset key; unset tics; unset border; unset xlabel; unset ylabel
set size ratio -1
plot snapshot binary filetype=png with rgbimage
set size noratio; set tics; set border

set title "(b) scaled mass distribution, gas: the paper's unit cells"
dist = nm; dfit = fit
eval nm_panel
if (has_contact) {
  # the axes afresh (gnuplot 5.4 warns of its log axes' links otherwise), the line styles again
  reset
  load plots . "/common.gp"
  set title sprintf("(c) the same by particles in contact (bonded closer than %s {/Symbol s})", word(meta(contact_nm, "contact"), 4))
  dist = contact_nm; dfit = contact_fit
  eval nm_panel
}

if (has_ba) {
  set title sprintf("(%s) ballistic aggregation: aggregates at their true size, the largest in colour", has_contact ? "d" : "c")
  unset key; unset tics; unset border; unset logscale; unset grid; unset xlabel; unset ylabel
  set size ratio -1
  plot ba_snapshot binary filetype=png with rgbimage
  set size noratio; set tics; set border
  set title sprintf("(%s) scaled mass distribution, ballistic aggregation", has_contact ? "e" : "d")
  set logscale xy; set grid; set key top right
  set xlabel "m / M_{avg}"
  set ylabel "N(m,t) M_{avg}^2 / n     (n = N / L^3)"
  nb = real(meta(ba_nm, "N")) / real(meta(ba_nm, "L"))**3
  bblocks = nblocks(ba_nm)
  plot for [i = 1 : bblocks] ba_nm index (i - 1) using 5:($6 / nb) with points ls i title sprintf("t = %s", bt(ba_nm, i))
}
unset multiplot
