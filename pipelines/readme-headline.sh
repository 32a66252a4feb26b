#!/bin/sh
# readme-headline.sh VALIDATION_MD README_MD
# Puts README's table of headline exponents between the lines
# '<!-- headline:begin -->' and '<!-- headline:end -->', built from the
# demo's and the workstation's exponent tables in VALIDATION_MD (which
# readme-table.sh fills from the pipelines' output), so that the README's
# numbers are a pipeline's output too:
#   sh pipelines/readme-headline.sh docs/validation.md README.md
# Each cell is the row's value and its verdict word, as the table has them
# (pipelines/row-verdict.sh states the rules); a row outside the paper's
# regime says so; a row a table lacks reads "—". The table names no build:
# which commits made and analysed each scale's runs stays in VALIDATION_MD
# and in the pipelines' files. The columns of a table are found by their
# names, so a table made before it had a verdict column gives its values
# without one.
set -e
validation=$1
readme=$2
here=$(dirname "$0")
grep -q '^<!-- headline:begin -->$' "$readme" && grep -q '^<!-- headline:end -->$' "$readme" || {
  echo "readme-headline.sh: $readme has no '<!-- headline:begin -->' ... '<!-- headline:end -->' lines" >&2; exit 2; }
table=$(mktemp)
trap 'rm -f "$table"' EXIT
awk -F ' [|] ' '
  # The rows shown: the start of their quantity in the exponent table, and their labels.
  BEGIN {
    n = split("θ, collapse|z, collapse with zθ = 3|z, free collapse|θ, power-law fit at L = |η, f(x)|τ, N(m) ~ m^-τ, unit cells|τ, N(m) ~ m^-τ, contact|θ_BA at φ = 0.208", key, "|")
    split("θ, finite-size collapse of E(t), θ and z fitted|z, the paper'"'"'s method: the same collapse with zθ = 3 held|z, the free fit: θ and z fitted together|θ, power-law fit at the largest L|η, f(x) ~ x^-η for x ≫ 1, the paper'"'"'s method|τ, N(m) ~ m^-τ, the paper'"'"'s unit-cell clusters|τ, contact clusters (spheres closer than 1.1 σ)|θ_BA at φ = 0.208", label, "|")
    # The names of tables made before the short names (ASCII, the free z
    # "same collapse") and before the contact clusters (one τ, by unit cells);
    # ";" separates a row'"'"'s several older names.
    split("theta, collapse|-|z, same collapse|theta, power-law fit at L = |-|tau, N(m);τ, N(m) ~ m^-τ|-|theta_BA at phi = 0.208", old, "|")
  }
  # Whether quantity q starts with one of the older names (";"-separated, "-" none).
  function older(q, names,    k, m, each) {
    m = split(names, each, ";")
    for (k = 1; k <= m; k++) if (each[k] != "-" && index(q, each[k]) == 1) return 1
    return 0
  }
  $0 == "<!-- exponents:begin -->" { scale = "demo"; head = 0 }
  $0 == "<!-- exponents-workstation:begin -->" { scale = "workstation"; head = 0 }
  /^<!-- exponents.*:end -->$/ { scale = "" }
  # The exponent table: the one whose first column is "quantity".
  scale != "" && /^\| quantity \|/ { head = 1; delete col; line = substr($0, 3); nc = split(line, name, / [|] ?/)
                                     for (i = 1; i <= nc; i++) col[name[i]] = i; next }
  scale != "" && head && /^\| / && !/^\|---/ {
    line = substr($0, 3); split(line, c, / [|] ?/)
    q = c[1]
    for (i = 1; i <= n; i++) if ((index(q, key[i]) == 1 || older(q, old[i])) && !((scale, i) in cell)) {
      v = c[col["measured"]] == "nan" ? "not measured" : c[col["measured"]]
      if (i == 4) { L = q; sub(/.*at L = /, "", L); sub(/ .*/, "", L); v = v " (L = " L ")" }
      if ("verdict" in col) { v = v ": " c[col["verdict"]]; note[scale, i] = c[col["notes"]] }
      else if (c[col["in the paper'"'"'s regime?"]] ~ /^no/) note[scale, i] = "outside the paper'"'"'s regime"
      cell[scale, i] = v; paper[i] = c[col["paper"]]
    }
  }
  scale != "" && head && !/^\|/ { head = 0 }
  # A long note is a footnote under the table: "- [k] text".
  scale != "" && /^- \[[0-9]+\] / { k = substr($0, 4); sub(/\].*/, "", k); foot[scale, "[" k "]"] = substr($0, index($0, "] ") + 2) }
  END {
    for (sc in note) {
      split(sc, at, SUBSEP); t = ((at[1], note[sc]) in foot) ? foot[at[1], note[sc]] : note[sc]
      if (index(t, "outside the paper") == 1) cell[sc] = cell[sc] " (outside the paper'"'"'s regime)"
    }
    print "From the exponent tables of [docs/validation.md](docs/validation.md), which give every row with its notes,"
    print "the rules of its verdict and the builds that made the runs. z is measured two ways. The paper'"'"'s method"
    print "holds zθ = 3 (its Fig. 1 plots E L³ against t/L^z) and fits z alone; with θ fixed by the power-law"
    print "part of E(t), that z is about 3/θ, a test of the relation more than a measurement of z. The free fit"
    print "fits θ and z together; since the power-law part collapses at any z, only the crossovers of the"
    print "different boxes fix it, loosely at these sizes (the robustness block beside the table shows by how much)."
    print ""
    print "| quantity | paper | demo | workstation |"
    print "|---|---|---|---|"
    for (i = 1; i <= n; i++) printf "| %s | %s | %s | %s |\n", label[i], (i in paper) ? paper[i] : "—",
      ((("demo", i) in cell) ? cell["demo", i] : "—"), ((("workstation", i) in cell) ? cell["workstation", i] : "—")
  }' "$validation" > "$table"
tmp=$(mktemp "$readme.XXXXXX")
awk -v table="$table" '
  $0 == "<!-- headline:begin -->" { print; while ((getline line < table) > 0) print line; skip = 1; next }
  $0 == "<!-- headline:end -->" { skip = 0 }
  !skip { print }' "$readme" > "$tmp"
mv "$tmp" "$readme"
