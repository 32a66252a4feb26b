"""The analysis kernels of the coolgas tools on numpy arrays: each calls the
C++ function the tool calls for one dump and returns the tool's columns."""
import numpy as np
import pandas as pd

from . import _core
from ._core import InputError
from ._run import Frame
from ._tables import frame_of


def _frame_args(frame_or_positions, L, t):
    """(positions, L, t, frame) from a Frame or from arrays."""
    if isinstance(frame_or_positions, Frame):
        f = frame_or_positions
        return f.positions, f.L if L is None else L, f.t if t is None else t, f
    if L is None:
        raise TypeError("L (the box side) is required with a positions array")
    return frame_or_positions, L, 0.0 if t is None else t, None


def _mixture_rows(f, positions, diameters, species):
    """(positions, diameters, rows) of the particles to label: a mixture
    Frame's diameters unless given; with species=K (coolgas-clusters
    --species K) the rows of species K alone (rows: their indices in the
    frame; None for every particle)."""
    if f is not None and f.species is not None and diameters is None:
        diameters = f.diameters
    if species is None:
        return positions, diameters, None
    if f is None or f.species is None:
        raise InputError("species: a mixture's Frame (a run with [[species]]) is needed; "
                         "these particles are all alike")
    rows = np.flatnonzero(f.species == species)
    if len(rows) == 0:
        raise InputError(f"species = {species}: the frame has species 0 to {int(f.species.max())}")
    return positions[rows], diameters[rows], rows


def label_clusters(positions, L=None, definition="cells", species=None, diameters=None):
    """The clusters of coolgas-clusters --definition: (labels, sizes).

    definition "cells", the paper's clusters (floor(L)^3 cells of side
    L/floor(L); occupied cells sharing a face, periodic, form a cluster), or
    "contact[:CUTOFF]" (particles closer than CUTOFF sigma, default 1.1,
    periodic minimum image, are bonded; bonded particles form a cluster).
    labels[i] is the cluster of particle i, numbered by size: 0 is the
    largest (ties by the smallest cell, or particle). sizes is a DataFrame
    with one row per cluster in that order: cluster, mass (particles), and
    first_cell (the smallest flat cell index i + n(j + n k), n = floor(L))
    or, by contact, first_particle (its smallest particle index). Accepts a
    Frame. An (N, 2) array is disks: floor(L)^2 unit squares sharing an
    edge; so in every kernel here, an (N, 2) positions or velocities array
    is 2D. An (N, 1) array is rods on a ring: floor(L) unit segments,
    neighbours left and right; so in every kernel, an (N, 1) array is 1D.

    A mixture (a Frame with species, or positions with diameters): by
    contact a pair is bonded closer than CUTOFF (d_i + d_j)/2. species=K
    (a Frame's species index, 0 for the first [[species]]): species K's
    clusters alone, as coolgas-clusters --species K; the other species'
    labels are -1."""
    positions, L, _, f = _frame_args(positions, L, None)
    positions, diameters, rows = _mixture_rows(f, positions, diameters, species)
    labels, mass, first, _ = _core.label_clusters(positions, float(L), definition, diameters)
    contact = definition.startswith("contact")
    if rows is not None:  # back to the frame's numbering: the other species -1, first particles the frame's
        every = np.full(len(f.species), -1, dtype=labels.dtype)
        every[rows] = labels
        labels, first = every, (rows[first] if contact else first)
    sizes = pd.DataFrame({"cluster": np.arange(len(mass)), "mass": mass,
                          ("first_particle" if contact else "first_cell"): first})
    return labels, sizes


def clusters(frame, L=None, t=None, table="distribution", bins_per_decade=10, masses=None, slots=None,
             definition="cells", species=None, diameters=None):
    """One dump's coolgas-clusters table: "distribution" (t m dm N x y),
    "scaled" (t x y) or "series" (t M0 M1 M2 M_avg M_max largest_fraction).

    frame: a Frame (ballistic aggregation: its aggregates are the clusters),
    or positions with L (and t). masses and slots: the aggregates' masses and
    the file's N, for arrays of a ballistic-aggregation frame. definition:
    "cells" (the paper's unit cells) or "contact[:CUTOFF]" (particles closer
    than CUTOFF sigma, default 1.1), as --definition. A mixture (a Frame
    with species, or positions with diameters): contacts bond closer than
    CUTOFF (d_i + d_j)/2; species=K: species K's clusters alone, as
    --species K. The block's comment line is df.attrs["comment"]."""
    positions, L, t, f = _frame_args(frame, L, t)
    if f is not None and f.masses is not None and f.species is None and masses is None:  # aggregates
        masses, slots = f.masses, f.slots
    positions, diameters, _ = _mixture_rows(f, positions, diameters, species)
    return frame_of(_core.cluster_table(positions, float(L), float(t), table, bins_per_decade, masses,
                                        None if slots is None else int(slots), definition, diameters))


def _frame_velocities(frame, spins, species):
    """The vectors coolgas.velocity pools: velocities or spins, all or one species'."""
    if spins:
        if frame.angular_velocities is None:
            raise InputError("spins=True: this frame has no angular velocities (its particles are smooth)")
        v = frame.angular_velocities
        if frame.velocities.shape[1] == 2:
            v = v[:, 2:3]  # disks spin about z only
    else:
        v = frame.velocities
    if species is None:
        return v
    if frame.species is None:
        raise InputError("species=%s: this frame has no species (its particles are all alike)" % species)
    chosen = np.asarray(frame.species) == species
    if not chosen.any():
        raise InputError("species=%s: no particle of this frame is of that species" % species)
    return v[chosen]


def velocity(frame, t=None, table="Phi", bins=120, ymax=6.0, tail_from=1.5, min_count=25, spins=False,
             species=None):
    """One dump's coolgas-velocity table: "Phi" (t y Phi Phi_err
    minus_ln_Phi; y = v_alpha / v_rms, the three components pooled), "tail"
    (t y minus_ln_Phi minus_ln_Phi_err fit) or "series" (t v_rms kappa
    kappa_err beta beta_err tail_points). frame: a Frame or velocities (N, 3).
    With a Frame, spins=True takes a rough run's angular velocities instead
    (disks: the one about z), and species=K a mixture's species K alone, as
    the tool's --spins and --species do.
    df.attrs: v_rms, kappa, kappa_err, beta, beta_err (None without a fit),
    tail_points and the block's comment."""
    if isinstance(frame, Frame):
        v, t = _frame_velocities(frame, spins, species), frame.t if t is None else t
    elif spins or species is not None:
        raise TypeError("spins and species need a Frame, which has them")
    else:
        v, t = frame, 0.0 if t is None else t
    d = _core.velocity_table(v, float(t), table, bins, float(ymax), float(tail_from), float(min_count))
    df = frame_of(d)
    for key in ("v_rms", "kappa", "kappa_err", "beta", "beta_err", "tail_points"):
        df.attrs[key] = d[key]
    return df


def _given(**options):
    """The options not None: the others keep the tool's defaults (held by _core)."""
    return {k: v for k, v in options.items() if v is not None}


def window(w):
    """A window "lo:hi" (the tools' syntax) from a string, or from (lo, hi) with None for an open end."""
    if w is None or isinstance(w, str):
        return w
    lo, hi = w
    return ("" if lo is None else repr(float(lo))) + ":" + ("" if hi is None else repr(float(hi)))


def structure(frame, L=None, t=None, table="spectrum", velocities=None, masses=None, grid=None, peak_fraction=None,
              direct_shells=None, r_max=None, bins_per_sigma=None, contact_bins=None):
    """One dump's coolgas-structure table: "spectrum" (t shell k S S_err
    modes x y; x = k L_t, y = S / L_t^3), "series" (t L_t k_mean k_cut
    k_peak S_peak L_C L_v), "correlation" (t r C C_v points), "rdf" (t r g
    g_err pairs: g(r), --rdf) or "rdf_series" (t g_contact g_contact_err
    kappa contact_pairs g_equilibrium: --rdf --series).

    frame: a Frame (ballistic aggregation: the aggregates weighted by their
    masses; refused by the rdf tables), or positions with L (and t,
    velocities, masses). velocities are needed by "series" and
    "correlation". grid: points per side (default: the even number below L);
    peak_fraction, direct_shells: the tool's options; r_max [sigma],
    bins_per_sigma, contact_bins: those of --rdf.
    df.attrs: the block's comment (L_t, k_cut, the exact sum's check; or
    g(sigma+)) and grid (or r_max for the rdf tables)."""
    positions, L, t, f = _frame_args(frame, L, t)
    rdf = table in ("rdf", "rdf_series")
    if f is not None:
        velocities = f.velocities if velocities is None else velocities
        masses = f.masses if masses is None else masses
    if table == "spectrum" or rdf:
        velocities = None  # S(k) and g(r) read positions only, as the tool does
    d = _core.structure_table(positions, float(L), float(t), table, velocities=velocities, masses=masses,
                              **_given(grid=grid, peak_fraction=peak_fraction, direct_shells=direct_shells,
                                       r_max=r_max, bins_per_sigma=bins_per_sigma, contact_bins=contact_bins))
    df = frame_of(d)
    for key in ("grid", "r_max"):
        if key in d:
            df.attrs[key] = d[key]
    return df


def fields(frame, L=None, t=None, table="series", velocities=None, masses=None, cell=None):
    """One dump's coolgas-fields table: "series" (one row: t cells E E_flow
    E_thermal T E_flow_noise E_L E_T E_L_noise E_T_noise density_var
    vorticity2), "spectrum" (t shell k E_L E_T modes) or "slab" (t x y
    density vorticity: the middle plane's cells).

    frame: a Frame (ballistic aggregation: the aggregates weighted by their
    masses), or positions with L and velocities (and t, masses). cell: the
    cell side wanted in sigma (default 4); df.attrs["cells"]: cells per side."""
    positions, L, t, f = _frame_args(frame, L, t)
    if f is not None:
        velocities = f.velocities if velocities is None else velocities
        masses = f.masses if masses is None else masses
    if velocities is None:
        raise TypeError("velocities are required with a positions array")
    d = _core.fields_table(positions, velocities, float(L), float(t), table, masses=masses, **_given(cell=cell))
    df = frame_of(d)
    df.attrs["cells"] = d["cells"]
    return df


def shape(frame, L=None, t=None, table="mass_radius", bins_per_decade=None, fit_mass=None, min_mass=None,
          masses=None):
    """One dump's coolgas-shape table: "mass_radius" (t m dm clusters Rg
    Rg_err asphericity prolateness), "series" (t d_f d_f_err fit_bins
    fitted_clusters asphericity prolateness wrapping_fraction) or "clusters"
    (t mass Rg lambda1 lambda2 lambda3 asphericity prolateness wraps: each
    cluster of at least min_mass particles, its gyration tensor's
    eigenvalues ascending).

    frame: a Frame (ballistic aggregation: its aggregates, solid spheres of
    diameter m^(1/3)), or positions with L (and t; masses for aggregates).
    fit_mass: the d_f fit's mass window, "lo:hi" or (lo, hi), None ends
    open. The block's comment (d_f and its error) is df.attrs["comment"]."""
    positions, L, t, f = _frame_args(frame, L, t)
    if f is not None and masses is None:
        masses = f.masses
    return frame_of(_core.shape_table(positions, float(L), float(t), table, masses=masses,
                                      **_given(bins_per_decade=bins_per_decade, fit_mass=window(fit_mass),
                                               min_mass=min_mass)))


def displacement(frame, reference):
    """One dump's coolgas-displacement row: t dt msd msd_err vacf vacf_norm
    T D_apparent of `frame` from `reference`, two Frames of one coolgas run
    (positions unwrapped by their image counts, as the tool does; the
    particles in the same order). Not for ballistic-aggregation frames."""
    for name, f in (("frame", frame), ("reference", reference)):
        if not isinstance(f, Frame) or f.images is None:
            raise TypeError(name + " must be a Frame of a coolgas run (with image counts)")
        if f.masses is not None:
            raise InputError(name + " is a ballistic-aggregation frame: its aggregates merge, and displacements "
                             "need particles that keep their identity")
    return frame_of(_core.displacement_row(frame.positions, frame.images, frame.velocities, float(frame.L),
                                           float(frame.t), reference.positions, reference.images,
                                           reference.velocities, float(reference.L), float(reference.t)))
