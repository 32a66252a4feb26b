#!/bin/sh
# markdown.sh EFFECTS_TSV
# The effects table (pipelines/effects/table.sh) as Markdown, headed by the
# versions that made the runs and the analysis and the date, and the
# verdict rule (pipelines/row-verdict.sh --rules).
set -e
tsv=$1
here=$(dirname "$0")
meta() { sed -n "s/^# $1: //p" "$tsv" | head -n 1; }
echo "Runs by coolgas $(meta simulator_version), analysed by coolgas $(meta version) on $(meta date) (\`make -C pipelines/effects\`)."
echo
echo "| effect | quantity | measured | theory | tolerance | (measured − theory)/σ | verdict | theory's source |"
echo "|---|---|---|---|---|---|---|---|"
awk -F '\t' '
  function num(v) { return v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
  function show(v, e) { if (!num(v)) return v; s = sprintf("%.4g", v); if (num(e) && e > 0) s = s " ± " sprintf("%.2g", e); return s }
  FNR == 1 || /^#/ || NF == 0 { next }
  { printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, show($3, $4), show($5, $6), show($7, ""), $8, $9, $10 }' "$tsv"
echo
# The exponent table's rule, with the row's theory where it says the paper.
echo "Verdicts: $(sh "$here/../row-verdict.sh" --rules | sed "s/the paper's/the theory's/g; s/the paper/the theory/g")"
