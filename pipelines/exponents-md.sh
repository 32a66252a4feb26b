#!/bin/sh
# exponents-md.sh EXPONENTS_TSV SCALE
# The exponent table (pipelines/exponents.sh) as Markdown, headed by the
# scale, the versions (commits) that made the runs and the analysis, and the
# date it was measured; the tables of docs/validation.md are copies made by
# pipelines/readme-table.sh.
set -e
tsv=$1
scale=$2
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
