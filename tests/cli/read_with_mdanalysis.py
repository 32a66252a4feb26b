#!/usr/bin/env python3
"""Checks that MDAnalysis 2.4 and h5py read a coolgas H5MD file as documented.

usage: read_with_mdanalysis.py FILE N L FRAME
Exits non-zero (with a message) if the per-particle series are not stored
compressed (shuffle + deflate, data-schema/h5md-profile.md, "Storage"), so
that both readers are shown to read compressed files, or if the number of
atoms, the box, the positions, velocities or times seen by MDAnalysis differ
from the raw datasets.
"""
import sys
import warnings

warnings.filterwarnings("ignore")
import h5py
import MDAnalysis as mda
import numpy as np

path, n, box, frame = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
errors = []
with h5py.File(path, "r") as f:
    for name in ("position", "velocity", "image"):
        ds = f[f"particles/all/{name}/value"]
        if ds.compression != "gzip" or not ds.shuffle:
            errors.append(f"{name}: stored with compression {ds.compression}, shuffle {ds.shuffle}")
    pos = f["particles/all/position/value"][frame]
    vel = f["particles/all/velocity/value"][frame]
    times = f["particles/all/position/time"][:]

u = mda.Universe.empty(n).load_new(path, format="H5MD", convert_units=False)
ts = u.trajectory[frame]
if u.atoms.n_atoms != n:
    errors.append(f"atoms: {u.atoms.n_atoms} != {n}")
if len(u.trajectory) != len(times):
    errors.append(f"frames: {len(u.trajectory)} != {len(times)}")
if ts.dimensions is None or not np.allclose(ts.dimensions, [box, box, box, 90, 90, 90]):
    errors.append(f"box: {ts.dimensions}")
if not np.allclose(ts.positions, pos, rtol=1e-6, atol=1e-5):  # MDAnalysis stores float32
    errors.append("positions differ")
if not np.allclose(ts.velocities, vel, rtol=1e-6, atol=1e-6):
    errors.append("velocities differ")
if not np.isclose(ts.time, times[frame]):
    errors.append(f"time: {ts.time} != {times[frame]}")
if errors:
    sys.exit("MDAnalysis read mismatch: " + "; ".join(errors))
print("ok")
