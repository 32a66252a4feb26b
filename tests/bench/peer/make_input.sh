#!/bin/sh
# The peer's input file from coolgas' own t = 0 state: the gas of
# build/bench/engine_bench (phi = 0.208, seed 1: random addition, then 5
# elastic collision times of equilibration) written by coolgas-simulate,
# exported by coolgas-convert and turned into the peer's format.
# Run from the repository's top folder after the build:
#   sh tests/bench/peer/make_input.sh N OUT.sph
set -e
n=$1
out=$2
[ -n "$n" ] && [ -n "$out" ] || { echo "usage: sh tests/bench/peer/make_input.sh N OUT.sph" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '[system]\nN = %s\nphi = 0.208\nseed = 1\n[collision]\nmodel = "elastic"\n[run]\nt_end = 0.01\n[output]\ndump_times = [0]\n' "$n" > "$tmp/start.toml"
build/bin/coolgas-simulate "$tmp/start.toml" -o "$tmp/start.h5" --quiet
build/bin/coolgas-convert --time 0 "$tmp/start.h5" | python3 "$here/xyz_to_sph.py" > "$out"
