"""A trajectory as a run object: parameters, observables and lazy frames.

coolgas trajectories are read through the tools' own reader
(common/trajectory/frame_reader.h: complete dumps only, so a file that
coolgas-simulate is still writing reads as far as it has got); an H5MD 1.1
file of another program through common/trajectory/h5md_frame.h. Every
property reads the file again when asked, so a live run grows under it."""
import os
import tomllib
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from . import _core

# The reduced units of every coolgas file (data-schema/h5md-profile.md, "Units").
UNITS = {
    "length": "particle diameter sigma (aggregation: the initial diameter)",
    "mass": "particle mass m",
    "time": "initial mean collision time 1/omega0 (Enskog, Carnahan-Starling)",
    "velocity": "sigma omega0",
    "energy": "m sigma^2 omega0^2 (per particle)",
}


@dataclass
class Frame:
    """One dump. Arrays are in id order; for ballistic aggregation only the
    aggregates present (ids, masses, diameters), for the gas every particle
    (ids 0..N-1, masses and diameters None: unit spheres; a mixture's from
    each particle's species, in `species`). A 2D file (disks,
    dimension 2) has two columns per vector: (n, 2) arrays, which the
    analysis kernels (coolgas.clusters, velocity, structure, shape) read as
    2D; a 1D file (rods on a ring, dimension 1) one: (n, 1) arrays, read as 1D."""
    index: int
    t: float
    L: float
    positions: np.ndarray          # (n, d), wrapped into [0, L)
    velocities: np.ndarray         # (n, d); None when the file has none
    ids: np.ndarray                # (n,)
    step: int = None               # collisions so far (coolgas files)
    images: np.ndarray = None      # (n, d) periodic image counts (coolgas files)
    masses: np.ndarray = None
    diameters: np.ndarray = None
    slots: int = None              # N of the file: particles, or aggregation slots
    extra: dict = field(default_factory=dict)
    angular_velocities: np.ndarray = None  # (n, 3) a rough run's spins (disks: about z, x and y 0); else None
    species: np.ndarray = None     # (n,) a mixture's species (0 for the first [[species]]); else None

    @property
    def dimension(self):
        """d: 3, 2 for disks or 1 for rods (the columns of positions)."""
        return self.positions.shape[1]

    @property
    def box(self):
        """The box edges (L, L, L), (L, L) in 2D, (L,) in 1D."""
        return np.full(self.dimension, self.L)


class Frames:
    """The frames of a file, read one at a time when indexed: frames[i]
    (position, negative from the end), frames.at(t) (nearest time, the
    earlier on a tie), len(frames), frames.times, iteration."""

    def __init__(self, path):
        self._path = path
        self._coolgas = _core.is_coolgas_file(path)
        # No file handle is kept: HDF5 shares one open file between handles,
        # so a handle kept here would hand later opens its stale view of a
        # file that coolgas-simulate is still writing. Each frame opens anew.
        if self._coolgas:
            traj = _core.Trajectory(path)
            self.times = np.asarray(traj.times)
            self._count, self._slots = len(self.times), traj.slots
        else:
            last = _core.h5md_frame(path, 0)
            self._count = last["frames"]
            self.times = np.asarray(last["times"]) if len(last["times"]) else None

    def __len__(self):
        return self._count

    def _index(self, i):
        if not isinstance(i, (int, np.integer)):
            raise TypeError(f"frames are indexed by position (an int), got {type(i).__name__}; use frames.at(t) for a time")
        n = len(self)
        j = int(i) + n if i < 0 else int(i)
        if not 0 <= j < n:
            raise IndexError(f"frame {i} out of range: the file holds {n} frames")
        return j

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self[j] for j in range(*i.indices(len(self)))]
        j = self._index(i)
        if self._coolgas:
            d = _core.Trajectory(self._path).read(j)
            n = len(d["positions"])
            return Frame(index=j, t=d["t"], L=d["L"], positions=d["positions"], velocities=d["velocities"],
                         ids=d.get("ids", np.arange(n, dtype=np.int32)), step=d["step"], images=d["images"],
                         masses=d.get("masses"), diameters=d.get("diameters"), slots=self._slots,
                         angular_velocities=d.get("angular_velocities"), species=d.get("species"))
        d = _core.h5md_frame(self._path, j)
        n = len(d["positions"])
        ids = d.get("ids")
        return Frame(index=j, t=d["t"], L=d["L"], positions=d["positions"], velocities=d.get("velocities"),
                     ids=np.arange(n, dtype=np.int32) if ids is None else ids.astype(np.int64),
                     masses=d.get("masses"), diameters=d.get("diameters"), slots=n,
                     extra={"group": d["group"], "length_unit": d["length_unit"]})

    def nearest(self, t):
        """Position of the frame nearest time t (the earlier one on a tie)."""
        if self.times is None:
            raise ValueError(f"{self._path}: its positions have no times; index the frames by position")
        t = float(t)
        if not np.isfinite(t):
            raise _core.InputError(f"{self._path}: time t = {t} is not a finite number (give a finite time)")
        return int(np.argmin(np.abs(self.times - t)))  # the first minimum: Trajectory::nearest_dump's rule

    def at(self, t):
        """The frame nearest time t."""
        return self[self.nearest(t)]

    def __iter__(self):
        for i in range(len(self)):
            yield self[i]


class Run:
    """A trajectory file: coolgas's own, or an H5MD 1.1 file of another program."""

    def __init__(self, path):
        self.path = os.fspath(path)
        if not os.path.exists(self.path):
            raise FileNotFoundError(2, "no such trajectory", self.path)
        self.is_coolgas = _core.is_coolgas_file(self.path)

    @property
    def parameters(self):
        """The /parameters of the run (scene text, seed, program_version, N,
        L, phi, T0, model and the model's own), its scene parsed from TOML
        (scene_dict) and the units. Another program's file: what it tells
        (N, L of the last frame, its length unit)."""
        if self.is_coolgas:
            p = dict(_core.parameters(self.path))
            p["scene_dict"] = tomllib.loads(p["scene"])
            p["units"] = dict(UNITS)
            return p
        f = _core.h5md_frame(self.path, 0)
        return {"N": len(f["positions"]), "L": f["L"], "group": f["group"],
                "units": {"length": f["length_unit"] or "as written (no unit attribute)"}}

    @property
    def L(self):
        return self.parameters["L"]

    @property
    def dimension(self):
        """The box's dimension d: 3, 2 for disks (system.dimension = 2), 1 for rods."""
        if self.is_coolgas:
            return _core.Trajectory(self.path).dimension
        return self.frames[0].dimension

    @property
    def observables(self):
        """Every /observables element up to the last complete dump, as a
        DataFrame indexed by t; a vector element (total_momentum) is d
        columns name_x(, name_y, name_z). Elements recorded at other times
        meet on the union of the times (NaN where one has no row)."""
        columns = []
        for name in _core.observable_names(self.path):
            t, v = _core.observable(self.path, name)
            if v.ndim == 1:
                columns.append(pd.Series(v, index=pd.Index(t, name="t"), name=name))
            else:
                for c in range(v.shape[1]):
                    # a vector's axes; a mixture's species by index (species_kinetic_energy_0, _1, ...)
                    suffix = "xyz"[c] if v.shape[1] in (1, 2, 3) and name != "species_kinetic_energy" else str(c)
                    columns.append(pd.Series(v[:, c], index=pd.Index(t, name="t"), name=f"{name}_{suffix}"))
        if not columns:
            return pd.DataFrame(index=pd.Index([], name="t"))
        if all(len(c.index) == len(columns[0].index) and (c.index == columns[0].index).all() for c in columns):
            return pd.concat(columns, axis=1)
        return pd.concat(columns, axis=1, join="outer").sort_index()

    @property
    def temperatures(self):
        """The temperatures per axis by time, from the observables: T_tr =
        2 E/d and, for a run of rough particles, T_rot = 2 E_rot/d_r with
        d_r = d(d - 1)/2 spinning axes (3 for spheres, 1 for disks); for a
        mixture each species' T_species_k = 2 E_k/d (coolgas-energy's columns)."""
        o = self.observables
        d = self.dimension
        T = pd.DataFrame({"T_tr": 2.0 * o["kinetic_energy"] / d}, index=o.index)
        if "rotational_energy" in o:
            T["T_rot"] = 2.0 * o["rotational_energy"] / (d * (d - 1) // 2)
        k = 0
        while f"species_kinetic_energy_{k}" in o:
            T[f"T_species_{k}"] = 2.0 * o[f"species_kinetic_energy_{k}"] / d
            k += 1
        return T

    @property
    def frames(self):
        """The frames complete now (a live run: read again for later ones)."""
        return Frames(self.path)

    def __repr__(self):
        kind = "coolgas" if self.is_coolgas else "H5MD"
        return f"<coolgas.Run {self.path!r} ({kind}, {len(self.frames)} frames)>"


def open(path):  # noqa: A001 - the package's entry point, coolgas.open
    """The run of a trajectory file (coolgas or any H5MD 1.1 file)."""
    return Run(path)
