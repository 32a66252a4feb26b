#!/bin/sh
# exponents-md.sh EXPONENTS_TSV SCALE [ROBUSTNESS_TSV]
# The exponent table (pipelines/exponents.sh) as Markdown, headed by the
# scale, the versions (commits) that made the runs and the analysis, and the
# date it was measured; the tables of docs/validation.md are copies made by
# pipelines/readme-table.sh. With ROBUSTNESS_TSV (pipelines/robustness.sh),
# the robustness block of Fig. 1's collapse follows the table. It ends with
# the paper's conclusions judged on the table (pipelines/verdicts.sh).
set -e
tsv=$1
scale=$2
robust=${3:-}
here=$(dirname "$0")
meta() { sed -n "s/^# $1: //p" "$tsv" | head -n 1; }
echo "SCALE = $scale: runs by coolgas $(meta simulator_version), analysed by coolgas $(meta version) on $(meta date)."
echo
echo "| quantity | Fig. | measured | paper | (measured − paper)/σ | in the paper's regime? |"
echo "|---|---|---|---|---|---|"
awk -F '\t' '
  function num(v) { return v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
  function show(v, e) { if (!num(v)) return v; s = sprintf("%.3f", v); if (num(e) && e > 0) s = s " ± " sprintf("%.3f", e); return s }
  FNR == 1 || /^#/ || NF == 0 { next }
  { printf "| %s | %s | %s | %s | %s | %s |\n", $1, $2, show($3, $4), show($5, $6), $7, $8 }' "$tsv"
verdicts() {
  echo
  echo "The paper's conclusions, judged on this table (pipelines/verdicts.sh states the rules): a claim is"
  echo "supported when its numbers lie within the tolerance named, not supported when they lie beyond it by"
  echo "more than 3 errors, and not decided at this scale when its evidence is outside the paper's regime or"
  echo "its errors are too large; the reason is given each time."
  echo
  echo "| the paper's claim | evidence | verdict |"
  echo "|---|---|---|"
  sh "$here/verdicts.sh" "$tsv" | awk -F '\t' '{ printf "| %s | %s | %s |\n", $1, $2, $3 }'
}
[ -n "$robust" ] || { verdicts; exit 0; }
echo
echo "Robustness of the collapse (Fig. 1): θ, z, η under other analysis choices, each changing one thing"
echo "(pipelines/robustness.mk); a choice agrees when each differs from the pipeline's by at most the larger"
echo "of the two errors (θ, z: the jackknife over whole runs; η: its fit to the pooled scaled points, which treats"
echo "them as independent and so is too small). Q is the collapse quality (a χ² per point with weights seeds)"
echo
echo "| analysis choice | θ | z | η | Q | verdict |"
echo "|---|---|---|---|---|---|"
awk -F '\t' '
  function num(v) { return v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
  function show(v, e) { if (!num(v)) return v; s = sprintf("%.3f", v); if (num(e) && e > 0) s = s " ± " sprintf("%.3f", e); return s }
  FNR == 1 || /^#/ || NF == 0 { next }
  { printf "| %s: %s | %s | %s | %s | %s | %s |\n", $1, $2, show($3, $4), show($5, $6), show($7, $8), num($9) ? sprintf("%.3g", $9) : $9, $10 }' "$robust"
verdicts
