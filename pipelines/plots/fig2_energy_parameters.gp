# Paper Fig. 2: E(t)/E(0) for several volume fractions phi (a), restitution
# coefficients r0 (b) and cut-offs delta (c), each curve with its fitted theta;
# the solid line is t^{-6/5}. Each *_tables is a list of coolgas-energy tables
# in the order of the values in phis, r0s, deltas; fits are the coolgas-fit
# tables beside them (energy_param_X.tsv -> fit_param_X.tsv).
plots = system("dirname " . ARG0)
load plots . "/common.gp"
fitof(t) = system("echo " . q(t) . " | sed 's,energy_param_,fit_param_,'")
th(t) = tsvval(fitof(t), "theta")
the(t) = tsvval(fitof(t), "theta_err")
# each curve's fit, E/E0 = (A/E0) t^-theta, drawn over its own window
E0(t) = real(system("awk 'FNR > 1 && !/^#/ && $4 > 0 { printf \"%.17g\", $2 / $4; exit }' " . q(t)))
fA(t) = tsvval(fitof(t), "A") / E0(t)
flo(t) = tsvval(fitof(t), "t_min")
fhi(t) = tsvval(fitof(t), "t_max")

eval term(1800, 600)
set output out
set multiplot layout 1, 3 title sprintf("Energy decay for varying parameters (L = %s unless the key says; otherwise {/Symbol f} = %s, r_0 = %s, {/Symbol d} = %s); thin lines: each curve's power-law fit over its window", L, phi0, r00, delta0)
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set grid
set key bottom left
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "E(t) / E(0)"
set xrange [0.1:*]
ref(x) = 3 * x**(-1.2)
# read_fits: the fit of each curve of `tables` into arrays TH, THE, FA, FLO,
# FHI, read once before its panel (a function of the file in the plot command
# would run its shell commands again at every sample point: minutes).
# LL: each run's box side (a set may have a box of its own: dilute gases need larger ones).
read_fits = "n = words(tables); array TH[n]; array THE[n]; array FA[n]; array FLO[n]; array FHI[n]; array LL[n]; " . \
  "do for [i = 1 : n] { t = word(tables, i); TH[i] = th(t); THE[i] = the(t); FA[i] = fA(t); FLO[i] = flo(t); FHI[i] = fhi(t); LL[i] = meta(t, 'L') }"
# the key names a curve's box side where it is not the L of the title
box(i) = LL[i] eq L ? "" : " (L = " . LL[i] . ")"
# panel(values, name): the curves of `tables`, their fits, and t^-6/5 (joined
# with '.', not sprintf, which cuts long strings such as lists of paths)
panel(values, name) = "for [i = 1 : n] word(tables, i) using 1:($1 > 0 ? $4 : NaN) " . \
  "with linespoints ls i pi 6 title sprintf('" . name . " = %s%s: {/Symbol q} = %.3f ± %.3f', word(" . q(values) . ", i), box(i), TH[i], THE[i]), " . \
  "for [i = 1 : n] [FLO[i]:FHI[i]] FA[i] * x**(-TH[i]) with lines ls i lw 1 dt 1 notitle, " . \
  "[1:*] ref(x) with lines lw 3 lc rgb 'black' title 't^{-6/5}'"

set title "(a) volume fraction {/Symbol f}"
tables = phi_tables; eval read_fits
eval "plot " . panel(phis, "{/Symbol f}")

set title "(b) coefficient of restitution r_0"
tables = r0_tables; eval read_fits
eval "plot " . panel(r0s, "r_0")

set title "(c) cut-off velocity {/Symbol d}"
tables = delta_tables; eval read_fits
eval "plot " . panel(deltas, "{/Symbol d}")
unset multiplot
