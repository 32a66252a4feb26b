"""Hostile input for the Python package, as a fuzz corpus (issue 52, classes
1, 2, 6, 8 and 9): kernels given arrays outside their box or not finite,
complex or boolean arrays, masses of the wrong length, negative or of 1e300,
non-positive slot counts, a NaN time; files whose box/dimension is an array,
a string or 2.5, or whose box group's header is damaged. Each case runs in a
child interpreter, so an abort or a segfault fails its case instead of
killing the test run; each must raise coolgas.InputError (a ValueError) with
one line naming the argument or the file, and return nothing."""
import os
import random
import shutil
import subprocess
import sys

import numpy as np
import pytest

import coolgas

SETUP = """
import numpy as np, coolgas
rng = np.random.default_rng(52)
P = rng.uniform(0, 10, (300, 3))
V = rng.normal(size=(300, 3))
"""


def kernel_cases():
    """(what, code, a word the error line must hold), generated from a fixed seed."""
    rng = random.Random(52)
    huge = [f"{rng.choice([1, -1]) * 10.0 ** rng.randrange(20, 309):g}" for _ in range(3)]
    cases = [
        ("shape masses of 1e300", "coolgas.shape(P, 10.0, masses=np.full(5, 1e300))", "masses[0]"),
        ("shape masses of 0.5", "coolgas.shape(P, 10.0, masses=[3.0, 0.5])", "masses[1]"),
        ("clusters masses of 1e300", "coolgas.clusters(P, 10.0, masses=np.full(300, 1e300), slots=300)", "masses[0]"),
        ("clusters masses beyond the slots", "coolgas.clusters(P, 10.0, masses=np.full(300, 301.0), slots=300)",
         "masses[0]"),
        ("clusters masses of the wrong length", "coolgas.clusters(P, 10.0, masses=np.ones(7), slots=300)", "masses"),
        ("structure masses of the wrong length", "coolgas.structure(P, 10.0, masses=np.ones(299))", "masses"),
        ("structure masses negative", "coolgas.structure(P, 10.0, masses=-np.ones(300))", "masses[0]"),
        ("structure masses NaN", "coolgas.structure(P, 10.0, masses=np.full(300, np.nan))", "masses[0]"),
        ("clusters slots 0", "coolgas.clusters(P, 10.0, masses=np.ones(300), slots=0)", "slots"),
        ("clusters slots -5", "coolgas.clusters(P, 10.0, masses=np.ones(300), slots=-5)", "slots"),
        ("positions beyond L", "coolgas.clusters(P + 10, 10.0)", "positions["),
        ("positions negative", "coolgas.label_clusters(P - 5, 10.0)", "positions["),
        ("L smaller than the data", "coolgas.shape(P, 5.0)", "positions["),
        ("L NaN", "coolgas.structure(P, float('nan'))", "L = nan"),
        ("L negative", "coolgas.clusters(P, -10.0)", "L = -10"),
        ("L inf", "coolgas.label_clusters(P, float('inf'))", "L = inf"),
        ("positions NaN", "coolgas.velocity(np.where(V > 2, np.nan, V))", "velocities["),
        ("complex positions", "coolgas.clusters(P + 1j, 10.0)", "complex"),
        ("complex velocities", "coolgas.velocity(V + 0j)", "complex"),
        ("complex velocities of a structure", "coolgas.structure(P, 10.0, table='series', velocities=V + 1j)",
         "complex"),
        ("complex masses", "coolgas.shape(P, 10.0, masses=np.ones(3) + 1j)", "complex"),
        ("boolean positions", "coolgas.clusters(P > 5, 10.0)", "bool"),
        ("string positions", "coolgas.shape(np.array([['1', '2', '3']]), 10.0)", "dtype"),
        ("t NaN", "coolgas.clusters(P, 10.0, t=float('nan'))", "t = nan"),
        ("velocities of 1e300", "coolgas.velocity(np.full((300, 3), 1e300), table='series')", "1e+300"),
        ("collapse of a complex E", "t = np.geomspace(1, 100, 20); coolgas.collapse([(10, t, t ** -1.2 + 0j), "
                                    "(20, t, t ** -1.2)], theta=1.2, z=2.5)", "complex"),
        ("smoluchowski from complex counts", "import pandas as pd; coolgas.smoluchowski(kernel='constant', t_end=1, "
                                             "initial=pd.DataFrame({'m': [1, 2], 'N': [10 + 1j, 5]}))", "complex"),
    ]
    for k, x in enumerate(huge):
        cases.append((f"positions of {x}", f"coolgas.structure(np.full((300, 3), {x}), 10.0)", "positions[0, 0]"))
        cases.append((f"shape masses of {x}", f"coolgas.shape(P, 10.0, masses=[2.0, {x}])", "masses"))
    for k in range(6):  # one coordinate of a random particle pushed out of the box
        i, j = rng.randrange(300), rng.randrange(3)
        x = rng.choice([-1e-9, 10.0, 10.5, -3.0, 1e20])
        kernel = rng.choice(["clusters", "shape", "structure", "label_clusters"])
        cases.append((f"{kernel} with P[{i}, {j}] = {x}", f"Q = P.copy(); Q[{i}, {j}] = {x}; coolgas.{kernel}(Q, 10.0)",
                      f"positions[{i}, {j}]"))
    return cases


def run_child(code, memory=None):
    """Runs code after SETUP in a child python (its address space limited to
    `memory` bytes when given); returns (exit code, last stdout line, stderr)."""
    wrapped = SETUP + "try:\n    " + code.replace("\n", "\n    ") + "\n    print('RETURNED')\n" + \
        "except coolgas.InputError as e:\n    print('InputError: ' + str(e))\n" + \
        "except Exception as e:\n    print(type(e).__name__ + ': ' + str(e))\n"
    def limit():
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
    r = subprocess.run([sys.executable, "-c", wrapped], capture_output=True, text=True, timeout=120,
                       env=dict(os.environ), preexec_fn=limit if memory else None)
    lines = r.stdout.strip().splitlines()
    return r.returncode, lines[-1] if lines else "", r.stderr


@pytest.mark.parametrize("what,code,named", kernel_cases(), ids=[c[0] for c in kernel_cases()])
def test_a_kernel_refuses_in_one_line(what, code, named):
    code_, line, err = run_child(code)
    assert code_ == 0, f"the interpreter died (exit {code_}): {err[-300:]}"
    assert line.startswith("InputError: "), line
    assert named in line and "\n" not in line and len(line) < 260, line


def test_integer_arrays_are_converted():
    P = np.random.default_rng(1).uniform(0, 10, (300, 3))
    assert coolgas.clusters(P.astype(np.int64), 10.0).equals(coolgas.clusters(np.floor(P), 10.0))


def test_a_nan_time_is_refused_by_frames_at(gas):
    with pytest.raises(coolgas.InputError, match="not a finite number"):
        coolgas.open(gas).frames.at(float("nan"))


def damaged_files(good, folder):
    """(what, path) copies of a good run with its box's dimension or header damaged."""
    import h5py
    out = []

    def copy(name):
        path = os.path.join(folder, name + ".h5")
        shutil.copy(good, path)
        return path

    for name, value in [("dimension_array", np.array([2, 2])), ("dimension_string", "3"),
                        ("dimension_2.5", 2.5), ("dimension_0", np.int64(0))]:
        path = copy(name)
        with h5py.File(path, "r+") as f:
            del f["particles/all/box"].attrs["dimension"]
            f["particles/all/box"].attrs["dimension"] = value
        out.append((name, path))
    path = copy("box_header")
    with h5py.File(path, "r") as f:
        at = h5py.h5o.get_info(f["particles/all/box"].id).addr
    data = bytearray(open(path, "rb").read())
    data[at:at + 4] = b"\xff" * 4
    open(path, "wb").write(data)
    out.append(("box_header", path))
    return out


def test_a_damaged_file_is_refused_naming_it(gas, tmp_path):
    for what, path in damaged_files(gas, str(tmp_path)):
        code, line, err = run_child(f"coolgas.open({path!r}).frames[0]")
        assert code == 0, f"{what}: the interpreter died (exit {code}): {err[-300:]}"
        assert line.startswith("InputError: ") and os.path.basename(path) in line, f"{what}: {line}"
        assert "dimension" in line or "damaged" in line, f"{what}: {line}"


# Issue 52, class 5: giant requests once ended in MemoryError (or the
# kernel's out-of-memory killer). Each is refused in one line before
# anything is allocated, naming the option and the limit; the child's address
# space is limited to 3 GB (ulimit -v), so the memory available is the same
# on every machine (common/memory.h, usable_memory_bytes).
GIANT = [
    ("structure of a box of 3e4", "coolgas.structure(P, 3e4)",
     "--grid 1024 (the default for L = 30000) would need 12.9 GB"),
    ("structure on a grid of 1024", "coolgas.structure(P, 10.0, grid=1024)", "--grid at most"),
    ("smoluchowski M = 1e8", "coolgas.smoluchowski(kernel='ballistic', M=10**8, t_end=1)",
     "cut-off mass --M 100000000 would need"),
    ("smoluchowski from a mass of 1e15", "import pandas as pd; coolgas.smoluchowski(kernel='constant', t_end=1, "
     "initial=pd.DataFrame({'m': [1, 1e15], 'N': [10, 5]}))", "holds mass 1e+15 above the cut-off M = 16384"),
]


@pytest.mark.parametrize("what,code,named", GIANT, ids=[c[0] for c in GIANT])
def test_a_giant_request_is_refused_before_allocating(what, code, named):
    code_, line, err = run_child(code, memory=3 * 2**30)
    assert code_ == 0, f"the interpreter died (exit {code_}): {err[-300:]}"
    assert line.startswith("InputError: "), line
    assert named in line and "\n" not in line and len(line) < 260, line
