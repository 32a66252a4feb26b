"""The Smoluchowski solver: coolgas.smoluchowski equals coolgas-smoluchowski
with the same options to the last bit (N(m,t) blocks, the series, both at
once as with --series-file, a run to a mean mass, a start from a
coolgas-clusters distribution), read back from the tool's shortest
round-trip numbers; and the constant kernel meets its exact solution."""
import numpy as np
import pandas as pd
import pytest

import coolgas
from conftest import tool


def cli_table(tmp_path, *args, name="cli.tsv"):
    path = tmp_path / name
    path.write_text(tool("smoluchowski", *args).stdout)
    return coolgas.read_table(path)


def same(py, cli):
    assert list(py.columns) == list(cli.columns)
    assert py.to_numpy().tobytes() == cli.to_numpy().tobytes()  # bit for bit


def test_distribution_blocks(tmp_path):
    cli = cli_table(tmp_path, "--kernel", "constant", "--M", 256, "--t-end", 10, "--time", "1,3")
    py = coolgas.smoluchowski(kernel="constant", M=256, t_end=10, times=[1, 3])
    same(py, cli)
    np.testing.assert_array_equal(py.attrs["block"], cli.attrs["block"])
    assert py.attrs["comments"] == ["t = 1", "t = 3", "t = 10"]
    # the '# end' line after the rows: steps and right-hand sides too, the same integration
    assert (tmp_path / "cli.tsv").read_text().endswith("# " + py.attrs["end"] + "\n")
    assert py.attrs["provenance"] == [kv for kv in cli.attrs["provenance"] if kv[0] in dict(py.attrs["provenance"])]


@pytest.mark.parametrize("args, options", [
    (["--kernel", "ballistic", "--M", 512, "--t-end", 3, "--series"],
     {"kernel": "ballistic", "M": 512, "t_end": 3, "table": "series"}),
    (["--kernel", "ballistic", "--M", 1024, "--until-mean-mass", 20, "--method", "geometric", "--convention", "paper",
      "--series", "--per-decade", 4],
     {"kernel": "ballistic", "M": 1024, "until_mean_mass": 20, "method": "geometric", "convention": "paper",
      "table": "series", "per_decade": 4}),
])
def test_series(tmp_path, args, options):
    same(coolgas.smoluchowski(**options), cli_table(tmp_path, *args))


def test_both_tables_are_the_tools_series_file(tmp_path):
    cli = cli_table(tmp_path, "--kernel", "additive", "--M", 512, "--t-end", 0.5, "--method", "direct",
                    "--series-file", tmp_path / "series.tsv", "--series-t-min", 0.001)
    dist, series = coolgas.smoluchowski(kernel="additive", M=512, t_end=0.5, method="direct", table="both",
                                        series_t_min=0.001)
    same(dist, cli)
    same(series, coolgas.read_table(tmp_path / "series.tsv"))


def test_a_start_from_a_clusters_table(gas, tmp_path):
    fr = coolgas.open(gas).frames[-1]
    (tmp_path / "N.tsv").write_text(tool("clusters", gas, "--time", repr(fr.t), "--exact-time").stdout)
    cli = cli_table(tmp_path, "--kernel", "constant", "--M", 4096, "--t-end", 3, "--initial", tmp_path / "N.tsv")
    same(coolgas.smoluchowski(kernel="constant", M=4096, t_end=3, initial=coolgas.clusters(fr)), cli)
    same(coolgas.smoluchowski(kernel="constant", M=4096, t_end=3, initial=tmp_path / "N.tsv"), cli)


def test_constant_kernel_meets_its_exact_solution():
    # c_k(t) = (t/2)^(k-1) / (1 + t/2)^(k+1) for K = 1, c_k(0) = delta_k1, half-gain time (exact.h)
    df = coolgas.smoluchowski(kernel="constant", M=128, t_end=2, method="direct", bins_per_decade=1000)
    k, t = df["m"].to_numpy(), 2.0
    exact = (t / 2) ** (k - 1) / (1 + t / 2) ** (k + 1)
    big = exact > 1e-12
    np.testing.assert_allclose(df["N"].to_numpy()[big], exact[big], rtol=1e-6)


def test_a_leak_past_the_cutoff_is_a_warning(tmp_path):
    with pytest.warns(RuntimeWarning, match="grown past the cut-off M = 64"):
        coolgas.smoluchowski(kernel="constant", M=64, t_end=100, leak_tolerance=1e-9)


def test_bad_arguments_raise_python_errors():
    with pytest.raises(coolgas.InputError, match="nothing to do"):
        coolgas.smoluchowski()
    with pytest.raises(coolgas.InputError, match="allowed: distribution, series, both"):
        coolgas.smoluchowski(t_end=1, table="N")
    with pytest.raises(coolgas.InputError, match="kernel"):
        coolgas.smoluchowski(kernel="quadratic", t_end=1)
    with pytest.raises(coolgas.InputError):
        coolgas.smoluchowski(t_end=1, M=1)
    with pytest.raises(coolgas.InputError, match="no column 'N'"):
        coolgas.smoluchowski(t_end=1, initial=pd.DataFrame({"m": [1.0], "n": [1.0]}))
    with pytest.raises(coolgas.InputError, match="not a finite number"):
        coolgas.smoluchowski(t_end=1, initial=pd.DataFrame({"m": [1.0], "N": [np.inf]}))
    with pytest.raises(TypeError, match="initial must be"):
        coolgas.smoluchowski(t_end=1, initial=3)
    with pytest.raises(TypeError):
        coolgas.smoluchowski(t_end="soon")
    with pytest.raises(TypeError):
        coolgas.smoluchowski(t_end=1, M="large")
