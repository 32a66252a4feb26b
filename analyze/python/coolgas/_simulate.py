"""Running coolgas-simulate from Python.

The simulator runs as the installed executable, not in-process: the engine
stays a program of its own (its libraries are not in the module), a run
survives a restart of the Python kernel, its SIGINT handling and exit codes
are the tool's own, and a crash cannot take the interpreter down. The tool
writes its progress line only to a terminal, so its stderr is a
pseudo-terminal whose lines are relayed here."""
import math
import os
import pty
import select
import shutil
import signal
import subprocess
import sys
import tempfile

from . import __version__
from ._core import InputError
from ._run import Run

TOOL = "coolgas-simulate"


class SimulationError(RuntimeError):
    """The run stopped on its own: exit code 4 (inelastic collapse), 5 (a
    write failed) or 1 (a bug); the message is the tool's error line."""

    def __init__(self, message, returncode):
        super().__init__(message)
        self.returncode = returncode


class SimulationInterrupted(KeyboardInterrupt):
    """Ctrl-C: the run got SIGINT, wrote its checkpoint and stopped (exit
    code 3); coolgas.simulate(output=..., resume=True) continues it."""

    def __init__(self, message, output):
        super().__init__(message)
        self.output = output


def _executable(explicit=None):
    """coolgas-simulate of this package's build or installation: the bin/
    beside the build tree's python/ or beside the prefix's lib/, else PATH."""
    if explicit:
        return explicit
    here = os.path.dirname(os.path.abspath(__file__))
    for rel in (("..", "..", "bin"), ("..", "..", "..", "..", "bin")):
        candidate = os.path.normpath(os.path.join(here, *rel, TOOL))
        if os.access(candidate, os.X_OK):
            return candidate
    found = shutil.which(TOOL)
    if not found:
        raise FileNotFoundError(2, f"{TOOL} not found beside the package nor on PATH", TOOL)
    return found


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)  # the shortest text that reads back to the same double
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if hasattr(v, "item"):  # numpy scalars
        return _toml_value(v.item())
    raise TypeError(f"scene value {v!r} is a {type(v).__name__}; allowed: bool, int, float, str, list")


def scene_toml(scene):
    """TOML text of a scene dict {table: {key: value}} (the shape of a scene file)."""
    lines = []
    for table, keys in scene.items():
        if not isinstance(keys, dict):
            raise TypeError(f"scene[{table!r}] must be a table (a dict of keys), got {type(keys).__name__}")
        lines.append(f"[{table}]")
        lines += [f"{k} = {_toml_value(v)}" for k, v in keys.items()]
        lines.append("")
    return "\n".join(lines)


def _error_line(text):
    """The tool's last error line in what it wrote to stderr."""
    lines = [ln.strip() for ln in text.replace("\r", "\n").split("\n") if ln.strip()]
    errors = [ln for ln in lines if ln.startswith(TOOL + ":")]
    return errors[-1] if errors else (lines[-1] if lines else "")


def simulate(scene=None, output=None, resume=False, set=None, force=False, progress=True, executable=None):  # noqa: A002
    """Runs coolgas-simulate and returns the run (coolgas.open(output)).

    scene: a dict {"system": {...}, "collision": {...}, ...}, TOML text, or
    the path of a scene file; not needed with resume=True. output: the
    trajectory file. resume: continue `output` from its checkpoint (set may
    then extend run.t_end). set: {"run.t_end": 1e4, ...}, the tool's --set.
    progress: relay the tool's progress line to stderr.

    A bad scene raises coolgas.InputError with the tool's one error line;
    Ctrl-C sends the run SIGINT, waits for its checkpoint and raises
    SimulationInterrupted; exit codes 1, 4, 5 raise SimulationError."""
    exe = _executable(executable)
    if output is None:
        raise TypeError("output (the trajectory file to write) is required")
    output = os.fspath(output)
    args = [exe]
    scene_file = None
    if resume:
        if scene is not None:
            raise TypeError("resume=True continues output with its own scene; give no scene (set= may extend run.t_end)")
        args += ["--resume", output]
    else:
        if scene is None:
            raise TypeError("scene (a dict, TOML text or a file path) is required unless resume=True")
        if isinstance(scene, dict):
            text = scene_toml(scene)
        elif isinstance(scene, os.PathLike) or (isinstance(scene, str) and "\n" not in scene and "=" not in scene):
            text = None
            args.append(os.fspath(scene))
        elif isinstance(scene, str):
            text = scene
        else:
            raise TypeError(f"scene must be a dict, TOML text or a path, got {type(scene).__name__}")
        if text is not None:
            fd, scene_file = tempfile.mkstemp(suffix=".toml", prefix="coolgas-scene-")
            with os.fdopen(fd, "w") as fh:
                fh.write(text)
            args.append(scene_file)
        args += ["-o", output]
        if force:
            args.append("--force")
    for key, value in (set or {}).items():
        args += ["--set", f"{key}={_toml_value(value)}"]
    if not progress:
        args.append("--quiet")
    try:
        code, err = _run(args, progress)
    finally:
        if scene_file:
            os.unlink(scene_file)
    if code == 0:
        return Run(output)
    line = _error_line(err)
    if code == 2:
        raise InputError(line)
    if code == 3:
        raise SimulationInterrupted(line + f" (continue with coolgas.simulate(output={output!r}, resume=True))", output)
    raise SimulationError(line or f"{TOOL} exited with code {code}", code)


def _run(args, progress):
    """Runs the tool with its stderr on a pseudo-terminal: (exit code, stderr text)."""
    master, slave = pty.openpty()
    # Its own session: a Ctrl-C at the terminal reaches Python only, which
    # passes exactly one SIGINT on (a second one would not change anything,
    # but the child must not see the terminal's before Python knows).
    proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=slave,
                            start_new_session=True)
    os.close(slave)
    chunks = []
    shown = False
    interrupted = False
    try:
        while True:
            try:
                ready, _, _ = select.select([master], [], [], 0.2)
                if ready:
                    data = os.read(master, 4096)
                    if not data:
                        break
                    text = data.decode("utf-8", "replace")
                    chunks.append(text)
                    if progress:
                        sys.stderr.write(text.replace("\r\n", "\n"))
                        sys.stderr.flush()
                        shown = True
                elif proc.poll() is not None:
                    break
            except OSError:  # EIO: the tool has closed its end
                break
            except KeyboardInterrupt:
                if interrupted:
                    raise
                interrupted = True
                proc.send_signal(signal.SIGINT)
        code = proc.wait()
    except BaseException:
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            proc.wait()
        raise
    finally:
        os.close(master)
    if shown:
        sys.stderr.write("\n")
    return code, "".join(chunks)
