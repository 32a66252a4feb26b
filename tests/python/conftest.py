"""Shared runs for the Python tests: a small inelastic gas, its
ballistic-aggregation counterpart and inelastic gases of disks (2D) and of
rods (1D), simulated once per test file by the CLI (so every comparison is
Python against the tool on the same file)."""
import os
import subprocess
import time

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

RODS = """[system]
dimension = 1
N = 3000
phi = 0.3
seed = 4
[collision]
model = "inelastic"
r0 = 0.5
delta = 1e-3
[run]
t_end = 30
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


# The longest a test waits for a program to reach a named point: only a hang
# takes this long (tests/support/fault_points.h, kHangSeconds).
HANG_S = 240


def waiting_at(point, ready):
    """The environment that makes coolgas-simulate wait at a named point
    (common/fault_point.h, the WAIT action) after creating the file `ready`."""
    return dict(os.environ, COOLGAS_FAULT=point + ":WAIT", COOLGAS_FAULT_READY=str(ready))


def wait_for_point(ready, proc):
    """Returns once `proc` is at its point (the file `ready` exists); fails
    if it ended first or is not there within HANG_S."""
    deadline = time.monotonic() + HANG_S
    while not os.path.exists(ready):
        assert proc.poll() is None, f"the program ended (exit {proc.returncode}) before reaching its point"
        assert time.monotonic() < deadline, f"the program did not reach its point within {HANG_S} s"
        time.sleep(0.05)


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



@pytest.fixture(scope="module")
def rods(tmp_path_factory):
    return simulate_cli(tmp_path_factory.mktemp("rods"), "rods", RODS)
