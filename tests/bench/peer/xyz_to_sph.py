#!/usr/bin/env python3
"""One frame of `coolgas-convert` (extended XYZ) on stdin -> the peer's input
file on stdout (tests/bench/peer/README.md): the particle count, the box
edges, then one line per sphere: type letter, x, y, z, radius. Positions are
written in their shortest round-trip form, so the peer starts from exactly our
positions; the peer draws its own velocities."""
import re
import sys

n = int(sys.stdin.readline())
header = sys.stdin.readline()
lattice = re.search(r'Lattice="([^"]*)"', header)
if lattice is None:
    sys.exit("error: the second line has no Lattice=\"...\" (not a coolgas-convert XYZ frame)")
edge = float(lattice.group(1).split()[0])
out = [f"{n}", f"{edge!r} {edge!r} {edge!r}"]
for _ in range(n):
    f = sys.stdin.readline().split()
    out.append(f"a {f[1]} {f[2]} {f[3]} 0.5")
print("\n".join(out))
