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
wlo = real(system("echo '" . window . "' | cut -d: -f1")); whi = real(system("echo '" . window . "' | cut -d: -f2"))

set terminal pngcairo size 1800, 600 font "sans,11"
set output out
set multiplot layout 1, 3 title sprintf("Energy decay for varying parameters (L = %s; otherwise {/Symbol f} = %s, r_0 = %s, {/Symbol d} = %s; fits over t = %s)", L, phi0, r00, delta0, window)
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set grid
set key bottom left
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "E(t) / E(0)"
set xrange [0.1:*]
ref(x) = 3 * x**(-1.2)

set title "(a) volume fraction {/Symbol f}"
plot for [i = 1 : words(phi_tables)] word(phi_tables, i) using 1:($1 > 0 ? $4 : NaN) with lines lw 2 \
       title sprintf("{/Symbol f} = %s: {/Symbol q} = %.3f ± %.3f", word(phis, i), th(word(phi_tables, i)), the(word(phi_tables, i))), \
     [wlo:whi] ref(x) with lines lw 3 lc rgb "black" title "t^{-6/5}"

set title "(b) coefficient of restitution r_0"
plot for [i = 1 : words(r0_tables)] word(r0_tables, i) using 1:($1 > 0 ? $4 : NaN) with lines lw 2 \
       title sprintf("r_0 = %s: {/Symbol q} = %.3f ± %.3f", word(r0s, i), th(word(r0_tables, i)), the(word(r0_tables, i))), \
     [wlo:whi] ref(x) with lines lw 3 lc rgb "black" title "t^{-6/5}"

set title "(c) cut-off velocity {/Symbol d}"
plot for [i = 1 : words(delta_tables)] word(delta_tables, i) using 1:($1 > 0 ? $4 : NaN) with lines lw 2 \
       title sprintf("{/Symbol d} = %s: {/Symbol q} = %.3f ± %.3f", word(deltas, i), th(word(delta_tables, i)), the(word(delta_tables, i))), \
     [wlo:whi] ref(x) with lines lw 3 lc rgb "black" title "t^{-6/5}"
unset multiplot
