"""Shapes: coolgas.shape on a frame's arrays equals coolgas-shape on the same
file to the last bit (mass-radius, series, clusters with their gyration
eigenvalues; gas and aggregation), read back from the tool's shortest
round-trip numbers."""
import numpy as np
import pytest

import coolgas
from conftest import assert_the_tool_per_dump

FLAGS = {"mass_radius": [], "series": ["--series"], "clusters": ["--clusters", "--min-mass", 2]}


@pytest.mark.parametrize("table", ["mass_radius", "series", "clusters"])
@pytest.mark.parametrize("run", ["gas", "aggregates", "disks", "rods"])
def test_equals_the_tool(run, table, request, tmp_path):
    assert_the_tool_per_dump(request.getfixturevalue(run), "shape",
                             ["--fit-mass", "2:", "--bins-per-decade", 6, *FLAGS[table]],
                             lambda fr: coolgas.shape(fr, table=table, fit_mass=(2, None), bins_per_decade=6, min_mass=2),
                             tmp_path, block=table != "series")


def test_a_rod_and_a_sphere():
    # a straight row of 10 occupied cells: one cluster, a rod (asphericity 1, prolateness 2, l1 = l2 = 0)
    rod = np.column_stack([np.arange(10) + 0.5, np.full(10, 5.5), np.full(10, 5.5)])
    row = coolgas.shape(rod, L=20, table="clusters", min_mass=1).iloc[0]
    assert (row["mass"], row["lambda1"], row["lambda2"], row["asphericity"], row["prolateness"]) == (10, 0, 0, 1, 2)
    assert row["lambda3"] == pytest.approx((10 ** 2 - 1) / 12)  # the variance of 0..9
    # an aggregate of mass m is a solid sphere of diameter m^(1/3): R_g^2 = 3 d^2 / 20 (cluster_shapes.h)
    sphere = coolgas.shape(np.zeros((1, 3)), L=20, table="clusters", min_mass=1, masses=[27.0]).iloc[0]
    assert sphere["Rg"] == pytest.approx(np.sqrt(3 * 9 / 20)) and sphere["asphericity"] == 0


def test_bad_arguments_raise_python_errors():
    pos = np.random.default_rng(2).uniform(0, 10, size=(40, 3))
    with pytest.raises(coolgas.InputError, match=r"shape \(N, 3\)"):
        coolgas.shape(pos.ravel(), L=10)
    with pytest.raises(coolgas.InputError, match="allowed: mass_radius, series, clusters"):
        coolgas.shape(pos, L=10, table="Rg")
    with pytest.raises(coolgas.InputError, match="--min-mass must be >= 1"):
        coolgas.shape(pos, L=10, min_mass=0)
    with pytest.raises(coolgas.InputError, match="fit_mass"):
        coolgas.shape(pos, L=10, fit_mass="10")
    with pytest.raises(coolgas.InputError, match="need L >= 1"):
        coolgas.shape(pos * 0.04, L=0.5)
    with pytest.raises(coolgas.InputError, match=r"outside the box \[0, L\) of side L = 5"):
        coolgas.shape(pos, L=5)
    with pytest.raises(coolgas.InputError, match="not a mass of 1 to"):
        coolgas.shape(pos, L=10, masses=[0.0, 3.0])
    with pytest.raises(TypeError):
        coolgas.shape(pos, L=10, bins_per_decade="ten")
