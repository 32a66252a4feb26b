"""Tables as pandas DataFrames: the tools' TSV files (common/tsv.h reads
them) and the rows the kernels return, with the same column names."""
import os

import pandas as pd

from . import _core


def frame_of(table):
    """A DataFrame of a {"columns", "rows"} dict from _core; its block comment in attrs."""
    df = pd.DataFrame(table["rows"], columns=list(table["columns"]))
    if table.get("comment"):
        df.attrs["comment"] = table["comment"]
    return df


def read_table(path):
    """A coolgas TSV table (data-schema/tsv-tables.md) as a DataFrame.

    df.attrs holds the provenance: each "# key: value" line as attrs[key]
    (a list when the key repeats, e.g. one "input" per file), the lines in
    order as attrs["provenance"], and the block of each row (gnuplot's index)
    as attrs["block"]."""
    path = os.fspath(path)
    if path != "-" and not os.path.exists(path):
        raise FileNotFoundError(2, "no such table", path)
    t = _core.read_table(path)
    df = frame_of(t)
    prov = [tuple(kv) for kv in t["provenance"]]
    for key, value in prov:
        if key in df.attrs:
            old = df.attrs[key]
            df.attrs[key] = (old if isinstance(old, list) else [old]) + [value]
        else:
            df.attrs[key] = value
    df.attrs["provenance"] = prov
    df.attrs["block"] = t["block"]
    df.attrs["source"] = t["source"]
    return df
