"""Structure: coolgas.structure on a frame's arrays equals coolgas-structure
on the same file to the last bit (spectrum, series, correlation; gas and
aggregation; g(r) and its contact value in every dimension). The tool prints every number in its shortest round-trip form,
so reading its TSV back gives the very doubles it computed."""
import numpy as np
import pandas as pd
import pytest

import coolgas
from conftest import assert_the_tool_per_dump, tool

FLAGS = {"spectrum": [], "series": ["--series"], "correlation": ["--correlation"]}


def cli_table(tmp_path, *args):
    out = tool("structure", *args).stdout
    (tmp_path / "cli.tsv").write_text(out)
    return pd.read_csv(tmp_path / "cli.tsv", sep="\t", comment="#", float_precision="round_trip"), out


@pytest.mark.parametrize("table", ["spectrum", "series", "correlation"])
@pytest.mark.parametrize("run", ["gas", "aggregates", "disks", "rods"])
def test_equals_the_tool(run, table, request, tmp_path):
    assert_the_tool_per_dump(request.getfixturevalue(run), "structure",
                             ["--direct-shells", 2, "--peak-fraction", 0.15, *FLAGS[table]],
                             lambda fr: coolgas.structure(fr, table=table, direct_shells=2, peak_fraction=0.15),
                             tmp_path, block=table != "series")


RDF_FLAGS = {"rdf": ["--rdf"], "rdf_series": ["--rdf", "--series"]}


@pytest.mark.parametrize("table", ["rdf", "rdf_series"])
@pytest.mark.parametrize("run", ["gas", "disks", "rods"])
def test_rdf_equals_the_tool(run, table, request, tmp_path):
    assert_the_tool_per_dump(request.getfixturevalue(run), "structure",
                             [*RDF_FLAGS[table], "--r-max", 2.5, "--bins-per-sigma", 40, "--contact-bins", 6],
                             lambda fr: coolgas.structure(fr, table=table, r_max=2.5, bins_per_sigma=40,
                                                          contact_bins=6),
                             tmp_path, block=table == "rdf")


def test_rdf_refuses_aggregates_and_bad_ranges(aggregates):
    fr = coolgas.open(aggregates).frames[-1]
    with pytest.raises(coolgas.InputError, match="particles of one diameter"):
        coolgas.structure(fr, table="rdf")
    pos = np.random.default_rng(2).uniform(0, 10, size=(50, 3))
    with pytest.raises(coolgas.InputError, match="exceeds half the box side"):
        coolgas.structure(pos, L=10, table="rdf", r_max=6)
    with pytest.raises(coolgas.InputError, match="--contact-bins"):
        coolgas.structure(pos, L=10, table="rdf_series", contact_bins=1)


def test_arrays_and_a_chosen_grid_equal_the_tool(gas, tmp_path):
    fr = coolgas.open(gas).frames[-1]
    cli, _ = cli_table(tmp_path, gas, "--time", repr(fr.t), "--exact-time", "--grid", 8, "--series")
    py = coolgas.structure(fr.positions, L=fr.L, t=fr.t, velocities=fr.velocities, table="series", grid=8)
    assert py.to_numpy().tobytes() == cli.to_numpy().tobytes()
    assert py.attrs["grid"] == 8


def test_bad_arguments_raise_python_errors():
    rng = np.random.default_rng(1)
    pos = rng.uniform(0, 10, size=(50, 3))
    with pytest.raises(coolgas.InputError, match=r"shape \(N, 3\)"):
        coolgas.structure(np.hstack([pos, pos]), L=10)
    with pytest.raises(coolgas.InputError, match=r"velocities of the positions' shape \(50, 2\), got \(50, 3\)"):
        coolgas.structure(pos[:, :2], L=10, table="series", velocities=pos)  # disks with 3D velocities
    with pytest.raises(coolgas.InputError, match="allowed: spectrum, series, correlation, rdf, rdf_series"):
        coolgas.structure(pos, L=10, table="S")
    with pytest.raises(coolgas.InputError, match="needs velocities"):
        coolgas.structure(pos, L=10, table="series")
    with pytest.raises(coolgas.InputError, match="--grid must be an even number"):
        coolgas.structure(pos, L=10, grid=9)
    with pytest.raises(coolgas.InputError, match="too small"):
        coolgas.structure(pos * 0.6, L=6)
    with pytest.raises(coolgas.InputError, match="not a box side"):
        coolgas.structure(pos, L=float("nan"), grid=8)
    with pytest.raises(coolgas.InputError, match="masses holds 3 values for 50"):
        coolgas.structure(pos, L=10, masses=[1, 2, 3])
    with pytest.raises(coolgas.InputError, match="not a finite number"):
        coolgas.structure(np.where(pos > 9, np.nan, pos), L=10)
    with pytest.raises(TypeError):
        coolgas.structure(pos)  # no L
    with pytest.raises(TypeError):
        coolgas.structure("positions", L=10)
