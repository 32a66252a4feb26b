"""The notebook pipelines/notebooks/first_look.ipynb: its plain-script twin
runs to the end (simulating, reading, labelling, drawing, and its check of
Haff's law), and the notebook holds exactly the script's cells."""
import json
import os
import re
import subprocess
import sys

import coolgas

HERE = os.path.dirname(os.path.abspath(__file__))
NOTEBOOKS = os.path.join(HERE, "..", "..", "pipelines", "notebooks")


def script_cells():
    src = open(os.path.join(NOTEBOOKS, "first_look.py"), encoding="utf-8").read()
    parts = re.split(r"^# %%(.*)$", src, flags=re.M)
    return [(m.strip() or "code", body.strip("\n")) for m, body in zip(parts[1::2], parts[2::2])]


def test_the_notebook_holds_the_scripts_cells():
    nb = json.load(open(os.path.join(NOTEBOOKS, "first_look.ipynb"), encoding="utf-8"))
    code = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"]
    assert code == [body for kind, body in script_cells() if kind == "code"]
    assert len(nb["cells"]) == len(script_cells())


def test_the_script_twin_runs(tmp_path):
    out = tmp_path / "out"
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(coolgas.__file__)))  # this build's package
    r = subprocess.run([sys.executable, os.path.join(NOTEBOOKS, "first_look.py"), str(out)], capture_output=True,
                       text=True, cwd=tmp_path, timeout=240, env=env)
    assert r.returncode == 0, r.stderr[-2000:]
    assert "Haff's law" in r.stdout
    for png in ("energy.png", "cluster_sizes.png", "velocity.png"):
        assert (out / png).stat().st_size > 10000, png
