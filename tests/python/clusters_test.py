"""Clusters: coolgas.clusters on a frame's arrays equals coolgas-clusters on
the same file to the last bit (every table, gas and aggregation; both
definitions, unit cells and contacts), and
label_clusters' labels and size table agree with the tool's masses (by
either definition; by contact also with an all-pairs labelling); a
mixture's tables, whole or of one species, are the tool's too."""
import numpy as np
import pytest

import coolgas
from conftest import assert_the_tool_per_dump, simulate_cli, tool


def cli_table(tmp_path, *args):
    path = tmp_path / "cli.tsv"
    path.write_text(tool("clusters", *args).stdout)
    return coolgas.read_table(path)


@pytest.mark.parametrize("table, flag", [("distribution", None), ("scaled", "--scaled"), ("series", "--series")])
@pytest.mark.parametrize("run", ["gas", "aggregates", "disks", "rods"])
def test_equals_the_tool(run, table, flag, request, tmp_path):
    path = request.getfixturevalue(run)
    frames = coolgas.open(path).frames
    for i in (len(frames) // 2, len(frames) - 1):
        fr = frames[i]
        cli = cli_table(tmp_path, path, "--time", repr(fr.t), "--exact-time", *([flag] if flag else []),
                        "--bins-per-decade", 7)
        py = coolgas.clusters(fr, table=table, bins_per_decade=7)
        assert list(py.columns) == list(cli.columns)
        assert py.to_numpy().tobytes() == cli.to_numpy().tobytes()  # bit for bit
        if table != "series":
            assert "# " + py.attrs["comment"] in tool("clusters", path, "--time", repr(fr.t), "--bins-per-decade",
                                                      7).stdout


@pytest.mark.parametrize("definition", ["contact", "contact:1.3"])
@pytest.mark.parametrize("run", ["gas", "disks", "rods"])
def test_contact_clusters_equal_the_tool(run, definition, request, tmp_path):
    path = request.getfixturevalue(run)
    for fr in coolgas.open(path).frames[-2:]:
        for table, flag in (("distribution", []), ("series", ["--series"])):
            cli = cli_table(tmp_path, path, "--time", repr(fr.t), "--exact-time", "--definition", definition, *flag)
            py = coolgas.clusters(fr, table=table, definition=definition)
            assert py.to_numpy().tobytes() == cli.to_numpy().tobytes()  # bit for bit


def test_contact_clusters_refuse_bad_definitions(aggregates):
    pos = np.random.default_rng(3).uniform(0, 10, size=(40, 3))
    with pytest.raises(coolgas.InputError, match="not a cluster definition"):
        coolgas.clusters(pos, L=10, definition="touching")
    with pytest.raises(coolgas.InputError, match="exceeds half the box side"):
        coolgas.clusters(pos, L=10, definition="contact:6")
    with pytest.raises(coolgas.InputError, match="aggregates"):
        coolgas.clusters(coolgas.open(aggregates).frames[-1], definition="contact")


def test_labels_and_sizes_are_the_tools_clusters(gas, tmp_path):
    fr = coolgas.open(gas).frames[-1]
    labels, sizes = coolgas.label_clusters(fr)
    assert len(labels) == len(fr.positions)
    # the size table is the labels counted, largest first, covering every particle
    np.testing.assert_array_equal(np.bincount(labels), sizes["mass"].to_numpy())
    assert (np.diff(sizes["mass"].to_numpy()) <= 0).all() and sizes["mass"].sum() == len(labels)
    # M_max and the cluster count per volume are the tool's
    series = cli_table(tmp_path, gas, "--series", "--time", repr(fr.t), "--exact-time")
    assert sizes["mass"].iloc[0] == series["M_max"].iloc[0]
    assert len(sizes) / fr.L ** 3 == series["M0"].iloc[0]
    # two particles in one cell share a label; a particle alone in a cube of empty cells is its own cluster
    cells = np.floor(fr.positions / (fr.L / np.floor(fr.L))).astype(int)
    flat = cells[:, 0] + int(np.floor(fr.L)) * (cells[:, 1] + int(np.floor(fr.L)) * cells[:, 2])
    order = np.argsort(flat, kind="stable")
    same_cell = flat[order][1:] == flat[order][:-1]
    assert (labels[order][1:][same_cell] == labels[order][:-1][same_cell]).all()


def test_face_neighbours_across_the_boundary_join():
    # cells (0,0,0) and (9,0,0) share a face through the periodic boundary; (5,5,5) is alone
    labels, sizes = coolgas.label_clusters([[0.5, 0.5, 0.5], [9.5, 0.5, 0.5], [5.5, 5.5, 5.5], [5.5, 6.5, 6.5]], 10.0)
    np.testing.assert_array_equal(labels, [0, 0, 1, 2])
    np.testing.assert_array_equal(sizes["mass"], [2, 1, 1])


def all_pairs_contact_labels(pos, L, cutoff):
    """Contact clusters by every pair (minimum image) and a plain union-find,
    ranked as label_clusters ranks them: by mass, ties by smallest particle."""
    n = len(pos)
    parent = list(range(n))

    def find(x):
        while parent[x] != x:
            x = parent[x]
        return x

    d = np.abs(pos[:, None, :] - pos[None, :, :])
    d = np.minimum(d, L - d)
    close = (d ** 2).sum(axis=2) < cutoff ** 2
    for i, j in zip(*np.nonzero(np.triu(close, 1))):
        a, b = find(i), find(j)
        parent[max(a, b)] = min(a, b)
    roots = np.array([find(i) for i in range(n)])
    firsts = np.unique(roots)  # the smallest particle of each cluster, increasing
    mass = np.array([(roots == r).sum() for r in firsts])
    order = sorted(range(len(firsts)), key=lambda k: -mass[k])  # stable: ties by smallest particle
    rank = {firsts[k]: r for r, k in enumerate(order)}
    return np.array([rank[r] for r in roots]), mass[order], firsts[order]


@pytest.mark.parametrize("run", ["gas", "disks", "rods"])
@pytest.mark.parametrize("definition, cutoff", [("contact", 1.1), ("contact:1.3", 1.3)])
def test_contact_labels_are_the_tools_clusters(run, definition, cutoff, request, tmp_path):
    path = request.getfixturevalue(run)
    fr = coolgas.open(path).frames[-1]
    labels, sizes = coolgas.label_clusters(fr, definition=definition)
    assert list(sizes.columns) == ["cluster", "mass", "first_particle"]
    np.testing.assert_array_equal(np.bincount(labels), sizes["mass"].to_numpy())
    assert (np.diff(sizes["mass"].to_numpy()) <= 0).all() and sizes["mass"].sum() == len(fr.positions)
    # the tool's series at that dump, to the last bit: M_max, the clusters
    # per volume and the largest share, from the sizes
    series = cli_table(tmp_path, path, "--series", "--time", repr(fr.t), "--exact-time", "--definition", definition)
    d = fr.positions.shape[1]
    assert sizes["mass"].iloc[0] == series["M_max"].iloc[0]
    assert len(sizes) / fr.L ** d == series["M0"].iloc[0]
    assert sizes["mass"].iloc[0] / len(labels) == series["largest_fraction"].iloc[0]
    # the labels themselves against every pair, on the first 600 particles
    # (their own clusters: a smaller frame in the same box)
    pos = fr.positions[:600]
    labels, sizes = coolgas.label_clusters(pos, fr.L, definition=definition)
    want, mass, first = all_pairs_contact_labels(pos, fr.L, cutoff)
    np.testing.assert_array_equal(labels, want)
    np.testing.assert_array_equal(sizes["mass"], mass)
    np.testing.assert_array_equal(sizes["first_particle"], first)


def test_contact_labels_join_across_the_boundary():
    # 0 and 1 touch through the periodic boundary (distance 1.0 < 1.1); 2 and 3 are
    # 1.2 apart, bonded at cutoff 1.3 only; equal masses rank by smallest particle
    pos = [[0.2, 5.0, 5.0], [9.2, 5.0, 5.0], [5.0, 5.0, 5.0], [5.0, 6.2, 5.0]]
    labels, sizes = coolgas.label_clusters(pos, 10.0, definition="contact")
    np.testing.assert_array_equal(labels, [0, 0, 1, 2])
    np.testing.assert_array_equal(sizes["first_particle"], [0, 2, 3])
    labels, sizes = coolgas.label_clusters(pos, 10.0, definition="contact:1.3")
    np.testing.assert_array_equal(labels, [0, 0, 1, 1])
    np.testing.assert_array_equal(sizes["mass"], [2, 2])
    with pytest.raises(coolgas.InputError, match="exceeds half the box side"):
        coolgas.label_clusters(pos, 10.0, definition="contact:6")


MIXTURE = """[system]
N = 1000
phi = 0.15
seed = 7
equilibrate = 1
[collision]
model = "inelastic"
r0 = 0.8
[run]
t_end = 20
[output]
dumps_per_decade = 4

[[species]]
fraction = 0.6
diameter = 1

[[species]]
fraction = 0.4
diameter = 1.5
"""


@pytest.fixture(scope="module")
def mixture(tmp_path_factory):
    return simulate_cli(tmp_path_factory.mktemp("mixture"), "mixture", MIXTURE)


@pytest.mark.parametrize("species", [None, 0, 1])
@pytest.mark.parametrize("definition", ["cells", "contact", "contact:1.3"])
def test_a_mixtures_clusters_equal_the_tool(mixture, definition, species, tmp_path):
    # The whole mixture (its Frame's masses are its species', not
    # aggregates; contacts at CUTOFF sigma_ij) or one species, as --species.
    option = [] if species is None else ["--species", species]
    for table, flag in (("distribution", []), ("scaled", ["--scaled"]), ("series", ["--series"])):
        assert_the_tool_per_dump(mixture, "clusters", ["--definition", definition, *option, *flag],
                                 lambda fr: coolgas.clusters(fr, table=table, definition=definition, species=species),
                                 tmp_path, block=table != "series")


def test_a_species_labels_are_its_own_contact_clusters(mixture, gas):
    # Species k alone, against every pair of its particles at 1.1 sigma_k;
    # the other species' labels are -1, first particles the frame's.
    fr = coolgas.open(mixture).frames[-1]
    for k in (0, 1):
        labels, sizes = coolgas.label_clusters(fr, definition="contact", species=k)
        mine = fr.species == k
        assert (labels[~mine] == -1).all()
        want, mass, first = all_pairs_contact_labels(fr.positions[mine], fr.L, 1.1 * fr.diameters[mine][0])
        np.testing.assert_array_equal(labels[mine], want)
        np.testing.assert_array_equal(sizes["mass"], mass)
        np.testing.assert_array_equal(sizes["first_particle"], np.flatnonzero(mine)[first])
    with pytest.raises(coolgas.InputError, match="species = 2: the frame has species 0 to 1"):
        coolgas.label_clusters(fr, species=2)
    with pytest.raises(coolgas.InputError, match="a mixture's Frame"):
        coolgas.clusters(coolgas.open(gas).frames[-1], species=0)
