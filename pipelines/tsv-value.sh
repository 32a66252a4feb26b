#!/bin/sh
# tsv-value.sh TABLE COLUMN [KEY]
# Prints COLUMN of the last data row of a coolgas TSV table (the column line is
# its first line, or in a format 1 table the first comment line without ':',
# data-schema/tsv-tables.md); with KEY = "#", prints the value of the
# provenance line "# COLUMN: value" instead. Used to gather exponents.
table=$1
column=$2
if [ "${3:-}" = "#" ]; then
  sed -n "s/^# $column: //p" "$table" | head -n 1
  exit 0
fi
awk -F '\t' -v want="$column" '
  function names(line) { n = split(line, name, "\t"); for (i = 1; i <= n; i++) if (name[i] == want) col = i; header = 1 }
  /^#/ { line = substr($0, 3); if (index(line, ":") == 0 && !header) names(line); next }
  NF > 0 && !header { names($0); next }
  NF > 0 { last = $col }
  END { if (!col) { print "tsv-value.sh: no column " want " in " FILENAME > "/dev/stderr"; exit 2 } print last }
' "$table"
