#!/bin/sh
# Runs clang-tidy (the checks of .clang-tidy, every finding an error) on
# every source file the build compiles, in parallel; exits non-zero on any
# finding, naming it.
# usage: tests/lint/clang_tidy.sh BUILD_DIR [JOBS]
set -eu
build=${1:?usage: clang_tidy.sh BUILD_DIR [JOBS]}
jobs=${2:-$(nproc)}
tidy=$(command -v clang-tidy-15 || true)
if [ -z "$tidy" ]; then
  echo "clang_tidy.sh: clang-tidy-15 is not installed (make test-deps installs it)" >&2
  exit 2
fi
[ -f "$build/compile_commands.json" ] || { echo "clang_tidy.sh: no $build/compile_commands.json (configure first)" >&2; exit 2; }
"$tidy" --verify-config >/dev/null
# Only the project's own sources: the build's generated files hold nothing to lint.
run-clang-tidy-15 -clang-tidy-binary "$tidy" -p "$build" -quiet -j "$jobs" \
  '/(common|simulate|analyze|data-schema|tests)/[^/]+(/[^/]+)*\.cc$' 2>/dev/null | grep -E "(warning|error):" && exit 1
echo "clang-tidy: no findings"
