"""The energy collapse: coolgas.collapse on E(t) tables equals
coolgas-collapse on the same tables to the last bit (scaled curves with fixed
and optimised exponents, the summary with eta, the jackknife over seeds with
seed weights), read back from the tool's shortest round-trip numbers; curves
given as arrays are the same tables."""
import numpy as np
import pandas as pd
import pytest

import coolgas
from conftest import simulate_cli, tool

SIZES = (10, 12, 14)


def scene(L, seed):
    return f"""[system]
L = {L}
phi = 0.208
seed = {seed}
[collision]
model = "inelastic"
r0 = 0.3
delta = 1e-4
[run]
t_end = 2000
"""


@pytest.fixture(scope="module")
def energy(tmp_path_factory):
    """E(t) tables of coolgas-energy: per L the mean of two seeds, and each seed alone."""
    tmp = tmp_path_factory.mktemp("energy")
    tables = {}
    for L in SIZES:
        runs = [simulate_cli(tmp, f"L{L}s{s}", scene(L, s)) for s in (1, 2)]
        for name, files in ((f"E{L}", runs), (f"E{L}-1", runs[:1]), (f"E{L}-2", runs[1:])):
            path = tmp / (name + ".tsv")
            path.write_text(tool("energy", *files).stdout)
            tables[name] = path
    return tables


def cli_table(tmp_path, *args):
    (tmp_path / "cli.tsv").write_text(tool("collapse", *args).stdout)
    # pandas for the values (read_table refuses the nan an impossible eta fit writes); read_table for the provenance
    return (pd.read_csv(tmp_path / "cli.tsv", sep="\t", comment="#", float_precision="round_trip"),
            coolgas.read_table(tmp_path / "cli.tsv"))


CASES = {
    "fixed": ([], {}),
    "optimised": (["--optimize", "--bootstrap", 5, "--seed", 3], {"optimize": True, "bootstrap": 5, "seed": 3}),
    "summary": (["--optimize", "--bootstrap", 5, "--summary", "--eta-window", "0.01:10", "--theta", 1.1, "--z", 2.2],
                {"optimize": True, "bootstrap": 5, "summary": True, "eta_window": (0.01, 10), "theta": 1.1, "z": 2.2}),
}


@pytest.mark.parametrize("case", CASES)
def test_equals_the_tool(case, energy, tmp_path):
    flags, options = CASES[case]
    paths = [energy[f"E{L}"] for L in SIZES]
    cli, cli_attrs = cli_table(tmp_path, *paths, *flags)
    py = coolgas.collapse([coolgas.read_table(p) for p in paths], **options)
    assert list(py.columns) == list(cli.columns)
    np.testing.assert_array_equal(py.to_numpy(), cli.to_numpy())  # exact: no tolerance
    if "summary" not in options:
        np.testing.assert_array_equal(py.attrs["block"], cli_attrs.attrs["block"])  # one block per L
    for key in ("theta", "z", "quality", "theta_err", "z_err", "z_theta_err"):
        if key in cli_attrs.attrs:
            assert py.attrs[key] == float(cli_attrs.attrs[key])
    assert py.attrs["theta_err"] is None or "theta_err" in cli_attrs.attrs


def test_seeds_jackknife_and_weights_equal_the_tool(energy, tmp_path):
    paths = [energy[f"E{L}-{s}"] for L in SIZES for s in (1, 2)]
    cli, _ = cli_table(tmp_path, *paths, "--optimize", "--summary", "--weights", "seeds", "--t-window", "1:2000")
    py = coolgas.collapse([coolgas.read_table(p) for p in paths], optimize=True, summary=True, weights="seeds",
                          t_window="1:2000")
    np.testing.assert_array_equal(py.to_numpy(), cli.to_numpy())


def test_fixed_product_equals_the_tool(energy, tmp_path):
    paths = [energy[f"E{L}-{s}"] for L in SIZES for s in (1, 2)]
    cli, _ = cli_table(tmp_path, *paths, "--optimize", "--summary", "--z-theta", "3", "--t-window", "1:2000")
    py = coolgas.collapse([coolgas.read_table(p) for p in paths], optimize=True, summary=True, z_theta=3,
                          t_window="1:2000")
    np.testing.assert_array_equal(py.to_numpy(), cli.to_numpy())
    assert py.attrs["z"] * py.attrs["theta"] == pytest.approx(3, rel=1e-14)


def test_arrays_are_the_same_tables(energy):
    tables = [coolgas.read_table(energy[f"E{L}"]) for L in SIZES]
    from_frames = coolgas.collapse(tables, theta=1.3, z=2.7)
    from_arrays = coolgas.collapse([(float(df.attrs["L"]), df["t"], df["E"], df["E_err"]) for df in tables],
                                   theta=1.3, z=2.7)
    np.testing.assert_array_equal(from_frames.to_numpy(), from_arrays.to_numpy())
    # x = t / L^z and y = E L^(z theta), the paper's Eq. (2)
    row = from_arrays.iloc[-1]
    assert row["x"] == pytest.approx(row["t"] / row["L"] ** 2.7, rel=1e-14)
    assert row["y"] == pytest.approx(row["E"] * row["L"] ** (2.7 * 1.3), rel=1e-14)


def test_bad_arguments_raise_python_errors(energy):
    t = np.array([1.0, 2.0, 4.0])
    with pytest.raises(TypeError, match="list of curves"):
        coolgas.collapse(coolgas.read_table(energy["E10"]))
    with pytest.raises(TypeError, match=r"tuple \(L, t, E"):
        coolgas.collapse([42])
    with pytest.raises(ValueError, match="one length"):
        coolgas.collapse([(10, t, t[:2])])
    with pytest.raises(ValueError, match="has no L"):
        coolgas.collapse([pd.DataFrame({"t": t, "E": t})])
    with pytest.raises(coolgas.InputError, match="not a box side"):
        coolgas.collapse([(-1, t, 1 / t), (12, t, 1 / t)])
    with pytest.raises(coolgas.InputError, match="not a finite number"):
        coolgas.collapse([(10, t, [1, np.nan, 0.5]), (12, t, 1 / t)])
    with pytest.raises(coolgas.InputError, match="allowed: none, seeds"):
        coolgas.collapse([(10, t, 1 / t), (12, t, 1 / t)], weights="errors")
    with pytest.raises(coolgas.InputError, match="--min-overlap"):
        coolgas.collapse([(10, t, 1 / t), (12, t, 1 / t)], min_overlap=-1)
    with pytest.raises(coolgas.InputError, match="t_window"):
        coolgas.collapse([(10, t, 1 / t), (12, t, 1 / t)], t_window="5")
    with pytest.raises(coolgas.InputError, match="needs optimize=True"):
        coolgas.collapse([(10, t, 1 / t), (12, t, 1 / t)], z_theta=3)
