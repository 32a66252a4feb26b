#!/bin/sh
# theta-causes.sh fits BIN < SPECS
# theta-causes.sh share LATE_TIME MMAX_TABLE...
# The measurements behind the exponent table's verdicts on theta (Fig. 2's
# sets, theta_BA) and on the largest cluster's share (pipelines/theta-causes.mk).
#
# fits: SPECS has lines "KIND TMIN:TMAX MEAN_TABLE [RUN_TABLE...]", MEAN_TABLE
# the coolgas-energy table of one or more runs (RUN_TABLEs: each run alone)
# and TMIN:TMAX the pipeline's fit window. Each line gives one row per window:
#   KIND param: window 0, the pipeline's; 1, its start sqrt(10) times later;
#               2, its last half decade
#   KIND size:  window 3, from TMIN to the finite-size crossover x = 0.1
#               (t = 0.1 L^(5/2)); 2, that window's last half decade
#   KIND ba:    window 0, the pipeline's; 4, from TMIN to the run's end
# A fit E ~ t^-theta over the window, unweighted as Fig. 1's (a few runs'
# standard errors make some points nearly infinitely heavy), beside what
# says how much that number depends on the window: the smoothed local slope
# -d ln E/d ln t (coolgas-fit --local-slope, +-1/4 decade) at its lowest in
# the window and at the window's last point, and the scatter of the same fit
# over the single runs (a fit error from one run counts only its points, not
# how much another seed would differ). Columns:
#   model  0 inelastic gas, 1 ballistic aggregation (r0, delta then 0)
#   phi r0 delta L runs  of MEAN_TABLE (its provenance)
#   window  the code above
#   t_min t_max x_max  the window's ends as fitted, x_max = t_max/L^(5/2)
#   theta theta_err  the fit
#   theta_sd  standard deviation of the single runs' theta (0 with < 2 runs)
#   slope_min t_slope_min slope_end  the local slope: its minimum in the
#           window, where, and its value at the window's last point
#
# share: the largest cluster's share of the particles (coolgas-clusters
# --series tables) at t = 0 and at LATE_TIME (nearest dump), one row per
# table, against the density of unit cells: n = N/floor(L)^3 particles per
# cell, an upper bound of the occupied cells' fraction p (two centres can
# share a cell). Unit cells occupied at random percolate above the simple
# cubic site threshold p_c = 0.3116; a share at t = 0 that does not fall with
# L is a spanning cluster of the definition, not of the gas's clustering.
# Columns: phi L N n share_0 t_late share_late.
set -e
mode=$1
shift
prov() { sed -n "s/^# $1: //p" "$2" | head -n 1; }
case $mode in
fits)
  bin=$1
  printf 'model\tphi\tr0\tdelta\tL\truns\twindow\tt_min\tt_max\tx_max\ttheta\ttheta_err\ttheta_sd\tslope_min\tt_slope_min\tslope_end\n'
  printf '# format: coolgas-table 2\n'
  printf '# tool: pipelines/theta-causes.sh fits\n'
  printf '# version: %s\n' "$("$bin/coolgas-fit" --version | head -n 1)"
  printf '# fit: coolgas-fit --power --no-weights over the window, of the mean E(t) of the runs\n'
  printf '# local_slope: coolgas-fit --local-slope (smoothed over +-0.25 decades) of the same table\n'
  printf '# window: 0 the pipeline'"'"'s fit window; 1 its start sqrt(10) times later; 2 its last half decade; 3 Fig. 1: from the fit window'"'"'s start to x = t/L^(5/2) = 0.1; 4 BA: from the fit window'"'"'s start to the run'"'"'s end\n'
  tmp=${TMPDIR:-/tmp}/theta-causes.$$
  trap 'rm -f "$tmp".*' EXIT
  # One line per window: "CODE TMIN:TMAX MEAN [RUNS]".
  while read -r kind range mean runs; do
    [ -n "$kind" ] || continue
    lo=${range%%:*} hi=${range#*:}
    case $kind in
      param) printf '0 %s %s %s\n1 %s:%s %s %s\n2 %s:%s %s %s\n' "$range" "$mean" "$runs" \
               "$(awk "BEGIN { printf \"%.6g\", $lo * sqrt(10) }")" "$hi" "$mean" "$runs" \
               "$(awk "BEGIN { printf \"%.6g\", $hi / sqrt(10) }")" "$hi" "$mean" "$runs" ;;
      size) end=$(awk "BEGIN { printf \"%.6g\", 0.1 * $(prov L "$mean") ^ 2.5 }")
            printf '3 %s:%s %s %s\n2 %s:%s %s %s\n' "$lo" "$end" "$mean" "$runs" \
              "$(awk "BEGIN { printf \"%.6g\", $end / sqrt(10) }")" "$end" "$mean" "$runs" ;;
      ba) printf '0 %s %s %s\n4 %s: %s %s\n' "$range" "$mean" "$runs" "$lo" "$mean" "$runs" ;;
      *) echo "theta-causes.sh: unknown kind $kind" >&2; exit 2 ;;
    esac
  done > "$tmp.specs"
  while read -r window range mean runs; do
    printf '# input: window %s, t = %s, %s (%s runs)\n' "$window" "$range" "$mean" "$(prov runs "$mean")"
  done < "$tmp.specs"
  while read -r window range mean runs; do
    "$bin/coolgas-fit" --power --no-weights --t-window "$range" "$mean" > "$tmp.fit" 2> "$tmp.err" \
      || { cat "$tmp.err" >&2; exit 1; }
    "$bin/coolgas-fit" --local-slope "$mean" > "$tmp.slope" 2> "$tmp.err" || { cat "$tmp.err" >&2; exit 1; }
    sd=0
    if [ "$(echo $runs | wc -w)" -ge 2 ]; then
      sd=$(for r in $runs; do
             "$bin/coolgas-fit" --power --no-weights --t-window "$range" "$r" 2> /dev/null \
               | awk -F '\t' 'NR > 1 && !/^#/ && NF > 0 { print $1 }'
           done | awk '{ s += $1; ss += $1 * $1; n++ } END { if (n < 2) print 0; else printf "%.6g", sqrt((ss - s * s / n) / (n - 1)) }')
    fi
    model=0
    [ "$(prov model "$mean")" = aggregation ] && model=1
    r0=$(prov r0 "$mean") delta=$(prov delta "$mean")
    awk -F '\t' -v model="$model" -v phi="$(prov phi "$mean")" -v r0="${r0:-0}" -v delta="${delta:-0}" \
        -v L="$(prov L "$mean")" -v runs="$(prov runs "$mean")" -v window="$window" -v sd="$sd" '
      FNR == 1 || /^#/ || NF == 0 { next }
      FILENAME == ARGV[1] { theta = $1; err = $2; lo = $5; hi = $6; next }
      $1 >= lo && $1 <= hi { if (min == "" || $2 < min) { min = $2; tmin = $1 } last = $2 }
      END { printf "%d\t%.6g\t%g\t%g\t%g\t%d\t%d\t%.6g\t%.6g\t%.4g\t%.6g\t%.3g\t%s\t%.4g\t%.4g\t%.4g\n",
              model, phi, r0, delta, L, runs, window, lo, hi, hi / L ^ 2.5, theta, err, sd, min, tmin, last }' \
      "$tmp.fit" "$tmp.slope"
  done < "$tmp.specs"
  ;;
share)
  late=$1
  shift
  printf 'phi\tL\tN\tn\tshare_0\tt_late\tshare_late\n'
  printf '# format: coolgas-table 2\n'
  printf '# tool: pipelines/theta-causes.sh share\n'
  printf '# site_percolation_threshold: 0.3116 (simple cubic lattice, site)\n'
  printf '# n: particles per unit cell, N/floor(L)^3 (an upper bound of the occupied cells'"'"' fraction)\n'
  printf '# late_time: %s\n' "$late"
  for t in "$@"; do printf '# input: %s\n' "$t"; done
  for t in "$@"; do
    awk -F '\t' -v phi="$(prov phi "$t")" -v L="$(prov L "$t")" -v N="$(prov N "$t")" -v late="$late" '
      FNR == 1 || /^#/ || NF == 0 { next }
      $1 == 0 { s0 = $7 }
      { d = $1 - late; if (d < 0) d = -d; if (best == "" || d < best) { best = d; tl = $1; sl = $7 } }
      END { c = int(L + 1e-9); printf "%.6g\t%g\t%d\t%.4g\t%.4g\t%g\t%.4g\n", phi, L, N, N / (c * c * c), s0, tl, sl }' "$t"
  done
  ;;
*)
  echo "usage: theta-causes.sh fits BIN < SPECS | theta-causes.sh share LATE_TIME MMAX_TABLE..." >&2
  exit 2
  ;;
esac
