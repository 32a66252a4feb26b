#!/bin/sh
# readme-table.sh EXPONENTS_MD DOCUMENT [NAME]
# Puts a pipeline's exponent table (OUT/exponents.md) into DOCUMENT between
# the lines '<!-- NAME:begin -->' and '<!-- NAME:end -->' (NAME defaults to
# 'exponents', the demo's table), so the documented numbers are always a
# pipeline's output, never typed by hand. The tables live in
# docs/validation.md:
#   sh pipelines/readme-table.sh out/demo/exponents.md docs/validation.md
#   sh pipelines/readme-table.sh out/workstation/exponents.md docs/validation.md exponents-workstation
set -e
table=$1
readme=$2
name=${3:-exponents}
grep -q "^<!-- $name:begin -->\$" "$readme" && grep -q "^<!-- $name:end -->\$" "$readme" || {
  echo "readme-table.sh: $readme has no '<!-- $name:begin -->' ... '<!-- $name:end -->' lines" >&2; exit 2; }
tmp=$(mktemp "$readme.XXXXXX")
awk -v table="$table" -v begin="<!-- $name:begin -->" -v end="<!-- $name:end -->" '
  $0 == begin { print; while ((getline line < table) > 0) print line; skip = 1; next }
  $0 == end { skip = 0 }
  !skip { print }' "$readme" > "$tmp"
mv "$tmp" "$readme"
