"""Displacement: coolgas.displacement on two frames of a run equals
coolgas-displacement on the same file to the last bit (gas, disks, rods),
from the first dump and from a later one."""
import pandas as pd
import pytest

import coolgas
from conftest import tool


@pytest.mark.parametrize("run", ["gas", "disks", "rods"])
def test_equals_the_tool(run, request, tmp_path):
    path = request.getfixturevalue(run)
    frames = coolgas.open(path).frames
    for ref in (0, len(frames) // 2):
        out = tool("displacement", path, "--from", repr(frames[ref].t), "--exact-time").stdout
        (tmp_path / "cli.tsv").write_text(out)
        cli = pd.read_csv(tmp_path / "cli.tsv", sep="\t", comment="#", float_precision="round_trip")
        rows = [coolgas.displacement(frames[i], frames[ref]) for i in range(ref, len(frames))]
        py = pd.concat(rows, ignore_index=True)
        assert list(py.columns) == list(cli.columns)
        assert py.to_numpy().tobytes() == cli.to_numpy().tobytes()  # bit for bit


def test_refuses_what_is_not_a_frame_pair(gas, aggregates):
    frames = coolgas.open(gas).frames
    with pytest.raises(TypeError, match="Frame"):
        coolgas.displacement(frames[-1].positions, frames[0])
    with pytest.raises(coolgas.InputError, match="ballistic-aggregation"):
        ba = coolgas.open(aggregates).frames
        coolgas.displacement(ba[-1], ba[0])
