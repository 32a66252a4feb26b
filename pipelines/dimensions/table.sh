#!/bin/sh
# table.sh TABLES BIN DIMS
# The dimension study's table (pipelines/dimensions/Makefile), one row per
# measured quantity and reference, judged as the paper's exponent table is
# (pipelines/exponents.sh): TSV columns
#   quantity  d  measured  error  reference  reference_error  source  deviation  regime
# deviation = (measured - reference) / sqrt(error^2 + reference_error^2).
# theta's error is the largest of its fit's error, the standard error of the
# seeds' thetas (each run fitted alone), and the window's drift: half the
# difference between the fits over the window's two halves (in log t),
# which a power law that has not settled shows and a fit's error does not.
# TABLES holds energy_MODEL_dD.tsv (with seed_energy_MODEL_dD_sS.tsv, each
# seed's), fit_MODEL_dD.tsv and velocity_MODEL_dD.tsv.
set -e
tables=$1 bin=$2 dims=$3
here=$(dirname "$0")
value() { sh "$here/../tsv-value.sh" "$@"; }
calc() { awk "BEGIN { printf \"%.6g\", $1 }"; }
short() { awk "BEGIN { printf \"%.3g\", $1 }"; }
when() { awk "BEGIN { printf \"%.6g\", $1 }"; }  # a time as the windows give it (10000, not 1e+04)
# Column $2 of table $1 in the row whose t is nearest $3.
at_time() {
  awk -F '\t' -v want="$2" -v t="$3" '
    /^#/ { next }
    !header { for (i = 1; i <= NF; i++) { if ($i == want) col = i; if ($i == "t") tc = i } header = 1; next }
    NF > 0 { d = $tc - t; if (d < 0) d = -d; if (best == "" || d < best) { best = d; v = $col } }
    END { print v }' "$1"
}
theta_in() { "$bin/coolgas-fit" --power --t-window "$2:$3" "$1" 2>/dev/null | sh "$here/../tsv-value.sh" /dev/stdin theta; }
# theta and its error: the largest of the fit's error, the standard error
# of the seeds' own thetas over the same window, and the window's drift.
theta_row() {  # model d
  fit=$tables/fit_$1_d$2.tsv energy=$tables/energy_$1_d$2.tsv
  theta=$(value "$fit" theta) err=$(value "$fit" theta_err)
  lo=$(value "$fit" t_min) hi=$(value "$fit" t_max)
  mid=$(calc "sqrt($lo * $hi)")
  drift=$(calc "($(theta_in "$energy" "$lo" "$mid") - $(theta_in "$energy" "$mid" "$hi")) / 2")
  seeds=$(for f in "$tables/seed_energy_$1_d$2"_s*.tsv; do theta_in "$f" "$lo" "$hi"; done | awk '
    { s += $1; q += $1 * $1; n++ } END { if (n > 1) printf "%.6g", sqrt((q - s * s / n) / (n - 1) / n); else print 0 }')
  err=$(awk "BEGIN { a = $drift; if (a < 0) a = -a; e = $err; if (a > e) e = a; if ($seeds > e) e = $seeds; printf \"%.6g\", e }")
  echo "$theta $err $lo $hi"
}
# The time of the steepest decay, the largest local slope -d ln E / d ln t:
# Haff's law steepens towards t^-2 until clustering bends E(t) away from it.
steepest() { "$bin/coolgas-fit" --local-slope "$1" 2>/dev/null | awk -F '\t' '!/^#/ && $1 + 0 > 0 && $2 > m { m = $2; t = $1 } END { printf "%.3g", t }'; }
# Whether theta's window is in the scaling regime: for the gas, past Haff's
# law at its start (after the steepest decay), and before the finite-size
# crossover x = t / L^z = 0.1 (z = (d+2)/2, the mean-field z) at its end.
regime() {  # model d lo hi
  energy=$tables/energy_$1_d$2.tsv
  L=$(value "$energy" L '#')
  z=$(calc "($2 + 2) / 2")
  if [ "$1" = gas ]; then
    peak=$(steepest "$energy")
    if awk "BEGIN { exit !($3 < $peak) }"; then
      echo "no: the window starts at t = $(short "$3"), before E(t) leaves Haff's law (its steepest decay is at t = $peak)"
      return
    fi
  fi
  x=$(short "$4 / ($L ^ $z)")
  if awk "BEGIN { exit !($x <= 0.1) }"; then echo yes
  else echo "no: the window ends at x = t/L^$z = $x > 0.1 in L = $L (finite-size regime)"; fi
}
row() {  # model d
  fit=$tables/fit_$1_d$2.tsv energy=$tables/energy_$1_d$2.tsv
  theta=$(value "$fit" theta) err=$(value "$fit" theta_err)
  lo=$(value "$fit" t_min) hi=$(value "$fit" t_max)
  mid=$(calc "sqrt($lo * $hi)")
  drift=$(calc "($(theta_in "$energy" "$lo" "$mid") - $(theta_in "$energy" "$mid" "$hi")) / 2")
  err=$(awk "BEGIN { a = $drift; if (a < 0) a = -a; printf \"%.6g\", (a > $err ? a : $err) }")
  echo "$theta $err $lo $hi"
}
# Local slope -d ln E / d ln t over the quarter decade from t.
local_slope() {  # energy_table t
  awk -F '\t' -v t0="$2" '
    /^#/ || $1 == "t" || NF == 0 || $1 <= 0 { next }
    $1 >= t0 && !a { ta = $1; ea = $2; a = 1 }
    $1 >= t0 * 1.778 && !b { tb = $1; eb = $2; b = 1 }
    END { if (a && b) printf "%.3g", -log(eb / ea) / log(tb / ta); else print "nan" }' "$1"
}
# Whether theta's window is in the scaling regime: past Haff's law at its
# start (the gas; a local slope still above 3/2, the largest theta any
# theory proposes, is the crossover) and before the finite-size crossover
# x = t / L^z = 0.1 (z = (d+2)/2) at its end.
regime() {  # model d lo hi
  energy=$tables/energy_$1_d$2.tsv
  L=$(value "$energy" L '#')
  z=$(calc "($2 + 2) / 2")
  s=$(local_slope "$energy" "$3")
  if [ "$1" = gas ] && awk "BEGIN { exit !(\"$s\" == \"nan\" || $s > 1.5) }"; then
    echo "no: at the window's start (t = $(short "$3")) E(t) still falls as t^-$s, faster than t^-3/2 (Haff's regime)"
    return
  fi
  x=$(short "$4 / ($L ^ $z)")
  if awk "BEGIN { exit !($x <= 0.1) }"; then echo yes
  else echo "no: the window ends at x = t/L^$z = $x > 0.1 in L = $L (finite-size regime)"; fi
}
row() {  # quantity d measured error reference reference_error source regime
  dev=$(awk "BEGIN { s = sqrt($4 * $4 + $6 * $6); if (s > 0) printf \"%.2f\", ($3 - $5) / s; else print \"-\" }")
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$5" "$6" "$7" "$dev" "$8"
}
ba_mf() { calc "2 * $1 / ($1 + 2)"; }
burgers() { if [ "$1" = 1 ]; then calc "2 / 3"; else calc "$1 / 2"; fi; }

printf 'quantity\td\tmeasured\terror\treference\treference_error\tsource\tdeviation\tregime\n'
printf '# format: coolgas-table 2\n'
printf '# tool: pipelines/dimensions/table.sh\n'
first=$(ls "$tables"/fit_*.tsv | head -n 1)
printf '# version: %s\n' "$(value "$first" version '#')"
printf '# simulator_version: %s\n' "$(sed -n 's/^# simulator_version: //p' "$tables"/energy_*.tsv | sort -u | paste -sd ';' -)"
printf '# date: %s\n' "$(date -u +%Y-%m-%d)"
for d in $dims; do
  set -- $(theta_row gas "$d")
  theta=$1 err=$2 reg=$(regime gas "$d" "$3" "$4")
  case $d in
    1) row "theta, inelastic gas" 1 "$theta" "$err" "$(ba_mf 1)" 0 \
         "2d/(d+2) = Burgers' 2/3: the sticky gas (Ben-Naim, Chen, Doolen, Redner, PRL 83, 4069 (1999))" "$reg" ;;
    2) row "theta, inelastic gas" 2 "$theta" "$err" "$(ba_mf 2)" 0 \
         "2d/(d+2) = d/2 = 1 (Nie, Ben-Naim, Chen, PRL 89, 204301 (2002))" "$reg" ;;
    *) row "theta, inelastic gas" "$d" "$theta" "$err" "$(ba_mf "$d")" 0 "ballistic aggregation's mean field 2d/(d+2)" "$reg"
       row "theta, inelastic gas" "$d" "$theta" "$err" "$(burgers "$d")" 0 "Burgers' equation d/2" "$reg" ;;
  esac
done
for d in $dims; do
  set -- $(theta_row ba "$d")
  theta=$1 err=$2 reg=$(regime ba "$d" "$3" "$4")
  case $d in
    1) source="2d/(d+2) = 2/3, exact in 1D (Frachebourg, PRL 82, 1502 (1999))" ;;
    3) source="mean field 2d/(d+2) (Pathak et al. 2014 measure 1.206 +- 0.005 at phi = 0.208)" ;;
    *) source="mean field 2d/(d+2)" ;;
  esac
  row "theta, ballistic aggregation" "$d" "$theta" "$err" "$(ba_mf "$d")" 0 "$source" "$reg"
done
# The velocity distribution at the end of the gas's window: its excess
# kurtosis kappa (0 for a Maxwellian in any d) against BA's at the end of
# BA's window, where the sticky-gas picture says the gas moves as BA does
# (exact in 1D: Ben-Naim et al. 1999; the paper finds them different in 3D).
for d in $dims; do
  tg=$(value "$tables/fit_gas_d$d.tsv" t_max) tb=$(value "$tables/fit_ba_d$d.tsv" t_max)
  vg=$tables/velocity_gas_d$d.tsv vb=$tables/velocity_ba_d$d.tsv
  row "kappa, gas at t = $(when "$tg") against BA at t = $(when "$tb")" "$d" \
    "$(at_time "$vg" kappa "$tg")" "$(at_time "$vg" kappa_err "$tg")" \
    "$(at_time "$vb" kappa "$tb")" "$(at_time "$vb" kappa_err "$tb")" \
    "the sticky-gas picture: the gas's velocities are BA's (Ben-Naim et al. 1999)" \
    "$(regime gas "$d" "$(value "$tables/fit_gas_d$d.tsv" t_min)" "$tg")"
done
# In 2D, Nie et al. find the late velocities Gaussian.
case " $dims " in *" 2 "*)
  tg=$(value "$tables/fit_gas_d2.tsv" t_max) vg=$tables/velocity_gas_d2.tsv
  row "kappa, gas at t = $(when "$tg")" 2 "$(at_time "$vg" kappa "$tg")" "$(at_time "$vg" kappa_err "$tg")" 0 0 \
    "Gaussian late (Nie, Ben-Naim, Chen 2002)" "$(regime gas 2 "$(value "$tables/fit_gas_d2.tsv" t_min)" "$tg")" ;;
esac
