#!/bin/sh
# Collisions per CPU second of whole runs (set-up included) of the gas in
# each dimension, in turns, ROUNDS times: the rods' and disks' rates over the
# spheres' are the factors simulate/run/run_costs.cc gives small runs.
# usage: tests/bench/dimension_rates.sh BIN_DIR [ROUNDS]   (from the repository root)
set -eu
bin=${1:?usage: dimension_rates.sh BIN_DIR [ROUNDS]}
rounds=${2:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for r in $(seq 1 "$rounds"); do
  for gas in rods disks spheres; do
    /usr/bin/time -f '%U %S' -o "$dir/time" "$bin/coolgas-simulate" "tests/bench/rate_scenes/$gas.toml" \
      -o "$dir/$gas.h5" --force --quiet
    /usr/bin/python3 - "$dir/$gas.h5" "$dir/time" "$r" "$gas" <<'PY'
import sys, h5py
collisions = int(h5py.File(sys.argv[1], "r")["observables/collisions/value"][-1])
user, system = map(float, open(sys.argv[2]).read().split())
print(f"round {sys.argv[3]}\t{sys.argv[4]}\tcollisions={collisions}\tcpu_s={user + system:.2f}\tper_cpu_s={collisions / (user + system):.0f}")
PY
  done
done
