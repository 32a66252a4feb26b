"""The notebook itself, executed headless as a user would run it:
jupyter-nbconvert --execute (Debian's jupyter-nbconvert and python3-ipykernel,
in the Makefile's TEST_PACKAGES) runs every cell without an error, in a
scratch folder that receives its files, and ends with the check of Haff's law."""
import json
import os
import shutil
import subprocess

import pytest

import coolgas

NOTEBOOK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "pipelines", "notebooks",
                        "first_look.ipynb")


def test_the_notebook_executes(tmp_path):
    exe = shutil.which("jupyter-nbconvert", path="/usr/bin:/bin")
    if exe is None:
        pytest.fail("jupyter-nbconvert is missing: `make test-deps` installs the test packages "
                    "(jupyter-nbconvert, python3-ipykernel)")
    shutil.copy(NOTEBOOK, tmp_path)  # the kernel starts in the notebook's folder and writes its outputs there
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(coolgas.__file__)),  # this build's package
               PYDEVD_DISABLE_FILE_VALIDATION="1")
    r = subprocess.run([exe, "--to", "notebook", "--execute", "--ExecutePreprocessor.timeout=200", "--output-dir",
                        str(tmp_path / "executed"), str(tmp_path / "first_look.ipynb")], capture_output=True,
                       text=True, cwd=tmp_path, timeout=280, env=env)
    assert r.returncode == 0, r.stderr[-3000:]
    nb = json.load(open(tmp_path / "executed" / "first_look.ipynb", encoding="utf-8"))
    outputs = [o for c in nb["cells"] if c["cell_type"] == "code" for o in c["outputs"]]
    assert not [o for o in outputs if o["output_type"] == "error"]
    text = "".join("".join(o.get("text", "")) for o in outputs if o["output_type"] == "stream")
    assert "coolgas " + coolgas.__version__ in text and "Haff's law" in text
    assert (tmp_path / "first-look" / "energy.png").stat().st_size > 10000
