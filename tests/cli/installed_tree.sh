#!/bin/sh
# `make install`'s tree, used as a user would: installs the build into a
# fresh prefix, then checks that every program has a manual page that
# `man -l` shows, that an installed program runs, that the documentation is
# in share/doc/coolgas with every link between its pages and every document a
# --help names resolving there, that the install says where the Python
# package went, that bash-completion's own loader finds each program's
# completion and that it offers that program's options and nothing else, and
# that the installed pipelines run on the installed programs (SCALE=tiny,
# seconds). Prints what failed and exits 1 on the first failure.
#
# usage: tests/cli/installed_tree.sh BUILD_DIR SCRATCH_DIR
set -u
build=${1:?usage: installed_tree.sh BUILD_DIR SCRATCH_DIR}
scratch=${2:?usage: installed_tree.sh BUILD_DIR SCRATCH_DIR}
fail() { echo "installed tree: $*"; exit 1; }
rm -rf "$scratch"
mkdir -p "$scratch"
prefix=$scratch/prefix
cmake --install "$build" --prefix "$prefix" >"$scratch/install.log" 2>&1 || fail "cmake --install failed: $(tail -1 "$scratch/install.log")"

programs=0
for program in "$prefix"/bin/coolgas-*; do
  name=$(basename "$program")
  [ -s "$prefix/share/man/man1/$name.1" ] || fail "no manual page for $name"
  programs=$((programs + 1))
done
[ "$programs" -ge 12 ] || fail "only $programs programs installed"
MANWIDTH=100 man -l "$prefix/share/man/man1/coolgas-simulate.1" 2>/dev/null >"$scratch/man.txt"
grep -q -- '--resume' "$scratch/man.txt" || fail "man -l coolgas-simulate.1 does not show --resume"
grep -q 'event-driven simulation' "$scratch/man.txt" || fail "man -l coolgas-simulate.1 has no NAME line"

"$prefix/bin/coolgas-simulate" --version | grep -q '^coolgas-simulate [0-9]' || fail "the installed coolgas-simulate gives no version"
# The documentation, its links between pages, and the documents --help names.
doc=$prefix/share/doc/coolgas
for f in README.md NEWS.md LICENSE CITATION.cff docs/README.md docs/tools.md data-schema/h5md-profile.md \
         data-schema/tsv-tables.md pipelines/README.md; do
  [ -s "$doc/$f" ] || fail "share/doc/coolgas/$f missing"
done
links=0
for page in $(find "$doc" -name '*.md'); do
  for target in $(grep -o '](\([^)]*\))' "$page" | sed 's/^](//; s/)$//; s/#.*//'); do
    case $target in http://* | https://* | mailto:*) continue ;; esac
    [ -e "$(dirname "$page")/$target" ] || fail "${page#"$doc"/} links to $target, which is not installed"
    links=$((links + 1))
  done
done
[ "$links" -ge 50 ] || fail "only $links links between the installed pages"
named=0
for program in "$prefix"/bin/coolgas-*; do
  for path in $("$program" --help | grep -oE '(share/doc/coolgas/)?(docs|data-schema)/[A-Za-z0-9_.-]+\.md'); do
    [ -f "$doc/${path#share/doc/coolgas/}" ] || fail "$(basename "$program") --help names $path, not in share/doc/coolgas"
    named=$((named + 1))
  done
done
[ "$named" -ge 2 ] || fail "no --help names a document"
"$prefix/bin/coolgas-simulate" --help | grep -q 'share/doc/coolgas/data-schema/h5md-profile.md' ||
  fail "coolgas-simulate --help does not name the installed profile"

# The install's last line: where the Python package went.
if grep -q 'dist-packages/coolgas' "$scratch/install.log"; then
  tail -1 "$scratch/install.log" | grep -q "^-- coolgas: the Python package is in $prefix/lib/python3[.0-9]*/dist-packages/coolgas; " ||
    fail "the install does not end by saying where the Python package went: $(tail -1 "$scratch/install.log")"
fi

# Completion as bash-completion loads it (its loader searches
# XDG_DATA_DIRS/bash-completion/completions for the command's name): each
# program's, offering every option its --help lists and nothing else.
loader=/usr/share/bash-completion/bash_completion
[ -f "$loader" ] || fail "bash-completion is not installed ($loader; make test-deps installs it)"
for program in "$prefix"/bin/coolgas-*; do
  name=$(basename "$program")
  offered=$(PATH="$prefix/bin:$PATH" XDG_DATA_DIRS="$prefix/share" bash -c '. "$1"; _completion_loader "$2"
    complete -p "$2" | grep -q -- "-F _coolgas_complete" || { echo "not loaded"; exit; }
    COMP_WORDS=("$2" -); COMP_CWORD=1; _coolgas_complete; printf "%s\n" "${COMPREPLY[@]}"' _ "$loader" "$name")
  [ "$offered" != "not loaded" ] || fail "bash-completion's loader does not load the completion of $name"
  "$program" --help >"$scratch/help.txt"
  count=0
  for word in $offered; do
    # an option name: first on an indented line of --help, or after another name and a comma
    grep -qE -- "^ +(-[-A-Za-z0-9]*,)*$word( |,|\$)" "$scratch/help.txt" || fail "completion of $name offers $word, not an option"
    count=$((count + 1))
  done
  for option in --help --version; do
    echo "$offered" | grep -qx -- "$option" || fail "completion of $name does not offer $option"
  done
  [ "$count" -ge 3 ] || fail "completion of $name offers only: $offered"
done
offered=$(bash -c '. "$1/share/bash-completion/completions/coolgas-fit"
  COMP_WORDS=(coolgas-fit -); COMP_CWORD=1; PATH="$1/bin:$PATH"; _coolgas_complete; printf "%s " "${COMPREPLY[@]}"' _ "$prefix")
[ "$offered" = "-h --help --t-window --window --t-column --e-column --err-column --no-weights --smooth --curve --version --power --local-slope --haff " ] ||
  fail "completion of coolgas-fit offers: $offered"
offered=$(bash -c '. "$1/share/bash-completion/completions/coolgas-simulate"
  COMP_WORDS=("$1/bin/coolgas-simulate" --resu); COMP_CWORD=1; _coolgas_complete; printf "%s\n" "${COMPREPLY[@]}"' _ "$prefix")
[ "$offered" = "--resume" ] || fail "completion of 'coolgas-simulate --resu' offers '$offered', not --resume"

make -s -C "$prefix/share/coolgas/pipelines/demo" SCALE=tiny OUT="$scratch/out" >"$scratch/make.log" 2>&1 ||
  fail "the installed demo pipeline failed: $(tail -1 "$scratch/make.log")"
[ -n "$(find "$scratch/out" -name '*.png' | head -1)" ] || fail "the installed demo pipeline drew no figure"
echo "installed tree: $programs programs with manual pages and completion, $links links and $named --help references resolved, a working pipeline"
