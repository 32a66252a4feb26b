# Why the velocity rows differ from the paper (tables/velocity_causes.tsv,
# pipelines/velocity-causes.sh): (a) alpha against t, the straight fit and
# kinetic theory's one-component form, beside kinetic theory's value and the
# paper's; (b) beta against the start of its fit window at the Maxwellian
# start, early and late times, beside the paper's 5/3; (c) kappa against t,
# the snapshot run and the seeds' mean of each box side.
# Variables: causes (the table), late (the late time of the exponent table), out.
plots = system("dirname " . ARG0)
load plots . "/common.gp"
kt = real(meta(causes, "alpha_kinetic_theory"))
af = meta(causes, "alpha_from")
f1 = word(meta(causes, "y_froms"), 1)
# The distinct values of column c among rows of quantity qn (in order of appearance).
distinct(qn, c) = system(sprintf("awk -F '\t' '$1 == \"%s\" && !s[$%d]++ { printf \"%%s \", $%d }' ", qn, c, c) . q(causes))
# The rows that satisfy an awk condition (curves stay unbroken by the other rows).
sel(cond) = "< awk -F '\t' '" . cond . "' " . q(causes)
row(qn, extra) = sel('$1 == "' . qn . '"' . extra)
t0(qn, f) = real(system("awk -F '\t' '$1 == \"" . qn . "\" && $3 == 0 && $4 == " . f . " { print $5 }' " . q(causes)))

eval term(1800, 600)
set output out
set multiplot layout 1, 3 title sprintf("Velocity rows against time and fit window (L = %s, N = %s, r_0 = %s): why they differ from the paper", \
    meta(causes, "L"), meta(causes, "N"), meta(causes, "r0"))

set title "(a) exponential tail {/Symbol F}(y) ∝ e^{-{/Symbol a}y}: {/Symbol a} against t"
set logscale x
set format x "10^{%L}"
set grid
set key top right font ",10"
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "{/Symbol a}"
set yrange [1.8:3.8]
plot row("alpha_kt", " && $4 == " . af . " && $3 > 0") using 3:5:6 with yerrorlines ls 1 \
       title sprintf("kinetic theory's form (y + 1/{/Symbol a}) e^{-{/Symbol a}y}, y ≥ %s (t = 0: %.2f)", af, t0("alpha_kt", af)), \
     row("alpha", " && $4 == " . af . " && $3 > 0") using 3:5:6 with yerrorlines ls 2 \
       title sprintf("straight line, y ≥ %s (t = 0: %.2f)", af, t0("alpha", af)), \
     row("alpha", " && $4 == " . f1 . " && $3 > 0") using 3:5:6 with yerrorlines ls 3 \
       title sprintf("straight line, y ≥ %s, the former row (t = 0: %.2f)", f1, t0("alpha", f1)), \
     kt with lines lw 2 lc rgb "black" title sprintf("kinetic theory %.2f (van Noije and Ernst 1998)", kt), \
     2.65 with lines dt 2 lw 2 lc rgb "gray40" title "paper 2.65 (t = 5, 10)"

set title "(b) -ln {/Symbol F}(y) ∝ y^{/Symbol b}: {/Symbol b} against the fit window"
unset logscale x
set format x "%g"
set key top left font ",9"
set xlabel "start of the fit window, y ≥ y_{from}"
set ylabel "{/Symbol b}"
set yrange [1.1:2.1]
set xrange [1.4:3.1]
bt = distinct("beta", 3)
plot for [i = 1 : words(bt)] row("beta", " && $3 == " . word(bt, i)) using 4:5:6 with yerrorlines ls i \
       title (real(word(bt, i)) == 0 ? "t = 0, Maxwellian start" : sprintf("t = %s", word(bt, i))), \
     5.0 / 3 with lines dt 2 lw 2 lc rgb "gray40" title "paper 5/3 (t = 2000-8000)", \
     2 with lines lw 1 lc rgb "black" title "Gaussian, y → ∞"

set title sprintf("(c) kurtosis {/Symbol k} = <v^4>/<v^2>^2 - 5/3 (speeds); paper: > 0 at t = %s", late)
set logscale x
set format x "10^{%L}"
set key bottom left font ",10"
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "{/Symbol k}"
# Room below the data for the key (stats reads only points inside the current ranges).
set xrange [*:*]; set yrange [*:*]
stats sel('$1 ~ /^kappa/ && $1 != "kappa_1"') using 5 nooutput
set yrange [STATS_min - 0.8 * (STATS_max - STATS_min) : STATS_max + 0.05 * (STATS_max - STATS_min)]
set xrange [*:*]
Ls = distinct("kappa_seeds", 2)
# Each L's points a little apart in t, so that their error bars stay apart.
plot row("kappa", " && $3 > 0") using 3:5 with lines ls 7 title sprintf("L = %s (one run)", meta(causes, "L")), \
     for [i = 1 : words(Ls)] row("kappa_seeds", " && $2 == " . word(Ls, i)) using ($3 * (1 + 0.06 * (i - 3))):5:6 \
       with yerrorbars ls i ps 1.2 title sprintf("L = %s, mean of seeds", word(Ls, i)), \
     0 with lines dt 2 lc rgb "gray40" title "Gaussian"
unset multiplot
