"""coolgas for Python: read coolgas (and other H5MD 1.1) trajectories and the
tools' TSV tables, run coolgas-simulate, and call the analysis kernels the
coolgas-<tool> programs run, on numpy arrays.

    run = coolgas.open("gas.h5")           # .parameters, .observables, .frames
    df = coolgas.read_table("E.tsv")       # provenance in df.attrs
    labels, sizes = coolgas.label_clusters(run.frames[-1].positions, run.L)

The C++ extension coolgas._core wraps the project's libraries; nothing here
computes what a tool computes (ARCHITECTURE.md, analyze/python/).
"""
import sys as _sys

# The package needs the interpreter it was built for, with numpy and pandas
# (Debian's python3 and its python3-numpy, python3-pandas); under another one
# the import fails with one line that names it, not a traceback from inside.
try:
    import numpy as _numpy  # noqa: F401
    import pandas as _pandas  # noqa: F401
    from ._core import InputError, program_version as _program_version
except ImportError as _error:
    from ._built_for import PYTHON as _PYTHON, PYTHON_VERSION as _PYTHON_VERSION
    _missing = _error.name or str(_error)
    if _sys.executable == _PYTHON:
        raise ImportError(f"coolgas needs numpy and pandas in {_PYTHON}, the Python it was built for, where {_missing} "
                          "cannot be imported (Debian: apt-get install python3-numpy python3-pandas)") from None
    raise ImportError(f"coolgas runs under {_PYTHON} (Python {_PYTHON_VERSION} with numpy and pandas), the Python it "
                      f"was built for, not {_sys.executable} (Python {_sys.version.split()[0]}), where {_missing} "
                      f"cannot be imported: run {_PYTHON}") from None

# The version the tools print: `coolgas-simulate --version` is
# "coolgas-simulate " + __version__ for the same build.
__version__ = _program_version()

from ._tables import read_table  # noqa: E402
from ._run import open, Run, Frame, Frames  # noqa: E402,A001
from ._kernels import label_clusters, clusters, velocity, structure, fields, shape, displacement  # noqa: E402
from ._collapse import collapse  # noqa: E402
from ._smoluchowski import smoluchowski  # noqa: E402
from ._simulate import simulate, SimulationError, SimulationInterrupted  # noqa: E402

__all__ = ["__version__", "InputError", "read_table", "open", "Run", "Frame", "Frames", "label_clusters", "velocity",
           "clusters", "structure", "fields", "shape", "displacement", "collapse", "smoluchowski", "simulate",
           "SimulationError", "SimulationInterrupted"]
