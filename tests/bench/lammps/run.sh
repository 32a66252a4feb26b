#!/bin/sh
# The same freely cooling gas by coolgas and by LAMMPS soft-sphere DEM
# (pair_style granular, GRANULAR package): N = 10000, phi = 0.208, r = 0.9,
# to t = 10 (in coolgas' time unit, the initial mean collision time).
# Run from the repository's top folder after the build, with `lmp` on PATH
# (Debian: apt-get install lammps; the benchmark only, not the project):
#   sh tests/bench/lammps/run.sh [t_end] [scratch folder]
# Prints E(1) and E(t_end) of both, coolgas' CPU time for the dynamics (the
# run to t_end less the same run to t = 0.01: set-up and writing cancel) and
# LAMMPS' loop time with its CPU use.
set -e
t_end=${1:-10}
dir=${2:-$(mktemp -d)}
mkdir -p "$dir"
bin=$(pwd)/build/bin
here=$(cd "$(dirname "$0")" && pwd)
cd "$dir"
cat > gas.toml <<TOML
[system]
N = 10000
phi = 0.208
seed = 1
[collision]
model = "inelastic"
r0 = 0.9
delta = 0
[run]
t_end = $t_end
[output]
dump_times = [0]
TOML
cpu() { /usr/bin/time -f "%U %S" -o cpu.txt "$@" && awk '{print $1 + $2}' cpu.txt; }
short=$(cpu "$bin"/coolgas-simulate gas.toml --set run.t_end=0.01 -o short.h5 --force --quiet)
long=$(cpu "$bin"/coolgas-simulate gas.toml -o gas.h5 --force --quiet)
"$bin"/coolgas-convert --format lammps --time 0 gas.h5 > start.dump
# restitution 0.9 -> damping ratio z -> eta_n0 = 2 z sqrt(k / m_eff), m_eff = 1/2
eta=$(python3 -c "import math; e=0.9; z=-math.log(e)/math.hypot(math.pi, math.log(e)); print(repr(2*z*math.sqrt(1e6/0.5)))")
steps=$(python3 -c "print(round($t_end / 1e-4))")
/usr/bin/time -f "%U %S" -o lmp_cpu.txt lmp -in "$here"/in.granular -var dump start.dump -var eta "$eta" -var steps "$steps" -var every 10000 -log lammps.log > lammps.out
"$bin"/coolgas-energy gas.h5 > E.tsv
python3 - "$t_end" "$short" "$long" <<'PY'
import re, sys
t_end, short, long = (float(a) for a in sys.argv[1:4])
ours = {}
for line in open("E.tsv"):
    f = line.split("\t")
    if f[0][:1].isdigit():
        ours[round(float(f[0]), 6)] = float(f[1])
log = open("lammps.log").read()
rows = re.findall(r"^\s*(\d+)\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)\s*$", log, re.M)
lmp = {round(float(r[1]), 6): float(r[2]) for r in rows}
loop = re.search(r"Loop time of ([0-9.]+)", log).group(1)
cpu_use = re.search(r"([0-9.]+)% CPU use", log).group(1)
lmp_cpu = sum(float(x) for x in open("lmp_cpu.txt").read().split())
for T in sorted({1.0, t_end}):
    nan = float("nan")
    print(f"E({T:g}): coolgas {ours.get(round(T, 6), nan):.6g}  LAMMPS {lmp.get(round(T, 6), nan):.6g}")
print(f"LAMMPS loop time: {loop} s ({cpu_use} % CPU use; the whole process {lmp_cpu:.2f} s of CPU)")
print(f"coolgas dynamics to t = {t_end:g}: {long - short:.2f} s of CPU (whole run {long:.2f} s, run to t = 0.01 {short:.2f} s)")
PY
