"""coolgas for Python: read coolgas (and other H5MD 1.1) trajectories and the
tools' TSV tables, run coolgas-simulate, and call the analysis kernels the
coolgas-<tool> programs run, on numpy arrays.

    run = coolgas.open("gas.h5")           # .parameters, .observables, .frames
    df = coolgas.read_table("E.tsv")       # provenance in df.attrs
    labels, sizes = coolgas.label_clusters(run.frames[-1].positions, run.L)

The C++ extension coolgas._core wraps the project's libraries; nothing here
computes what a tool computes (ARCHITECTURE.md, analyze/python/).
"""
from ._core import InputError, program_version as _program_version

# The version the tools print: `coolgas-simulate --version` is
# "coolgas-simulate " + __version__ for the same build.
__version__ = _program_version()

from ._tables import read_table  # noqa: E402
from ._run import open, Run, Frame, Frames  # noqa: E402,A001
from ._kernels import label_clusters, clusters, velocity, structure, shape  # noqa: E402
from ._collapse import collapse  # noqa: E402
from ._smoluchowski import smoluchowski  # noqa: E402
from ._simulate import simulate, SimulationError, SimulationInterrupted  # noqa: E402

__all__ = ["__version__", "InputError", "read_table", "open", "Run", "Frame", "Frames", "label_clusters", "velocity",
           "clusters", "structure", "shape", "collapse", "smoluchowski", "simulate", "SimulationError", "SimulationInterrupted"]
