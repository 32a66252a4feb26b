# Why the velocity rows differ from the paper (tables/velocity_causes*.tsv,
# pipelines/velocity-causes.sh): (a) alpha against t, the straight fit and
# kinetic theory's one-component form, beside kinetic theory's value and the
# paper's; (b) beta against the start of its fit window at the Maxwellian
# start, early and late times, beside the paper's 5/3; (c) kappa against t,
# the snapshot run and the seeds' mean of each box side.
# Variables: causes (the tables' prefix: causes.tsv, causes_beta.tsv,
# causes_kappa.tsv), late (the late time of the exponent table), out.
plots = system("dirname " . ARG0)
load plots . "/common.gp"
ta = causes . ".tsv"; tb = causes . "_beta.tsv"; tk = causes . "_kappa.tsv"
kt = real(meta(ta, "alpha_kinetic_theory"))
af = meta(ta, "alpha_from")
f1 = word(meta(ta, "y_froms"), 1)
# The data rows of a table that satisfy an awk condition, as a gnuplot data
# source (curves stay unbroken by the other rows); columns by number:
#   causes.tsv        1 t, 2 y_from, 4 alpha, 5 alpha_err, 7 alpha_kt, 8 alpha_kt_err
#   causes_beta.tsv   1 source, 2 L, 3 t, 4 y_from, 6 beta, 7 beta_err
#   causes_kappa.tsv  1 source, 2 L, 3 t, 5 kappa, 6 kappa_err
sel(file, cond) = "< awk -F '\t' 'FNR > 1 && !/^#/ && " . cond . "' " . q(file)
# The distinct values of column c among the rows that satisfy cond, in order.
distinct(file, cond, c) = system(sprintf("awk -F '\t' 'FNR > 1 && !/^#/ && %s && !s[$%d]++ { printf \"%%s \", $%d }' ", cond, c, c) . q(file))
# The value of column c in the first row that satisfies cond (nan if none).
first(file, cond, c) = real(system(sprintf("awk -F '\t' 'FNR > 1 && !/^#/ && %s { v = $%d; exit } END { print (v == \"\" ? \"nan\" : v) }' ", cond, c) . q(file)))

eval term(1800, 600)
set output out
set multiplot layout 1, 3 title sprintf("Velocity rows against time and fit window (L = %s, N = %s, r_0 = %s): why they differ from the paper", \
    meta(ta, "L"), meta(ta, "N"), meta(ta, "r0"))

set title "(a) exponential tail {/Symbol F}(y) ∝ e^{-{/Symbol a}y}: {/Symbol a} against t"
set logscale x
set format x "10^{%L}"
set grid
set key top right font ",10"
set xlabel "t  [initial mean collision times 1/{/Symbol w}_0]"
set ylabel "{/Symbol a}"
set yrange [1.8:3.8]
at0(c, f) = first(ta, "$1 == 0 && $2 == " . f, c)
plot sel(ta, "$2 == " . af . " && $1 > 0") using 1:7:8 with yerrorlines ls 1 \
       title sprintf("kinetic theory's form (y + 1/{/Symbol a}) e^{-{/Symbol a}y}, y ≥ %s (t = 0: %.2f)", af, at0(7, af)), \
     sel(ta, "$2 == " . af . " && $1 > 0") using 1:4:5 with yerrorlines ls 2 \
       title sprintf("straight line, y ≥ %s (t = 0: %.2f)", af, at0(4, af)), \
     sel(ta, "$2 == " . f1 . " && $1 > 0") using 1:4:5 with yerrorlines ls 3 \
       title sprintf("straight line, y ≥ %s, the former row (t = 0: %.2f)", f1, at0(4, f1)), \
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
bt = distinct(tb, "$1 == 0", 3)
plot for [i = 1 : words(bt)] sel(tb, "$1 == 0 && $3 == " . word(bt, i)) using 4:6:7 with yerrorlines ls i \
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
stats sel(tk, "1") using 5 nooutput
set yrange [STATS_min - 0.8 * (STATS_max - STATS_min) : STATS_max + 0.05 * (STATS_max - STATS_min)]
Ls = distinct(tk, "$1 == 1", 2)
# Each L's points a little apart in t, so that their error bars stay apart.
plot sel(tk, "$1 == 0 && $3 > 0") using 3:5 with lines ls 7 title sprintf("L = %s (one run)", meta(ta, "L")), \
     for [i = 1 : words(Ls)] sel(tk, "$1 == 1 && $2 == " . word(Ls, i)) using ($3 * (1 + 0.06 * (i - 3))):5:6 \
       with yerrorbars ls i ps 1.2 title sprintf("L = %s, mean of seeds", word(Ls, i)), \
     0 with lines dt 2 lc rgb "gray40" title "Gaussian"
unset multiplot
