"""coolgas.simulate: a scene given as a dict gives the file the CLI gives;
a bad scene raises the tool's own error line; Ctrl-C (SIGINT) leaves a
checkpoint and a clear exception, and resume=True then ends on the
uninterrupted run's trajectory, bit for bit; the progress lines are relayed."""
import os
import signal
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import coolgas
from conftest import GAS, HANG_S, tool, wait_for_point, waiting_at

SCENE = {"system": {"L": 16, "phi": 0.208, "seed": 7},
         "collision": {"model": "inelastic", "r0": 0.1, "delta": 1e-4},
         "run": {"t_end": 300}, "output": {"dumps_per_decade": 3}}


def same_frames(a, b):
    fa, fb = coolgas.open(a).frames, coolgas.open(b).frames
    assert len(fa) == len(fb)
    for i in range(len(fa)):
        assert fa[i].t == fb[i].t
        assert fa[i].positions.tobytes() == fb[i].positions.tobytes()
        assert fa[i].velocities.tobytes() == fb[i].velocities.tobytes()


def test_a_dict_scene_runs_as_the_cli_runs_its_file(gas, tmp_path):
    run = coolgas.simulate(SCENE, output=tmp_path / "py.h5", progress=False)
    assert isinstance(run, coolgas.Run)
    same_frames(run.path, gas)  # conftest's gas is the same scene, run by the CLI
    assert coolgas.open(gas).parameters["scene_dict"] == run.parameters["scene_dict"]


def test_toml_text_and_set_overrides(tmp_path):
    run = coolgas.simulate(GAS, output=tmp_path / "t.h5", set={"run.t_end": 5.0}, progress=False)
    assert run.frames[-1].t == 5.0


def test_a_bad_scene_raises_the_tools_line(tmp_path):
    bad = dict(SCENE, system={"L": 16, "phi": 0.9, "seed": 7})
    scene = tmp_path / "bad.toml"
    scene.write_text(coolgas._simulate.scene_toml(bad))
    cli = tool("simulate", scene, "-o", tmp_path / "cli.h5", check=False)
    assert cli.returncode == 2
    with pytest.raises(coolgas.InputError) as e:
        coolgas.simulate(bad, output=tmp_path / "py.h5", progress=False)
    assert str(e.value) == cli.stderr.strip()
    # phi is the one of the N the box holds, 0.9 to a few digits
    assert "system.phi = 0.900" in str(e.value) and "is out of range" in str(e.value)
    with pytest.raises(TypeError, match="allowed: bool, int, float, str, list"):
        coolgas.simulate({"system": {"L": {1, 2}}}, output=tmp_path / "x.h5")


def test_sigint_checkpoints_and_resume_is_bit_identical(tmp_path):
    scene = {"system": {"N": 50000, "phi": 0.25, "seed": 11},
             "collision": {"model": "inelastic", "r0": 0.5, "delta": 1e-4},
             "run": {"t_end": 3000}, "output": {"dumps_per_decade": 4}}
    out = tmp_path / "stopped.h5"
    # The Python that runs it, as a user's script: Ctrl-C is a SIGINT to it alone.
    script = textwrap.dedent(f"""
        import coolgas
        try:
            coolgas.simulate({scene!r}, output={str(out)!r})
        except coolgas.SimulationInterrupted as e:
            print("INTERRUPTED", e.output, e)
    """)
    # The run waits after 10 events per particle (past its first dumps and
    # checkpoint) for the Ctrl-C: a named point, the same on every machine.
    ready = tmp_path / "ready"
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=waiting_at("events:500000", ready))
    wait_for_point(ready, proc)
    proc.send_signal(signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=HANG_S)
    assert proc.returncode == 0, stderr
    assert stdout.startswith("INTERRUPTED " + str(out)), stdout
    assert "SIGINT" in stdout and "resume=True" in stdout
    assert "set-up (" in stderr  # the tool's progress lines, relayed (its run's come every 0.5 s of wall time)
    stopped_at = coolgas.open(out).frames[-1].t
    assert stopped_at < 3000
    run = coolgas.simulate(output=out, resume=True, progress=False)
    assert run.frames[-1].t == 3000
    ref = tmp_path / "ref.h5"
    coolgas.simulate(scene, output=ref, progress=False)
    same_frames(out, ref)
