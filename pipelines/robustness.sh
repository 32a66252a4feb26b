#!/bin/sh
# robustness.sh TABLES T_WINDOW OTHER_WEIGHTS ETA_WINDOW SMALLEST_L
# The robustness block of the exponent table (pipelines/robustness.mk): the
# pipeline's collapse (TABLES/collapse.tsv) and the same collapse under each
# other analysis choice (TABLES/collapse_robust_CHOICE.tsv, coolgas-collapse
# --summary rows), one row each, as a TSV table with columns
#   choice  change  theta  theta_err  z  z_err  eta  eta_err  quality  verdict
# The verdict compares each choice with the pipeline's own: it "agrees" when
# theta, z and eta each differ by no more than the larger of the two errors
# (the choices use largely the same runs, so their errors are not
# independent and a difference within either one is no evidence of a
# change); otherwise it names what moved and by how many of those errors, so
# the table says which choice decides. (The paper's method, z theta held at
# d, is in the exponent table itself, beside the free fit: pipelines/exponents.sh.)
# eta's error is that of its power-law fit to the pooled scaled points, which
# treats them as independent: too small, so eta "decides" more readily than
# theta and z, whose errors are the jackknife over whole runs.
# The other arguments are the choices' settings, for the 'change' column.
set -e
tables=$1 t_window=$2 other_weights=$3 eta_window=$4 smallest=$5
here=$(dirname "$0")
value() { sh "$here/tsv-value.sh" "$@"; }
base=$tables/collapse.tsv
meta() { value "$base" "$1" '#'; }

printf 'choice\tchange\ttheta\ttheta_err\tz\tz_err\teta\teta_err\tquality\tverdict\n'
printf '# format: coolgas-table 2\n'
printf '# tool: pipelines/robustness.sh\n'
printf '# version: %s\n' "$(meta version)"
printf '# rule: a choice agrees when theta, z and eta each differ from the pipeline'"'"'s by at most the larger of the two errors\n'
b_theta=$(meta theta) b_theta_err=$(meta theta_err) b_z=$(meta z) b_z_err=$(meta z_err)
b_eta=$(meta eta) b_eta_err=$(meta eta_err) b_q=$(meta quality)
printf 'pipeline\tt = %s, weights %s, eta over x = %s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(meta t_window)" \
  "$(meta weights | cut -d: -f1)" "$(meta eta_window)" "$b_theta" "$b_theta_err" "$b_z" "$b_z_err" "$b_eta" "$b_eta_err" \
  "$b_q" "the reference of the rows below"

for choice in start weights eta drop; do
  case $choice in
    start) change="t from ${t_window%%:*} (window $t_window)" ;;
    weights) change="weights $other_weights" ;;
    eta) change="eta over x = $eta_window" ;;
    drop) change="without L = $smallest" ;;
  esac
  t=$tables/collapse_robust_$choice.tsv
  err=$(sed -n 's/^# error: //p' "$t")
  if [ -n "$err" ]; then
    printf '%s\t%s\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnot determined: %s\n' "$choice" "$change" "$err"
    continue
  fi
  theta=$(value "$t" theta) theta_err=$(value "$t" theta_err) z=$(value "$t" z) z_err=$(value "$t" z_err)
  eta=$(value "$t" eta) eta_err=$(value "$t" eta_err) q=$(value "$t" quality)
  # A search that ran off to z <= 1/2 or theta <= 0 found no finite-size
  # scaling: with t/L^z hardly scaled the curves are only shifted up or down
  # (by z theta ln L), which sizes too close together allow at any z (the
  # demo's L = 48 and 68 alone: z = 1.5e-7, theta = -5.6e5).
  if awk "BEGIN { exit !($z <= 0.5 || $theta <= 0) }"; then
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\tnot determined: the search ran off to z = %s, theta = %s, a collapse by a vertical shift alone (the sizes left do not fix z)\n' \
      "$choice" "$change" "$theta" "$theta_err" "$z" "$z_err" "$eta" "$eta_err" "$q" "$(printf '%.3g' "$z")" "$(printf '%.3g' "$theta")"
    continue
  fi
  verdict=$(awk -v a="$theta $theta_err $b_theta $b_theta_err" -v b="$z $z_err $b_z $b_z_err" -v e="$eta $eta_err $b_eta $b_eta_err" '
    function num(v) { return v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
    # "name moves by k sigma" when |v - ref| exceeds the larger error
    function judge(name, s,   p, d, m) {
      split(s, p, " ")
      if (!num(p[1]) || !num(p[3])) { if (name == "eta") unknown = unknown " eta not fitted (" (num(p[1]) ? "pipeline" : "this choice") ");"; return }
      d = p[1] - p[3]; if (d < 0) d = -d
      m = (p[2] > p[4] ? p[2] : p[4])
      if (m > 0 && d > m) moved = moved sprintf(" %s by %+.3g (%.1f sigma)", name, p[1] - p[3], d / m) ";"
      if (m == 0 && d > 0) moved = moved sprintf(" %s by %+.3g (no error)", name, p[1] - p[3]) ";"
    }
    BEGIN {
      judge("theta", a); judge("z", b); judge("eta", e)
      v = (moved == "" ? "agrees" : "decides:" moved)
      sub(/;$/, "", v)
      if (unknown != "") v = v ";" unknown
      sub(/;$/, "", v)
      print v
    }')
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$choice" "$change" "$theta" "$theta_err" "$z" "$z_err" \
    "$eta" "$eta_err" "$q" "$verdict"
done
