"""The package: its version is the tools', it installs where Debian's python3
finds it, and a bad argument is a Python exception, never a crash."""
import os
import subprocess
import sys

import numpy as np
import pytest

import coolgas
from conftest import BIN, tool


@pytest.mark.parametrize("name", ["simulate", "clusters", "velocity", "energy", "structure", "shape", "collapse",
                                  "smoluchowski"])
def test_version_is_the_tools(name):
    assert tool(name, "--version").stdout.strip() == f"coolgas-{name} {coolgas.__version__}"


def test_install_puts_the_package_where_python_finds_it(tmp_path):
    build = os.environ["COOLGAS_BUILD_DIR"]
    install = subprocess.run(["cmake", "--install", build, "--prefix", tmp_path], check=True, capture_output=True,
                             text=True)
    site = tmp_path / "lib" / f"python3.{sys.version_info.minor}" / "dist-packages"
    # the install's last line says where the package went and how this python finds it
    assert install.stdout.strip().splitlines()[-1] == \
        f"-- coolgas: the Python package is in {site}/coolgas; {sys.executable} finds it with PYTHONPATH={site}"
    script = ("import coolgas, coolgas._simulate as s; print(coolgas.__file__); print(coolgas.__version__); "
              "print(s._executable())")
    env = {"PYTHONPATH": str(site), "PATH": "/usr/bin:/bin"}
    out = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, check=True)
    file, version, exe = out.stdout.splitlines()
    assert file.startswith(str(site))
    assert version == coolgas.__version__
    assert exe == str(tmp_path / "bin" / "coolgas-simulate")  # the installed tool, not the build tree's


def test_another_python_is_told_which_to_use(tmp_path):
    # An interpreter without numpy and pandas: this one, under another name and without site-packages (-S).
    other = tmp_path / "python3"
    other.symlink_to(sys.executable)
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(coolgas.__file__)))
    r = subprocess.run([str(other), "-S", "-c", "import coolgas"], env=env, capture_output=True, text=True)
    assert r.returncode == 1
    last = r.stderr.strip().splitlines()[-1]
    assert last == (f"ImportError: coolgas runs under {sys.executable} (Python 3.{sys.version_info.minor} with numpy "
                    f"and pandas), the Python it was built for, not {other} (Python {sys.version.split()[0]}), where "
                    f"numpy cannot be imported: run {sys.executable}"), r.stderr
    assert "pandas/" not in r.stderr and "numpy/" not in r.stderr  # no traceback from inside them
    # the same interpreter without them: install them
    r = subprocess.run([sys.executable, "-S", "-c", "import coolgas"], env=env, capture_output=True, text=True)
    assert r.stderr.strip().splitlines()[-1] == (
        f"ImportError: coolgas needs numpy and pandas in {sys.executable}, the Python it was built for, where numpy "
        "cannot be imported (Debian: apt-get install python3-numpy python3-pandas)"), r.stderr


def test_missing_file_is_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError):
        coolgas.open(tmp_path / "absent.h5")
    with pytest.raises(FileNotFoundError):
        coolgas.read_table(tmp_path / "absent.tsv")


def test_a_file_that_is_not_hdf5_is_an_input_error(tmp_path):
    bad = tmp_path / "bad.h5"
    bad.write_text("not hdf5\n")
    with pytest.raises(coolgas.InputError, match="not HDF5"):
        coolgas.open(bad).frames


def test_wrong_argument_types_raise():
    with pytest.raises(TypeError):
        coolgas.label_clusters("positions", 10.0)
    with pytest.raises(coolgas.InputError, match=r"shape \(N, 3\), or \(N, 2\) for disks"):
        coolgas.label_clusters(np.zeros((4, 4)), 10.0)
    with pytest.raises(coolgas.InputError, match=r"positions\[1, 2\] = nan is not a finite number"):
        coolgas.label_clusters([[1, 1, 1], [2, 2, np.nan]], 10.0)
    with pytest.raises(coolgas.InputError, match="L"):
        coolgas.label_clusters([[1, 1, 1]], 0.5)  # the tool's own message for a box below one cell
    with pytest.raises(coolgas.InputError, match="allowed: distribution, scaled, series"):
        coolgas.clusters([[1, 1, 1]], L=10, table="histogram")


def test_the_readmes_example_runs(tmp_path, monkeypatch):
    """The README's Python example, as written (in a scratch folder)."""
    readme = open(os.path.join(os.path.dirname(__file__), "..", "..", "README.md"), encoding="utf-8").read()
    section = readme[readme.index("## Python"):]
    code = section[section.index("```python\n") + 10:section.index("```", section.index("```python\n") + 10)]
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})
    assert coolgas.open(tmp_path / "gas.h5").frames[-1].t == 100
