#!/bin/sh
# exponents-md.sh EXPONENTS_TSV SCALE [ROBUSTNESS_TSV]
# The exponent table (pipelines/exponents.sh) as Markdown, headed by the
# scale, the versions (commits) that made the runs and the analysis, and the
# date it was measured; the tables of docs/validation.md are copies made by
# pipelines/readme-table.sh. Each row shows its short name, its numbers, its
# verdict in a column of its own, and its note: in the notes column when
# short, else as a numbered footnote under the table. With ROBUSTNESS_TSV
# (pipelines/robustness.sh), the robustness block of Fig. 1's free collapse
# follows the table. It ends with the paper's conclusions judged on the table
# (pipelines/verdicts.sh). Names read as symbols (theta as θ, ...); file
# names keep their spelling.
set -e
tsv=$1
scale=$2
robust=${3:-}
here=$(dirname "$0")
meta() { sed -n "s/^# $1: //p" "$tsv" | head -n 1; }
# ASCII names as symbols, whole words only (tables/theta_causes.tsv stays).
symbols() {
  sed -E 's/\btheta_BA\^mf\b/θ_BA^mf/g; s/\btheta_BE\b/θ_BE/g; s/\b(theta|beta|tau)_BA\b/\1@BA/g
    s/\btheta\b/θ/g; s/\bbeta\b/β/g; s/\beta\b/η/g; s/\btau\b/τ/g; s/\bkappa\b/κ/g; s/\balpha\b/α/g
    s/\bphi\b/φ/g; s/\bPhi\b/Φ/g; s/\bdelta\b/δ/g; s/\bsigma\b/σ/g; s/\bpi\b/π/g; s/ \+- / ± /g
    s/θ@BA/θ_BA/g; s/β@BA/β_BA/g; s/τ@BA/τ_BA/g; s/(^|[^A-Za-z_])z θ/\1zθ/g'
}
# Short notes stay in the table; longer ones become footnotes.
NOTE_MAX=70
echo "SCALE = $scale: runs by coolgas $(meta simulator_version), analysed by coolgas $(meta version) on $(meta date)."
echo
echo "$(sh "$here/row-verdict.sh" --rules) (pipelines/row-verdict.sh; a row's tolerance is in the column \"agrees within\".)" | symbols
echo
echo "| quantity | Fig. | measured | paper | agrees within | (measured − paper)/σ | verdict | notes |"
echo "|---|---|---|---|---|---|---|---|"
notes=$(mktemp)
trap 'rm -f "$notes"' EXIT
awk -F '\t' -v notes="$notes" -v max="$NOTE_MAX" '
  function num(v) { return v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
  function show(v, e) { if (!num(v)) return v; s = sprintf("%.3f", v); if (num(e) && e > 0) s = s " ± " sprintf("%.3f", e); return s }
  FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  /^#/ || NF == 0 { next }
  {
    note = $col["note"] == "-" ? "" : $col["note"]
    reg = $col["regime"]
    if (reg ~ /^no/) note = "outside the paper'"'"'s regime: " substr(reg, 5) (note == "" ? "" : "; " note)
    if (length(note) > max) { k++; print "- [" k "] " note > notes; note = "[" k "]" }
    paper = $col["paper"]; if (num(paper)) paper = show(paper, $col["paper_error"])
    printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", $col["quantity"], $col["figure"], show($col["measured"], $col["error"]),
      paper, $col["tolerance"], $col["deviation"], $col["verdict"], note
  }' "$tsv" | symbols
if [ -s "$notes" ]; then
  echo
  echo "Notes:"
  echo
  symbols < "$notes"
fi
verdicts() {
  echo
  echo "The paper's conclusions, judged on this table: $(sh "$here/verdicts.sh" --rules) (pipelines/verdicts.sh)" | symbols
  echo
  echo "| the paper's claim | evidence | verdict |"
  echo "|---|---|---|"
  sh "$here/verdicts.sh" "$tsv" | awk -F '\t' '{ printf "| %s | %s | %s |\n", $1, $2, $3 }' | symbols
}
[ -n "$robust" ] || { verdicts; exit 0; }
echo
echo "Robustness of the free collapse (Fig. 1): θ, z, η under other analysis choices, each changing one thing"
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
  { printf "| %s: %s | %s | %s | %s | %s | %s |\n", $1, $2, show($3, $4), show($5, $6), show($7, $8), num($9) ? sprintf("%.3g", $9) : $9, $10 }' "$robust" | symbols
verdicts
