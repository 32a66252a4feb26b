#!/bin/sh
# The dimension of space lives in one place, common/geometry.h: outside it,
# no source switches on d to pick a value (a ternary on the dimension, a
# d-th root or power written out, cbrt beside sqrt), and no function takes
# a dimension that defaults to 3. Each finding is printed as file:line: text
# and fails the test. Run by ctest (Lint.DimensionSwitches).
# usage: tests/lint/dimension_switches.sh [SOURCE_DIR]
set -eu
src=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
cd "$src"
# Library and tool sources: the tests may pick a scene per dimension.
code=$(find common simulate analyze data-schema -name '*.h' -o -name '*.cc' | grep -v '^common/geometry\.h$' | sort)
# The slow reference engine sizes merged aggregates apart from Geometry on purpose.
roots=$(printf '%s\n' $code | grep -v '^simulate/engine/reference_engine\.cc$')
found=0
report() { # $1 what, then grep output lines
  what=$1
  shift
  if [ -n "$*" ]; then
    printf '%s\n' "$*" | while IFS= read -r line; do printf '%s   <- %s\n' "$line" "$what"; done
    found=1
  fi
}
var='(dimension|dimension_|dim|dim_|D|d)'
report "a switch on the dimension (ask common/geometry.h)" \
  "$(grep -nE "\\b$var\\s*(==|!=|>=|<=|<|>)\\s*[123]\\s*\\?" $code || true)"
report "a d-th power or root written out (Geometry::power/root)" \
  "$(grep -nE "pow\\([^;]*,\\s*(1\\.0\\s*/\\s*)?(double\\()?$var\\)?\\)" $roots || true)"
report "cbrt beside sqrt: a d-th root by cases (Geometry::root)" \
  "$(grep -nE 'cbrt\(.*sqrt\(|sqrt\(.*cbrt\(' $code || true)"
report "a dimension defaulting to 3 (pass a Geometry)" \
  "$(grep -nE "\\bint\\s+$var\\s*=\\s*3\\s*[,)]" $code $(find tests -name '*.h' -o -name '*.cc') || true)"
if [ "$found" -ne 0 ]; then
  echo "dimension_switches.sh: the dimension is switched on outside common/geometry.h (above)" >&2
  exit 1
fi
echo "dimension switches: none outside common/geometry.h"
