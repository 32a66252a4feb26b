"""coolgas-fields on real runs: an equilibrium elastic gas's flow sits at the
noise level of independent velocities (each cell's mean velocity has
variance T/(m n_cell)), and its VTK image files read back with VTK's own
reader (Debian's python3-vtk9) hold the fields the table summarises."""
import io

import numpy as np
import pandas as pd
import pytest

from conftest import assert_the_tool_per_dump, simulate_cli, tool

# An elastic gas equilibrated from random placement; dumps every 2 collision times.
ELASTIC = """
[system]
N = 8000
phi = 0.2
seed = 4
equilibrate = 5
[collision]
model = "elastic"
[run]
t_end = 20
[output]
dumps_per_decade = 1
dump_times = [2, 4, 6, 8, 10, 12, 14, 16, 18]
"""


def table(*args):
    out = tool("fields", *args).stdout
    return pd.read_csv(io.StringIO(out), sep="\t", comment="#")


@pytest.fixture(scope="module")
def elastic(tmp_path_factory):
    return simulate_cli(tmp_path_factory.mktemp("elastic"), "elastic", ELASTIC)


def test_an_equilibrium_gas_flows_at_the_noise_level(elastic):
    t = table(elastic, "--cell", 3)
    late = t[t.t >= 2]
    cells = late.cells.iloc[0] ** 3
    # Each ratio is a sum of ~cells independent squares per dump: the mean
    # over the dumps is within a few sqrt(2/(d cells dumps)) of 1 (the dumps
    # two collision times apart are nearly independent).
    tol = 5 * np.sqrt(2 / (3 * cells * len(late)))
    assert abs((late.E_flow / late.E_flow_noise).mean() - 1) < tol
    assert abs((late.E_T / late.E_T_noise).mean() - 1) < tol
    assert abs((late.E_L / late.E_L_noise).mean() - 1) < 3 * tol
    # Energy is conserved and split exactly.
    assert np.allclose(late.E, late.E.iloc[0], rtol=1e-9)
    assert np.allclose(late.E_flow + late.E_thermal, late.E, rtol=1e-12)
    # Hard spheres at phi = 0.2 are less compressible than independent
    # points: the density varies less than Poisson's (S(0) = 0.3 by
    # Carnahan-Starling; cells of 3 sigma see more than k = 0).
    assert (late.density_var < 0.8).all()


def test_the_vti_files_read_back_with_vtk(elastic, tmp_path):
    from vtkmodules import vtkIOXML
    from vtkmodules.util.numpy_support import vtk_to_numpy
    t = table(elastic, "--cell", 3, "--time", 10, "--vti", tmp_path)
    files = sorted(tmp_path.glob("fields_*.vti"))
    assert len(files) == 1
    reader = vtkIOXML.vtkXMLImageDataReader()
    reader.SetFileName(str(files[0]))
    reader.Update()
    image = reader.GetOutput()
    n = int(t.cells.iloc[0])
    assert image.GetDimensions() == (n + 1, n + 1, n + 1)
    h = image.GetSpacing()[0]
    data = image.GetCellData()
    density = vtk_to_numpy(data.GetArray("density"))
    velocity = vtk_to_numpy(data.GetArray("velocity"))
    assert density.shape == (n ** 3,) and velocity.shape == (n ** 3, 3)
    count = density * h ** 3
    assert round(count.sum()) == 8000
    # Velocities relative to the centre of mass: the momentum adds to zero,
    # and the cells' flow energy is the table's E_flow.
    momentum = count[:, None] * velocity
    assert np.abs(momentum.sum(axis=0)).max() < 1e-9
    assert np.isclose((0.5 * (count[:, None] * velocity ** 2).sum()) / 8000, t.E_flow.iloc[0], rtol=1e-9)
    assert data.GetArray("vorticity").GetNumberOfComponents() == 3


def test_bad_options_are_one_line(elastic, tmp_path):
    r = tool("fields", elastic, "--cell", 0.5, check=False)
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "--cell = 0.5" in r.stderr
    r = tool("fields", elastic, "--vti", tmp_path / "missing", check=False)
    assert r.returncode == 2 and "not a directory" in r.stderr
    import coolgas
    fr = coolgas.open(elastic).frames[-1]
    with pytest.raises(ValueError, match="cell = 0.5"):
        coolgas.fields(fr, cell=0.5)
    with pytest.raises(ValueError, match="is not a fields table"):
        coolgas.fields(fr, table="vortices")
    with pytest.raises(ValueError, match="velocities must have"):
        coolgas.fields(fr.positions, L=fr.L, velocities=fr.velocities[:10])


# The paper's gas (phi = 0.208, r0 = 0.1, delta = 1e-4) in a box of side 34,
# ten dumps a decade.
COOLING = """
[system]
L = 34
phi = 0.208
seed = 1
[collision]
model = "inelastic"
r0 = 0.1
delta = 1e-4
[run]
t_end = 100
[output]
dumps_per_decade = 10
t_min = 0.1
"""


def first_time(t, ratio, level):
    above = t[ratio >= level]
    return above.iloc[0] if len(above) else np.inf


def test_vortices_grow_before_clusters(tmp_path):
    """The transverse (shear) flow rises above its noise level before the
    density's variance rises as far above its start: vortices, then clusters
    (Goldhirsch & Zanetti 1993; Brito & Ernst 1998)."""
    run = simulate_cli(tmp_path, "cooling", COOLING)
    t = table(run, "--cell", 4)
    shear = t.E_T / t.E_T_noise
    density = t.density_var / t.density_var.iloc[0]
    assert abs(shear.iloc[0] - 1) < 0.2  # the start is at the noise level
    for level in (2, 3, 5):
        assert first_time(t.t, shear, level) < first_time(t.t, density, level), level
    # By the time the shear flow is five times its noise, the density's
    # variance has not yet grown five-fold.
    assert density[t.t == first_time(t.t, shear, 5)].iloc[0] < 5


FLAGS = {"series": [], "spectrum": ["--spectrum"], "slab": ["--slab"]}


@pytest.mark.parametrize("table", ["series", "spectrum", "slab"])
@pytest.mark.parametrize("run", ["gas", "aggregates", "disks", "rods"])
def test_the_python_kernel_equals_the_tool(run, table, request, tmp_path):
    """coolgas.fields on a frame is coolgas-fields on its dump, to the last bit."""
    import coolgas
    path = request.getfixturevalue(run)
    if run == "rods" and table == "slab":  # no plane of cells: both refuse
        assert tool("fields", path, "--slab", check=False).returncode == 2
        with pytest.raises(ValueError, match="rods have none"):
            coolgas.fields(coolgas.open(path).frames[-1], table="slab")
        return
    assert_the_tool_per_dump(path, "fields", ["--cell", 2, *FLAGS[table]],
                             lambda fr: coolgas.fields(fr, table=table, cell=2), tmp_path, block=table != "series")
