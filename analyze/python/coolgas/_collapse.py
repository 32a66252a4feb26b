"""The energy collapse of several E(t) curves: coolgas-collapse on tables
held in memory (DataFrames, or arrays of t and E)."""
import numpy as np
import pandas as pd

from . import _core
from ._kernels import _given, window


def _curve(i, c):
    """The table coolgas-collapse would read: {"columns", "rows", "L", "source"}."""
    if isinstance(c, pd.DataFrame):
        if "L" not in c.attrs:
            raise ValueError(f"curves[{i}] has no L: give df.attrs['L'] (read_table of a coolgas-energy table has it) "
                             "or a tuple (L, t, E[, E_err])")
        return {"columns": [str(n) for n in c.columns], "rows": c.to_numpy(), "L": float(c.attrs["L"]),
                "source": str(c.attrs.get("source", f"curves[{i}]"))}
    if isinstance(c, dict):
        c = (c["L"], c["t"], c["E"], c.get("E_err"))
    if not isinstance(c, (tuple, list)) or len(c) not in (3, 4):
        raise TypeError(f"curves[{i}] must be a DataFrame with attrs['L'], a dict or a tuple (L, t, E[, E_err]), "
                        f"got {type(c).__name__}")
    # dtypes as given: the kernel converts integers and refuses complex numbers (arrays.h)
    L, columns = c[0], [np.asarray(a) for a in c[1:] if a is not None]
    if any(a.ndim != 1 or len(a) != len(columns[0]) for a in columns):
        raise ValueError(f"curves[{i}]: t, E (and E_err) must be 1-D arrays of one length, got shapes "
                         f"{[a.shape for a in columns]}")
    return {"columns": ["t", "E", "E_err"][:len(columns)], "rows": np.column_stack(columns), "L": float(L),
            "source": f"curves[{i}]"}


def collapse(curves, theta=None, z=None, optimize=False, bootstrap=None, seed=None, min_overlap=None, t_window=None,
             eta_window=None, weights="none", summary=False, t_column=None, e_column=None, z_theta=None):
    """coolgas-collapse on E(t) curves: finite-size scaling E(t) =
    L^(-z theta) f(t/L^z). Returns the tool's table: the scaled curves
    (x y L t E, one block per L ascending, df.attrs["block"]) or, with
    summary=True, one row (theta theta_err z z_err quality [eta eta_err]).

    curves: DataFrames of coolgas-energy tables (read_table: L from
    attrs["L"]), dicts {"L", "t", "E"[, "E_err"]} or tuples (L, t, E[,
    E_err]); several of one L are its runs (seeds). optimize: find theta and
    z (starting from theta, z); without t_window it collapses from where
    every curve is past Haff's law, as the tool does. z_theta (with
    optimize): hold z theta at this value and find z alone (--z-theta; 3
    is the paper's E L^3 against t/L^(5/2)). Windows: "lo:hi" or
    (lo, hi). weights: "none" or "seeds". df.attrs: theta, z, quality,
    theta_err, z_err, z_theta_err (the free fit's product z theta, its
    error from the same replicas), eta, eta_err (None when not computed),
    provenance."""
    if isinstance(curves, (pd.DataFrame, dict, tuple)):
        raise TypeError("curves must be a list of curves (several L), not a single "
                        f"{type(curves).__name__}")
    d = _core.collapse([_curve(i, c) for i, c in enumerate(curves)], optimize=bool(optimize), weights=weights,
                       summary=bool(summary), t_window=window(t_window), eta_window=window(eta_window),
                       **_given(theta=theta, z=z, bootstrap=bootstrap, seed=seed, min_overlap=min_overlap,
                                t_column=t_column, e_column=e_column, z_theta=z_theta))
    df = pd.DataFrame(d["rows"], columns=list(d["columns"]))
    df.attrs["block"] = d["block"]
    df.attrs["provenance"] = [tuple(kv) for kv in d["provenance"]]
    for key in ("theta", "z", "quality", "theta_err", "z_err", "z_theta_err", "eta", "eta_err"):
        df.attrs[key] = d[key]
    return df
