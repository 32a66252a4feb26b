"""Velocity statistics: coolgas.velocity on a frame's velocities equals
coolgas-velocity on the same file to the last bit (Phi, tail, series; a
rough run's spins as --spins, in 3D and 2D; a mixture's species as
--species), and a Maxwellian sample has kappa = 0 within its error
(tests/physics/README.md)."""
import numpy as np
import pandas as pd
import pytest

import coolgas
from conftest import DISKS, GAS, simulate_cli, tool


@pytest.mark.parametrize("table", ["Phi", "tail", "series"])
@pytest.mark.parametrize("run", ["gas", "aggregates", "disks", "rods"])
def test_equals_the_tool(run, table, request, tmp_path):
    path = request.getfixturevalue(run)
    frames = coolgas.open(path).frames
    options = {"bins": 60, "ymax": 5.0, "tail_from": 1.2, "min_count": 10}
    for i in (len(frames) // 2, len(frames) - 1):
        fr = frames[i]
        flag = {"Phi": [], "tail": ["--tail"], "series": ["--series"]}[table]
        out = tool("velocity", path, *flag, "--time", repr(fr.t), "--exact-time", "--bins", 60, "--ymax", 5,
                   "--tail-from", 1.2, "--min-count", 10).stdout
        (tmp_path / "cli.tsv").write_text(out)
        # pandas, not read_table: a series row whose tail cannot be fitted holds nan, which read_table refuses
        cli = pd.read_csv(tmp_path / "cli.tsv", sep="\t", comment="#", float_precision="round_trip")
        py = coolgas.velocity(fr, table=table, **options)
        assert list(py.columns) == list(cli.columns)
        np.testing.assert_array_equal(py.to_numpy(), cli.to_numpy())  # exact: no tolerance (nan equals nan)
        if table != "series":
            assert "# " + py.attrs["comment"] + "\n" in out


@pytest.mark.parametrize("scene, option, kwargs", [
    (GAS.replace("delta = 1e-4", "delta = 1e-4\nbeta = 0.5").replace("t_end = 300", "t_end = 5"), ["--spins"],
     {"spins": True}),
    (DISKS.replace("delta = 1e-3", "delta = 1e-3\nbeta = 0.5").replace("t_end = 100", "t_end = 5"), ["--spins"],
     {"spins": True}),
    (GAS.replace("t_end = 300", "t_end = 5") + "\n[[species]]\nfraction = 0.25\ndiameter = 1\n[[species]]\n"
     "fraction = 0.75\ndiameter = 0.8\n", ["--species", 1], {"species": 1}),
], ids=["spins", "disk_spins", "species"])
def test_spins_and_species_equal_the_tool(scene, option, kwargs, tmp_path):
    path = simulate_cli(tmp_path, "run", scene)
    fr = coolgas.open(path).frames[-1]
    for table, flag in (("Phi", []), ("series", ["--series"])):
        out = tool("velocity", path, *flag, *option, "--time", repr(fr.t), "--exact-time", "--bins", 60,
                   "--tail-from", 1.2, "--min-count", 10).stdout
        (tmp_path / "cli.tsv").write_text(out)
        cli = pd.read_csv(tmp_path / "cli.tsv", sep="\t", comment="#", float_precision="round_trip")
        py = coolgas.velocity(fr, table=table, bins=60, tail_from=1.2, min_count=10, **kwargs)
        assert list(py.columns) == list(cli.columns)
        np.testing.assert_array_equal(py.to_numpy(), cli.to_numpy())
    other = {"species": 0} if "spins" in kwargs else {"spins": True}
    with pytest.raises(coolgas.InputError, match="has no|no particle"):
        coolgas.velocity(fr, **other)


def test_a_maxwellian_has_no_excess_kurtosis():
    v = np.random.default_rng(3).normal(size=(200000, 3))
    df = coolgas.velocity(v, table="series")
    assert abs(df.attrs["kappa"]) < 4 * df.attrs["kappa_err"]
    assert df["v_rms"].iloc[0] == pytest.approx(1.0, abs=0.01)


def test_bad_options_are_one_clear_error():
    v = np.random.default_rng(3).normal(size=(100, 3))
    with pytest.raises(coolgas.InputError, match="allowed: Phi, tail, series"):
        coolgas.velocity(v, table="phi")
    with pytest.raises(coolgas.InputError, match="--bins must be even"):
        coolgas.velocity(v, bins=7)
    with pytest.raises(coolgas.InputError, match="3 needed to fit beta"):
        coolgas.velocity(v, table="tail")
