#!/bin/sh
# readme-table.sh EXPONENTS_MD DOCUMENT [NAME]
# Puts a pipeline's exponent table (OUT/exponents.md) into DOCUMENT between
# the lines '<!-- NAME:begin -->' and '<!-- NAME:end -->' (NAME defaults to
# 'exponents', the demo's table), so the documented numbers are always a
# pipeline's output, never typed by hand, made by committed builds. The tables live in
# docs/validation.md:
#   sh pipelines/readme-table.sh out/demo/exponents.md docs/validation.md
#   sh pipelines/readme-table.sh out/workstation/exponents.md docs/validation.md exponents-workstation
set -e
table=$1
readme=$2
name=${3:-exponents}
grep -q "^<!-- $name:begin -->\$" "$readme" && grep -q "^<!-- $name:end -->\$" "$readme" || {
  echo "readme-table.sh: $readme has no '<!-- $name:begin -->' ... '<!-- $name:end -->' lines" >&2; exit 2; }
# A table whose header names a build with uncommitted changes ("-dirty") is
# refused: a documented number must come from a commit anyone can check out.
dirty=$(grep -o '[0-9a-f]\{7,\}-dirty' "$table" | head -n 1 || true)
[ -z "$dirty" ] || {
  echo "readme-table.sh: $table was made by a build with uncommitted changes ($dirty); allowed: tables made by committed builds only" >&2; exit 2; }
tmp=$(mktemp "$readme.XXXXXX")
awk -v table="$table" -v begin="<!-- $name:begin -->" -v end="<!-- $name:end -->" '
  $0 == begin { print; while ((getline line < table) > 0) print line; skip = 1; next }
  $0 == end { skip = 0 }
  !skip { print }' "$readme" > "$tmp"
mv "$tmp" "$readme"
