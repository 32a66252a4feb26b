# Paper Fig. 1: E(t) for several L, the power-law fit of the largest L, and the
# finite-size collapse E L^{z theta} against t / L^z, with the fitted theta, z
# and eta (coolgas-collapse --optimize) and with the paper's theta = 6/5, z = 5/2.
# gnuplot -e "tables='E_L12.tsv E_L16.tsv'; fit='fit.tsv'; collapse='c.tsv'; paper='c_paper.tsv'; out='fig1.png'" fig1_energy_size.gp
plots = system("dirname " . ARG0)
load plots . "/common.gp"
n = words(tables)
theta = real(meta(collapse, "theta")); theta_err = real(meta(collapse, "theta_err"))
z = real(meta(collapse, "z")); z_err = real(meta(collapse, "z_err"))
eta = real(meta(collapse, "eta")); eta_err = real(meta(collapse, "eta_err"))
ew = meta(collapse, "eta_window"); xlo = real(system("echo '" . ew . "' | cut -d: -f1")); xhis = system("echo '" . ew . "' | cut -d: -f2"); xhi = strlen(xhis) > 0 ? real(xhis) : 0
fit_theta = tsvval(fit, "theta"); fit_err = tsvval(fit, "theta_err"); fit_A = tsvval(fit, "A")
fit_lo = tsvval(fit, "t_min"); fit_hi = tsvval(fit, "t_max")
Lof(i) = meta(word(tables, i), "L") + 0

eval term(1800, 600)
set output out
# Seeds per L, in the order of the L (they may differ: small boxes are cheap).
seeds = ""
do for [i = 1 : n] { seeds = seeds . (i > 1 ? ", " : "") . meta(word(tables, i), "runs") }
set multiplot layout 1, 3 title sprintf("Energy decay of the freely cooling gas for several system sizes L ({/Symbol f} = %.3f, r_0 = %s, {/Symbol d} = %s; seeds per L: %s)", \
    real(meta(word(tables, 1), "phi")), meta(word(tables, 1), "r0"), meta(word(tables, 1), "delta"), seeds)
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set grid
set key top right

# (a) E(t) as measured
set title "(a) E(t)"
set key bottom left
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "E(t)  [m {/Symbol s}^2 {/Symbol w}_0^2 per particle]"
plot for [i = 1 : n] word(tables, i) using 1:($1 > 0 ? $2 : NaN) with linespoints ls i pi 6 title sprintf("L = %d", Lof(i)), \
     [fit_lo:fit_hi] fit_A * x**(-fit_theta) with lines lw 3 dt 1 lc rgb "black" \
       title sprintf("fit t^{-{/Symbol q}} at L = %d: {/Symbol q} = %.3f ± %.1g", Lof(n), fit_theta, fit_err)

# (b) collapse with the fitted exponents (the data run from top left to
# bottom right: the key goes bottom left, below them, samples first)
set key bottom left Left reverse
set title "(b) collapse with the fitted {/Symbol q}, z"
set xlabel "x = t / L^z"
set ylabel "E L^{z{/Symbol q}}"
stats collapse using 1 nooutput
x_min = STATS_min; x_max = STATS_max
if (xhi <= 0) xhi = x_max
# eta is nan when its window held too few scaled points (coolgas-collapse says so)
has_eta = (eta == eta)
B_eta = NaN
if (has_eta) {
  stats collapse using ($1 >= xlo && $1 <= xhi ? log($2) + eta * log($1) : 1/0) nooutput
  B_eta = exp(STATS_mean)
}
# x^-theta is the scaling regime x << 1: drawn (and its prefactor taken) below x = 0.1
th_hi = (xlo / 3 < 0.1 ? xlo / 3 : 0.1)
stats collapse using ($1 < th_hi ? log($2) + theta * log($1) : 1/0) nooutput
B_theta = exp(STATS_mean)
if (!has_eta) set label 1 sprintf("no {/Symbol h}: fewer than 3 scaled points in x = %s", ew) at graph 0.97, graph 0.95 right
plot for [i = 0 : n - 1] collapse index i using 1:2 with linespoints ls (i + 1) pi 6 title sprintf("L = %d", Lof(i + 1)), \
     [x_min:th_hi] B_theta * x**(-theta) with lines lw 3 lc rgb "black" \
       title sprintf("x^{-{/Symbol q}}, {/Symbol q} = %.3f ± %.3f, z = %.2f ± %.2f", theta, theta_err, z, z_err), \
     [xlo:xhi] B_eta * x**(-eta) with lines lw 3 dt 2 lc rgb "black" \
       title (has_eta ? sprintf("x^{-{/Symbol h}}, {/Symbol h} = %.2f ± %.2f", eta, eta_err) : "")
unset label 1

# (c) collapse with the paper's exponents
set key bottom left noreverse Right
set title "(c) collapse with the paper's {/Symbol q} = 6/5, z = 5/2"
set xlabel "x = t / L^{5/2}"
set ylabel "E L^{3}"
stats paper using 1 nooutput
px_min = STATS_min; px_max = STATS_max
stats paper using ($1 < px_min * 30 ? log($2) + 1.2 * log($1) : 1/0) nooutput
P = exp(STATS_mean)
plot for [i = 0 : n - 1] paper index i using 1:2 with linespoints ls (i + 1) pi 6 title sprintf("L = %d", Lof(i + 1)), \
     [px_min:px_max] P * x**(-1.2) with lines lw 2 dt 2 lc rgb "black" title "x^{-6/5} (paper)", \
     [px_min:px_max] P * x**(-1.5) with lines lw 1 dt 3 lc rgb "gray40" title "x^{-3/2} (Burgers)"
unset multiplot
