#!/bin/sh
# markdown.sh DIMENSIONS_TSV
# The dimension study's table (pipelines/dimensions/table.sh) as Markdown,
# headed by the versions that made the runs and the analysis and the date;
# README.md's copy is made by pipelines/readme-table.sh.
set -e
tsv=$1
meta() { sed -n "s/^# $1: //p" "$tsv" | head -n 1; }
echo "Runs by coolgas $(meta simulator_version), analysed by coolgas $(meta version) on $(meta date) (\`make -C pipelines/dimensions\`)."
echo
echo "| quantity | d | measured | reference | source | (measured − reference)/σ | in the regime? |"
echo "|---|---|---|---|---|---|---|"
awk -F '\t' '
  function num(v) { return v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
  function show(v, e) { if (!num(v)) return v; s = sprintf("%.3f", v); if (num(e) && e > 0) s = s " ± " sprintf("%.3f", e); return s }
  FNR == 1 || /^#/ || NF == 0 { next }
  { printf "| %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, show($3, $4), show($5, $6), $7, $8, $9 }' "$tsv"
