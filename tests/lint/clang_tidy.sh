#!/bin/sh
# Runs clang-tidy (the checks of .clang-tidy, every finding an error) on
# every source file of the tree, in parallel; exits non-zero on any finding,
# naming it. The build's own compile_commands.json cannot serve: a unity
# build lists its batch files, not the sources in them, so the commands
# come from a configure-only folder LINT_DIR (unity off; nothing is built
# there, which is all clang-tidy needs).
# usage: tests/lint/clang_tidy.sh LINT_DIR [JOBS]
set -eu
dir=${1:?usage: clang_tidy.sh LINT_DIR [JOBS]}
jobs=${2:-$(nproc)}
tidy=$(command -v clang-tidy-15 || true)
if [ -z "$tidy" ]; then
  echo "clang_tidy.sh: clang-tidy-15 is not installed (make lint installs it)" >&2
  exit 2
fi
src=$(cd "$(dirname "$0")/../.." && pwd)
# Reconfiguring a build folder would turn its unity builds off behind its owner's back.
if grep -q '^COOLGAS_UNITY:BOOL=ON' "$dir/CMakeCache.txt" 2>/dev/null; then
  echo "clang_tidy.sh: $dir is a unity build folder; give a folder of its own (make lint uses BUILD-lint)" >&2
  exit 2
fi
cmake -S "$src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCOOLGAS_NATIVE=OFF -DCOOLGAS_UNITY=OFF >/dev/null
"$tidy" --verify-config >/dev/null
# Only the project's own sources: generated files (common/version.cc, made
# by a build, which this folder never has) hold nothing to lint.
run-clang-tidy-15 -clang-tidy-binary "$tidy" -p "$dir" -quiet -j "$jobs" \
  "^$src/(common|simulate|analyze|data-schema|tests)/[^/]+(/[^/]+)*\.cc\$" 2>/dev/null | grep -E "(warning|error):" && exit 1
echo "clang-tidy: no findings"
