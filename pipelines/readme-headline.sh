#!/bin/sh
# readme-headline.sh VALIDATION_MD README_MD
# Puts README's table of headline exponents between the lines
# '<!-- headline:begin -->' and '<!-- headline:end -->', built from the
# demo's and the workstation's exponent tables in VALIDATION_MD (which
# readme-table.sh fills from the pipelines' output), so that the README's
# numbers are a pipeline's output too:
#   sh pipelines/readme-headline.sh docs/validation.md README.md
# A row outside the paper's regime says so; a value not measured reads
# "not measured". The table names no build: which commits made and analysed
# each scale's runs stays in VALIDATION_MD and in the pipelines' files.
set -e
validation=$1
readme=$2
grep -q '^<!-- headline:begin -->$' "$readme" && grep -q '^<!-- headline:end -->$' "$readme" || {
  echo "readme-headline.sh: $readme has no '<!-- headline:begin -->' ... '<!-- headline:end -->' lines" >&2; exit 2; }
table=$(mktemp)
awk -F ' [|] ' '
  # The rows shown, by the start of their quantity column, and their labels.
  BEGIN {
    n = split("theta, collapse|z, same collapse|theta, power-law fit at L = |eta, f(x)|tau, N(m)|theta_BA at phi = 0.208", key, "|")
    split("θ, finite-size collapse of E(t)|z, same collapse|θ, power-law fit at the largest L|η, f(x) ~ x^-η for x ≫ 1|τ, N(m) ~ m^-τ|θ_BA at φ = 0.208", label, "|")
  }
  $0 == "<!-- exponents:begin -->" { scale = "demo" }
  $0 == "<!-- exponents-workstation:begin -->" { scale = "workstation" }
  /^<!-- exponents.*:end -->$/ { scale = "" }
  scale != "" && /^\| / {
    q = substr($1, 3)
    for (i = 1; i <= n; i++) if (index(q, key[i]) == 1 && !((scale, i) in cell)) {
      v = $3 == "nan" ? "not measured" : $3
      if (i == 3) { L = q; sub(/.*at L = /, "", L); sub(/ .*/, "", L); v = v " (L = " L ")" }
      if ($6 ~ /^no/) v = v " (outside the paper'"'"'s regime)"
      cell[scale, i] = v; paper[i] = $4
    }
  }
  END {
    print "From the exponent tables of [docs/validation.md](docs/validation.md), which also say which builds made the runs:"
    print ""
    print "| quantity | paper | demo | workstation |"
    print "|---|---|---|---|"
    for (i = 1; i <= n; i++) printf "| %s | %s | %s | %s |\n", label[i], paper[i], cell["demo", i], cell["workstation", i]
  }' "$validation" > "$table"
tmp=$(mktemp "$readme.XXXXXX")
awk -v table="$table" '
  $0 == "<!-- headline:begin -->" { print; while ((getline line < table) > 0) print line; skip = 1; next }
  $0 == "<!-- headline:end -->" { skip = 0 }
  !skip { print }' "$readme" > "$tmp"
rm -f "$table"
mv "$tmp" "$readme"
