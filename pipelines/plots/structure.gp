# The growing length (coolgas-structure) and the shape of clusters (coolgas-shape):
#  (a) S(k, t) of the gas at every dump (table sk);
#  (b) its dynamic-scaling collapse L_t^-3 S(k L_t) for t >= collapse_from;
#  (c) L_t(t) (first moment of the low-k peak), L_C (first zero of the density
#      correlation) and L_v (of the momentum correlation) for each series in lt,
#      with the fits L = A t^{1/z} of L_t and L_C over window (coolgas-fit
#      tables fit_lt_* and fit_lc_* beside each lt_*), the box limit L/4 and
#      the paper's slope 1/z = 2/5 for comparison;
#  (d) the fractal dimension d_f(t) of the gas clusters and, if shape_ba is
#      not empty, of the BA aggregates.
# Written as PNG or PDF by the name of out (term() of plots/common.gp).
plots = system("dirname " . ARG0)
load plots . "/common.gp"
# The fit tables of a series: kind "lt" (L_t) or "lc" (L_C).
fitof(t, kind) = system("echo " . q(t) . " | sed 's,/lt_,/fit_" . kind . "_,'")
th(t, kind) = tsvval(fitof(t, kind), "theta")
z(t, kind) = -1 / th(t, kind)
ze(t, kind) = tsvval(fitof(t, kind), "theta_err") * z(t, kind)**2
A(t, kind) = tsvval(fitof(t, kind), "A")
lo(t) = tsvval(fitof(t, "lt"), "t_min")
hi(t) = tsvval(fitof(t, "lt"), "t_max")
if (!exists("shape_ba")) shape_ba = ""
nb = nblocks(sk); nl = words(lt); ng = words(shape_gas); nba = words(shape_ba)
# The fits of each series, read once: a function of the file in the plot
# command would run its shell commands again at every sample point (minutes).
array Zt[nl]; array Zte[nl]; array At[nl]; array Ac[nl]; array Zc[nl]; array Zce[nl]; array LO[nl]; array HI[nl]
do for [i = 1 : nl] {
  t = word(lt, i)
  Zt[i] = z(t, "lt"); Zte[i] = ze(t, "lt"); At[i] = A(t, "lt")
  Zc[i] = z(t, "lc"); Zce[i] = ze(t, "lc"); Ac[i] = A(t, "lc")
  LO[i] = lo(t); HI[i] = hi(t)
}
# The box side of each series, and the first one's L_C fit at the window's
# start: the anchor of the paper's slope 1/z = 2/5, drawn below it.
array Lbox[nl]
Lbox_max = 0
do for [i = 1 : nl] { Lbox[i] = real(meta(word(lt, i), "L")); Lbox_max = Lbox[i] > Lbox_max ? Lbox[i] : Lbox_max }
c_anchor = 0.6 * Ac[1] * LO[1]**(1 / Zc[1])
blockt(i) = real(bfield(sk, i + 1, "t"))

eval term(1400, 1000)
set output out
set multiplot layout 2, 2 title sprintf("Growing length and cluster shape: L = %s, {/Symbol f} = %.3f, r_0 = %s, {/Symbol d} = %s", \
    meta(sk, "L"), real(meta(sk, "phi")), meta(sk, "r0"), meta(sk, "delta"))
set grid
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
# viridis: its lightness rises with t, so the times stay in order in grey too.
set palette defined (0 "#440154", 1 "#3b528b", 2 "#21918c", 3 "#5ec962", 4 "#fde725")
set cbrange [log10(blockt(1) > 0 ? blockt(1) : 0.01):log10(blockt(nb - 1))]
set cblabel "log_{10} t"
set colorbox

set title "(a) structure factor S(k, t), every dump"
set xlabel "k  [1/{/Symbol s}]"
set ylabel "S(k, t)"
set autoscale xfix
set format x "%g"
set xtics (0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2)
plot for [i = 0 : nb - 1] sk index i using 3:4:(log10($1 > 0 ? $1 : 0.01)) with lines lw 1.5 lc palette notitle

set autoscale x
set xtics autofreq
set format x "10^{%L}"
set title sprintf("(b) dynamic scaling, t ≥ %g: L_t^{-3} S(k, t) against k L_t", collapse_from)
set xlabel "k L_t"
set ylabel "S / L_t^3  [{/Symbol s}^{-3}]"
plot for [i = 0 : nb - 1] sk index i using ($1 >= collapse_from ? $7 : NaN):8:(log10($1 > 0 ? $1 : 0.01)) \
     with linespoints pt 7 ps 0.5 lw 1.5 lc palette notitle
unset colorbox

set title sprintf("(c) growing lengths; black lines: L = A t^{1/z} fitted over t = %s", window)
set xlabel "t  [1/{/Symbol w}_0]"
set ylabel "length  [{/Symbol s}]"
# The lengths stay below ~L/2; the key goes in the decade above them.
set key top left opaque box
set xrange [0.5:*]
set yrange [*:4 * Lbox_max]
# Line styles of plots/common.gp: L_t, L_C, L_v of series i are 3i-2, 3i-1, 3i.
plot for [i = 1 : nl] word(lt, i) using 1:($1 > 0 ? $2 : NaN) with linespoints ls (3 * i - 2) ps 0.6 \
       title sprintf("L_t = 2{/Symbol p}/<k> (L = %s, seed %s)", meta(word(lt, i), "L"), meta(word(lt, i), "seed")), \
     for [i = 1 : nl] word(lt, i) using 1:($1 > 0 ? $7 : NaN) with linespoints ls (3 * i - 1) ps 0.6 \
       title "L_C: first zero of C(r)", \
     for [i = 1 : nl] word(lt, i) using 1:($1 > 0 ? $8 : NaN) with linespoints ls (3 * i) ps 0.6 \
       title "L_v: first zero of C_v(r) (momentum)", \
     for [i = 1 : nl] Lbox[i] / 4 with lines dt 4 lw 1.5 lc rgb "gray40" \
       title sprintf("L/4 = %g: box-limited above", Lbox[i] / 4), \
     [LO[1]:HI[1]] c_anchor * (x / LO[1])**0.4 with lines dt 3 lw 2 lc rgb "gray50" title "slope 2/5 (the paper's z = 5/2)", \
     for [i = 1 : nl] [LO[i]:HI[i]] At[i] * x**(1 / Zt[i]) \
       with lines lw 3 lc rgb "black" title sprintf("L_t: z = %.2f ± %.2f", Zt[i], Zte[i]), \
     for [i = 1 : nl] [LO[i]:HI[i]] Ac[i] * x**(1 / Zc[i]) \
       with lines lw 3 dt 2 lc rgb "black" title sprintf("L_C: z = %.2f ± %.2f", Zc[i], Zce[i])
unset xrange
set autoscale y

set title "(d) fractal dimension of clusters, M ∝ R_g^{d_f} (mass bins from 10 particles)"
set xlabel "t  [1/{/Symbol w}_0]"
set ylabel "d_f"
unset logscale y
set format y "%g"
set yrange [0:3.5]
set xrange [0.5:*]
set key bottom left opaque box
# (an empty loop over files still opens one: the BA curves only when there are BA runs)
ba_curves = nba == 0 ? "" : 'for [i = 1 : nba] word(shape_ba, i) using 1:($4 >= 3 ? $2 : NaN):3 with yerrorbars ls (ng + i) ps 0.7 ' . \
  'title sprintf("BA, L = %s: aggregates as solid spheres, 3 by construction", meta(word(shape_ba, i), "L")),'
plot for [i = 1 : ng] word(shape_gas, i) using 1:($4 >= 3 ? $2 : NaN):3 with yerrorbars ls i ps 0.7 \
       title sprintf("gas, L = %s (clusters that wrap left out)", meta(word(shape_gas, i), "L")), \
     @ba_curves 3 with lines dt 2 lc rgb "gray40" title "d_f = 3", 2.5226 with lines dt 3 lc rgb "gray60" title "percolation 2.52"
unset multiplot
