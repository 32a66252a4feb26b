"""The mean-field Smoluchowski solver: a coolgas-smoluchowski run whose
tables come back as DataFrames."""
import os
import warnings

import pandas as pd

from . import _core
from ._kernels import _given


def _initial(initial):
    """"mono", a table's path, or a DataFrame with columns m, N [, dm] (a coolgas-clusters distribution)."""
    if isinstance(initial, pd.DataFrame):
        return {"columns": [str(n) for n in initial.columns], "rows": initial.to_numpy(),
                "source": "the initial DataFrame"}
    if isinstance(initial, (str, os.PathLike)):
        return os.fspath(initial)
    raise TypeError(f"initial must be 'mono', a table's path or a DataFrame with columns m, N [, dm], "
                    f"got {type(initial).__name__}")


def _frame(table):
    df = pd.DataFrame(table["rows"], columns=list(table["columns"]))
    if "block" in table:
        df.attrs["block"] = table["block"]
        df.attrs["comments"] = list(table["comments"])
    return df


def smoluchowski(kernel=None, t_end=None, times=(), until_mean_mass=None, table="distribution", initial="mono",
                 method=None, M=None, grid_ratio=None, fft_floor=None, rtol=None, atol=None, stepper=None,
                 convention=None, series_t_min=None, per_decade=None, bins_per_decade=None, volume=None,
                 leak_tolerance=None):
    """coolgas-smoluchowski: N(m, t) from the Smoluchowski equation, as the
    tool's tables. table: "distribution" (t m dm N x y, a block per time in
    `times` and at the end: df.attrs["block"]), "series" (t M0 M1 M2 M_avg
    M_max largest_fraction) or "both" (a pair: the tool with --series-file).

    kernel: constant, additive, product, ballistic (default), eq4 or
    separable:c,p,q[;...]; stop at t_end, at the last of `times`, or when the
    mean mass reaches until_mean_mass. initial: "mono", a table's path, or a
    DataFrame with columns m, N [, dm]. The other options are the tool's
    (None: its default). The tool's warnings (mass leaking past M) are
    RuntimeWarnings; df.attrs holds provenance, end (the '# end' line), t,
    leaked_fraction, steps, evaluations."""
    d = _core.smoluchowski(initial=_initial(initial), times=[float(t) for t in times], t_end=t_end,
                           until_mean_mass=until_mean_mass, table=table,
                           **_given(kernel=kernel, method=method, M=M, grid_ratio=grid_ratio, fft_floor=fft_floor,
                                    rtol=rtol, atol=atol, stepper=stepper, convention=convention,
                                    series_t_min=series_t_min, per_decade=per_decade,
                                    bins_per_decade=bins_per_decade, volume=volume, leak_tolerance=leak_tolerance))
    for line in d["warnings"]:
        warnings.warn(line, RuntimeWarning, stacklevel=2)
    tables = [_frame(d[k]) for k in ("distribution", "series") if k in d]
    for df in tables:
        df.attrs["provenance"] = [tuple(kv) for kv in d["provenance"]]
        for key in ("end", "t", "leaked_fraction", "steps", "evaluations"):
            df.attrs[key] = d[key]
    return tuple(tables) if table == "both" else tables[0]
