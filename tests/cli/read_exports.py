#!/usr/bin/env python3
"""Checks coolgas-convert's output with real readers against h5py's view of the trajectory.

usage: read_exports.py xyz RUN.h5 FRAMES.xyz     ASE reads every frame: cell, pbc, time, positions
                                                 and velocities (exactly: the XYZ numbers round-trip),
                                                 radii = diameter/2 of the aggregates present; a 2D
                                                 run's frames: cell (L, L, 1), pbc (T, T, F), z = 0;
                                                 a 1D run's: cell (L, 1, 1), pbc (T, F, F), y = z = 0
       read_exports.py lammps RUN.h5 DUMP DUMP   MDAnalysis (LAMMPSDUMP, convert_units=False) reads
                                                 the dump of the last frame: box, ids, positions and
                                                 velocities (float32 in MDAnalysis)
       read_exports.py h5md RUN.h5 OUT.h5md      MDAnalysis writes the last frame as H5MD 1.1 (another
                                                 program's file for coolgas-simulate to start from)
       read_exports.py h5md_fixed RUN.h5 OUT     h5py writes the last frame as H5MD 1.1 the other way the
                                                 specification allows: time-independent datasets, box edges
                                                 a vector, group "gas", and one absent particle (id -1)
       read_exports.py h5md_bad KIND OUT         h5py writes a broken H5MD file: KIND = slab (edges 10 10 5),
                                                 open (boundary none), groups (two particle groups)
       read_exports.py mda_2d RUN.h5 N           MDAnalysis refuses a 2D run's H5MD file (box/dimension = 2)
                                                 with its ValueError "only supports 3-dimensional simulation boxes"
Exits non-zero with a message on the first mismatch; prints "ok".
"""
import sys
import warnings

warnings.filterwarnings("ignore")
import h5py
import numpy as np


def frames(path):
    """Per dump (time, L, positions, velocities, diameters or None) of the particles present."""
    with h5py.File(path, "r") as f:
        p = f["particles/all"]
        out = []
        for k, t in enumerate(p["position/time"][:]):
            live = p["id/value"][k] >= 0 if "id" in p else slice(None)
            d = p["diameter/value"][k][live] if "diameter" in p else None
            out.append((t, p["box/edges/value"][k][0, 0], p["position/value"][k][live], p["velocity/value"][k][live], d))
        return out


def fail(msg):
    sys.exit("mismatch: " + msg)


def in_3d(v):
    """Rows of d numbers (a 2D run: d = 2; 1D: d = 1) as 3-vectors, the rest 0: what 3D readers hold."""
    return np.hstack([v, np.zeros((len(v), 3 - v.shape[1]))])


def check_xyz(h5, xyz):
    import ase.io
    ref = frames(h5)
    images = ase.io.read(xyz, index=":")
    if len(images) != len(ref):
        fail(f"{len(images)} XYZ frames, {len(ref)} dumps")
    for a, (t, L, pos, vel, d) in zip(images, ref):
        dim = pos.shape[1]
        if not (np.array_equal(a.cell.array, np.diag([L] * dim + [1] * (3 - dim)))
                and list(a.pbc) == [True] * dim + [False] * (3 - dim)):
            fail(f"cell {a.cell.array} pbc {a.pbc} at t = {t}")
        if a.info.get("Time") != t:
            fail(f"Time {a.info.get('Time')} != {t}")
        if not np.array_equal(a.positions, in_3d(pos)) or not np.array_equal(a.arrays["velo"], in_3d(vel)):
            fail(f"positions or velocities differ at t = {t}")
        if d is not None and not np.array_equal(2 * a.arrays["radius"], d):
            fail(f"radii differ at t = {t}")


def check_lammps(h5, dump):
    import MDAnalysis as mda
    t, L, pos, vel, d = frames(h5)[-1]
    u = mda.Universe(dump, format="LAMMPSDUMP", convert_units=False)
    ts = u.trajectory[0]
    box = [L, L, L] if pos.shape[1] == 3 else [L, L, 1]  # 2D: z from -0.5 to 0.5
    # MDAnalysis moves the box's lower corner to the origin: a 2D dump's z = 0 reads as 0.5.
    pos = in_3d(pos) + [0, 0, 0.5 * (pos.shape[1] == 2)]
    if u.atoms.n_atoms != len(pos) or not np.allclose(ts.dimensions, box + [90, 90, 90]):
        fail(f"atoms {u.atoms.n_atoms} box {ts.dimensions}")
    if not np.array_equal(u.atoms.ids, np.arange(1, len(pos) + 1)) and d is None:
        fail("ids are not 1..N")
    if not np.allclose(ts.positions, pos, rtol=1e-6, atol=1e-5) or \
            not np.allclose(ts.velocities, in_3d(vel), rtol=1e-6, atol=1e-6):
        fail("positions or velocities differ")


def write_h5md(h5, out):
    import MDAnalysis as mda
    t, L, pos, vel, d = frames(h5)[-1]
    u = mda.Universe.empty(len(pos), trajectory=True, velocities=True)
    u.atoms.positions, u.atoms.velocities, u.dimensions = pos, vel, [L, L, L, 90, 90, 90]
    with mda.Writer(out, n_atoms=len(pos), velocities=True, convert_units=False) as w:
        w.write(u)


def h5md_group(f, name, pos, edges, boundary="periodic"):
    f.require_group("h5md").attrs["version"] = np.array([1, 1])
    g = f.create_group("particles/" + name)
    g["position"] = pos
    box = g.create_group("box")
    box.attrs["dimension"] = 3
    box.attrs["boundary"] = np.array([boundary.encode()] * 3)  # fixed-length strings, as numpy writes them
    box["edges"] = edges
    return g


def write_h5md_fixed(h5, out):
    t, L, pos, vel, d = frames(h5)[-1]
    with h5py.File(out, "w") as f:
        g = h5md_group(f, "gas", np.vstack([[np.nan, np.nan, np.nan], pos]), np.array([L, L, L]))
        g["velocity"] = np.vstack([[0, 0, 0], vel])
        g["id"] = np.concatenate([[-1], np.arange(len(pos))])


def write_h5md_bad(kind, out):
    pos = np.array([[1.0, 1, 1], [3, 3, 3]])
    with h5py.File(out, "w") as f:
        if kind == "slab":
            h5md_group(f, "all", pos, np.array([10.0, 10, 5]))
        elif kind == "open":
            h5md_group(f, "all", pos, np.array([10.0, 10, 10]), "none")
        else:
            h5md_group(f, "a", pos, np.array([10.0, 10, 10]))
            h5md_group(f, "b", pos, np.array([10.0, 10, 10]))


def check_mda_refuses_2d(h5, n):
    import MDAnalysis as mda
    try:
        mda.Universe.empty(int(n)).load_new(h5, format="H5MD", convert_units=False)
    except ValueError as e:
        if "3-dimensional" not in str(e):
            fail(f"MDAnalysis refused the 2D file otherwise: {e}")
        return
    fail("MDAnalysis read a 2D file")


mode, h5, other = sys.argv[1], sys.argv[2], sys.argv[3]
{"xyz": check_xyz, "lammps": check_lammps, "h5md": write_h5md, "h5md_fixed": write_h5md_fixed,
 "h5md_bad": write_h5md_bad, "mda_2d": check_mda_refuses_2d}[mode](h5, other)
print("ok")
