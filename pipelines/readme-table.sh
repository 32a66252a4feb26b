#!/bin/sh
# readme-table.sh EXPONENTS_MD README
# Puts a pipeline's exponent table (OUT/exponents.md) into README between
# the lines '<!-- exponents:begin -->' and '<!-- exponents:end -->', so the
# README's numbers are always a pipeline's output, never typed by hand:
#   sh pipelines/readme-table.sh out/demo/exponents.md README.md
set -e
table=$1
readme=$2
grep -q '^<!-- exponents:begin -->$' "$readme" && grep -q '^<!-- exponents:end -->$' "$readme" || {
  echo "readme-table.sh: $readme has no '<!-- exponents:begin -->' ... '<!-- exponents:end -->' lines" >&2; exit 2; }
tmp=$(mktemp "$readme.XXXXXX")
awk -v table="$table" '
  /^<!-- exponents:begin -->$/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
  /^<!-- exponents:end -->$/ { skip = 0 }
  !skip { print }' "$readme" > "$tmp"
mv "$tmp" "$readme"
