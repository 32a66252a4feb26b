"""Shared runs for the Python tests: a small inelastic gas, its
ballistic-aggregation counterpart and an inelastic gas of disks (2D),
simulated once per test file by the CLI (so every comparison is Python
against the tool on the same file), and a file of rods (1D) made from the
gas's file."""
import os
import shutil
import subprocess

import h5py
import numpy as np

import pytest

BIN = os.environ["COOLGAS_BIN_DIR"]

GAS = """[system]
L = 16
phi = 0.208
seed = 7
[collision]
model = "inelastic"
r0 = 0.1
delta = 1e-4
[run]
t_end = 300
[output]
dumps_per_decade = 3
"""

DISKS = """[system]
dimension = 2
N = 3000
phi = 0.3
seed = 4
[collision]
model = "inelastic"
r0 = 0.5
delta = 1e-3
[run]
t_end = 100
[output]
dumps_per_decade = 3
"""

AGGREGATES = """[system]
N = 3000
phi = 0.1
seed = 2
[collision]
model = "aggregation"
[run]
t_end = 20
"""


def tool(name, *args, check=True):
    """Runs bin/coolgas-<name>; the CompletedProcess (text)."""
    return subprocess.run([os.path.join(BIN, "coolgas-" + name), *map(str, args)], capture_output=True, text=True,
                          check=check)


def simulate_cli(tmp, name, scene):
    scene_path = tmp / (name + ".toml")
    scene_path.write_text(scene)
    out = tmp / (name + ".h5")
    tool("simulate", "-q", scene_path, "-o", out)
    return out


@pytest.fixture(scope="module")
def gas(tmp_path_factory):
    return simulate_cli(tmp_path_factory.mktemp("gas"), "gas", GAS)


@pytest.fixture(scope="module")
def disks(tmp_path_factory):
    return simulate_cli(tmp_path_factory.mktemp("disks"), "disks", DISKS)


@pytest.fixture(scope="module")
def aggregates(tmp_path_factory):
    return simulate_cli(tmp_path_factory.mktemp("ba"), "ba", AGGREGATES)


def assert_the_tool_per_dump(path, name, args, kernel, tmp_path, block=True):
    """For the middle and the last dump of `path`: kernel(frame) equals
    coolgas-<name> --time t --exact-time ARGS to the last bit (the tool
    prints shortest round-trip numbers, read back as the very doubles), and
    for a table of blocks its block comment is the tool's."""
    import coolgas
    import pandas as pd
    frames = coolgas.open(path).frames
    for i in (len(frames) // 2, len(frames) - 1):
        fr = frames[i]
        out = tool(name, path, "--time", repr(fr.t), "--exact-time", *args).stdout
        (tmp_path / "cli.tsv").write_text(out)
        cli = pd.read_csv(tmp_path / "cli.tsv", sep="\t", comment="#", float_precision="round_trip")
        py = kernel(fr)
        assert list(py.columns) == list(cli.columns)
        assert py.to_numpy().tobytes() == cli.to_numpy().tobytes()  # bit for bit
        if block:
            assert "# " + py.attrs["comment"] + "\n" in out


RODS_L = 3000.0


def _one_component(group, name, values):
    """Replaces dataset `name` of `group` by `values`, chunked and resizable as the writer makes it."""
    del group[name]
    group.create_dataset(name, data=values, maxshape=(None,) + values.shape[1:], chunks=True)


@pytest.fixture(scope="module")
def rods(gas, tmp_path_factory):
    """A 1D file (the simulator writes none yet): the gas run's file with box/dimension = 1 and its particles
    replaced by as many rods on a ring of length RODS_L, uniform positions and Gaussian velocities of rms
    1/(1 + t) (seed 5), every vector (F, N, 1) and the box edges (F, 1, 1)."""
    path = tmp_path_factory.mktemp("rods") / "rods.h5"
    shutil.copy(gas, path)
    rng = np.random.default_rng(5)
    with h5py.File(path, "r+") as f:
        p = f["particles/all"]
        frames, n = p["position/value"].shape[:2]
        t = p["position/time"][:]
        p["box"].attrs["dimension"] = np.int64(1)
        f["parameters"].attrs["L"] = RODS_L
        _one_component(p["box/edges"], "value", np.full((frames, 1, 1), RODS_L))
        _one_component(p["position"], "value", rng.uniform(0, RODS_L, (frames, n, 1)))
        _one_component(p["velocity"], "value", rng.normal(size=(frames, n, 1)) / (1 + t)[:, None, None])
        _one_component(p["image"], "value", np.zeros((frames, n, 1), dtype=np.int32))
        momentum = f["observables/total_momentum"]
        _one_component(momentum, "value", momentum["value"][:, :1])
    return path
