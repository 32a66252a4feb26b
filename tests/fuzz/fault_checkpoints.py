#!/usr/bin/python3
"""Faults that once crashed or hung coolgas (issue 41), as a corpus run by ctest.

Generated from a fixed seed (the same corpus on every run); each case has a
time limit, so a hang fails too:
  crafted   checkpoints of three models with one field made out of range or
            not finite (issue 52: an own time of -1e300, which hung at 100 %
            CPU) and the hash made to match again: --resume exits 2
            with one line naming the checkpoint, and the trajectory stays
            valid (coolgas-validate);
  collapse  r0 <= 1e-13 with delta = 1e-4 at N = 500 (time stuck at one
            value while collisions go on) and with delta = 0: exit 4, the
            stuck state written as the last dump;
  full      a checkpoint whose write meets a full device (/dev/full): exit 5,
            one line, the previous checkpoint kept byte for byte, the
            trajectory valid;
  overlap   an aggregation trajectory with two aggregates of its last dump
            made to overlap: coolgas-validate names them (exit 2);
  signal    10^5 output.dump_times (refused, naming that key) and
            coolgas-clusters with 10^9 bins per decade, each also with
            SIGTERM pending as it starts (no timing): ends within the limit
            (no loop deaf to signals), with exit code 3 for the signal.

usage: fault_checkpoints.py BIN_DIR WORK_DIR
"""
import os
import random
import shutil
import struct
import subprocess
import sys
import time

from fuzz_cli import pending

TIMEOUT_S = 30
MAGIC_BYTES = 24  # magic, version, byte-order mark
TRAILER = b"end\0\0\0\0\0"
FNV_OFFSET, FNV_PRIME = 14695981039346656037, 1099511628211

SCENES = {
    "inelastic": {"system.N": "300", "system.phi": "0.1", "system.seed": "4", "collision.model": '"inelastic"',
                  "collision.r0": "0.6", "collision.delta": "1e-4", "run.t_end": "3"},
    "elastic": {"system.N": "300", "system.phi": "0.2", "system.seed": "5", "run.t_end": "2"},
    "aggregation": {"system.N": "400", "system.phi": "0.1", "system.seed": "6", "collision.model": '"aggregation"',
                    "run.t_end": "2"},
}


def toml(kv):
    tables = {}
    for key, value in kv.items():
        table, name = key.split(".")
        tables.setdefault(table, []).append(f"{name} = {value}")
    return "".join(f"[{t}]\n" + "\n".join(lines) + "\n" for t, lines in tables.items())


def fnv1a(data):
    h = FNV_OFFSET
    for b in data:
        h = ((h ^ b) * FNV_PRIME) & 0xFFFFFFFFFFFFFFFF
    return h


class Checkpoint:
    """A checkpoint's sections (data-schema/checkpoint.md), editable in place."""

    def __init__(self, data):
        self.data = bytearray(data)
        self.sections = {}
        at = MAGIC_BYTES
        while self.data[at:at + 8] != TRAILER:
            (n,) = struct.unpack_from("<I", self.data, at)
            name = self.data[at + 4:at + 4 + n].decode()
            size, count = struct.unpack_from("<QQ", self.data, at + 4 + n)
            at += 4 + n + 16
            self.sections[name] = (at, size, count)
            at += size * count
        self.end = at

    def count(self, name):
        return self.sections[name][2]

    def get(self, name, index, offset, fmt):
        at, size, _ = self.sections[name]
        return struct.unpack_from("<" + fmt, self.data, at + index * size + offset)[0]

    def put(self, name, index, offset, fmt, value):
        at, size, count = self.sections[name]
        assert index < count, (name, index, count)
        struct.pack_into("<" + fmt, self.data, at + index * size + offset, value)

    def sealed(self):
        """The bytes with the hash made to match the edited contents."""
        out = bytearray(self.data)
        struct.pack_into("<Q", out, self.end + 8, fnv1a(out[:self.end]))
        return bytes(out)


NAN, INF = float("nan"), float("inf")


def engine_mutations(ck, rng, prefix):
    """(description, edit) pairs for an engine's checkpoint, each out of range by construction."""
    n = ck.count(prefix + "motion")
    cells = ck.count(prefix + "grid/heads")
    listed = [i for i in range(n) if ck.get(prefix + "grid/cell", i, 0, "i") >= 0]
    i, j = rng.choice(listed), rng.randrange(n)
    heap = ck.count(prefix + "calendar/heap")
    m = [
        ("position NaN", lambda: ck.put(prefix + "motion", i, 8 * rng.randrange(3), "d", NAN)),
        ("position far outside its cell", lambda: ck.put(prefix + "motion", i, 0, "d", 1e300)),
        ("velocity inf", lambda: ck.put(prefix + "motion", i, 24 + 8 * rng.randrange(3), "d", INF)),
        ("own time after now", lambda: ck.put(prefix + "motion", i, 48, "d", 1e9)),
        # issue 52: moving a particle to now wrapped 1e300 one box side at a time, for ever
        ("own time -1e300", lambda: ck.put(prefix + "motion", i, 48, "d", -1e300)),
        ("own time negative", lambda: ck.put(prefix + "motion", i, 48, "d", -rng.uniform(1e-3, 10))),
        ("velocity 1e150 (beyond the box by now)",
         lambda: (ck.put(prefix + "motion", i, 24 + 8 * rng.randrange(3), "d", 1e150),
                  ck.put(prefix + "motion", i, 48, "d", 0.0))),
        ("time 1e300", lambda: ck.put(prefix + "scalars", 0, 8, "d", 1e300)),
        ("last dump NaN", lambda: ck.put("run/last_dump", 0, 0, "d", NAN)),
        ("last dump -1e300", lambda: ck.put("run/last_dump", 0, 0, "d", -1e300)),
        ("last dump after now", lambda: ck.put("run/last_dump", 0, 0, "d", 1e300)),
        ("cell link beyond N", lambda: ck.put(prefix + "motion", i, 60, "i", n + rng.randrange(1, 1 << 20))),
        ("cell link negative", lambda: ck.put(prefix + "motion", i, 60, "i", -rng.randrange(2, 1 << 20))),
        ("cell head beyond N", lambda: ck.put(prefix + "grid/heads", rng.randrange(cells), 0, "i", n + 3)),
        ("particle's cell out of range", lambda: ck.put(prefix + "grid/cell", i, 0, "i", cells + rng.randrange(9))),
        ("calendar place out of range", lambda: ck.put(prefix + "calendar/entries", j, 24, "i", 1 << 29)),
        ("calendar link beyond N", lambda: ck.put(prefix + "calendar/entries", j, 16, "i", n + 11)),
        ("event partner beyond N", lambda: ck.put(prefix + "calendar/entries", j, 12, "i", n + 100)),
        ("event time NaN", lambda: ck.put(prefix + "calendar/entries", j, 0, "d", NAN)),
        ("calendar bucket count", lambda: ck.put(prefix + "calendar/scalars", 0, 32, "i", 1 << 30)),
        ("calendar width NaN", lambda: ck.put(prefix + "calendar/scalars", 0, 8, "d", NAN)),
        ("box side NaN", lambda: ck.put(prefix + "scalars", 0, 0, "d", NAN)),
        ("box side huge", lambda: ck.put(prefix + "scalars", 0, 0, "d", 1e7)),
        ("time NaN", lambda: ck.put(prefix + "scalars", 0, 8, "d", NAN)),
    ]
    if heap:
        m.append(("heap index beyond N", lambda: ck.put(prefix + "calendar/heap", rng.randrange(heap), 0, "i", n + 5)))
    if prefix == "engine/":
        k = rng.randrange(1, n)
        m += [
            ("duplicate id", lambda: ck.put("engine/id", k, 0, "i", ck.get("engine/id", k - 1, 0, "i"))),
            ("id beyond N", lambda: ck.put("engine/id", k, 0, "i", n + 7)),
            ("kept event partner beyond N", lambda: ck.put("engine/later", k, 12, "i", n + 9)),
            ("negative counter", lambda: ck.put("engine/scalars", 0, 24, "q", -5)),
        ]
    else:
        present = [s for s in range(n) if ck.get("aggregation/id", s, 0, "i") >= 0]
        s = rng.choice(present)
        m += [
            ("diameter NaN", lambda: ck.put("aggregation/diameter", s, 0, "d", NAN)),
            ("mass negative", lambda: ck.put("aggregation/mass", s, 0, "d", -1.0)),
            ("id below -1", lambda: ck.put("aggregation/id", s, 0, "i", -3)),
            ("aggregate count off by one", lambda: ck.put("aggregation/scalars", 0, 32, "q",
                                                          ck.get("aggregation/scalars", 0, 32, "q") + 1)),
            ("large-index cell out of range", lambda: ck.put("aggregation/large_cell", s, 0, "i", cells + 4)),
        ]
    return m


def run(cmd, env=None, pending_signal=None):
    """Runs cmd, with `pending_signal` ("TERM") blocked and sent before it
    starts if given (fuzz_cli.pending); returns (exit code, stdout, stderr,
    seconds), or None for the code on the time limit."""
    start = time.monotonic()
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                         preexec_fn=pending(pending_signal) if pending_signal else None)
    try:
        out, err = p.communicate(timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:  # a hang: a failed case, and the corpus goes on
        p.kill()
        p.communicate()
        return None, "", f"no end within {TIMEOUT_S} s", time.monotonic() - start
    return p.returncode, out.decode(errors="replace"), err.decode(errors="replace"), time.monotonic() - start


class Corpus:
    def __init__(self, bin_dir, work):
        self.bin, self.work, self.failures, self.cases = bin_dir, work, [], 0

    def exe(self, name):
        return os.path.join(self.bin, name)

    def check(self, name, ok, detail):
        self.cases += 1
        if not ok:
            self.failures.append(f"{name}: {detail}")

    def one_line_error(self, err):
        lines = err.strip("\n").split("\n")
        return len(lines) == 1 and "error" in lines[0]

    def valid(self, path):
        code, out, err, _ = run([self.exe("coolgas-validate"), path])
        return code == 0, err.strip()

    def start_run(self, model):
        d = os.path.join(self.work, "runs", model)
        os.makedirs(d, exist_ok=True)
        scene = os.path.join(d, "scene.toml")
        with open(scene, "w") as f:
            f.write(toml(SCENES[model]))
        traj = os.path.join(d, "run.h5")
        code, _, err, _ = run([self.exe("coolgas-simulate"), scene, "-o", traj, "--force", "-q"])
        assert code == 0, f"the {model} run to craft checkpoints from failed: {err}"
        return traj

    def crafted(self, rng):
        for model in SCENES:
            traj = self.start_run(model)
            with open(traj + ".checkpoint", "rb") as f:
                original = f.read()
            prefix = "aggregation/" if model == "aggregation" else "engine/"
            for index, (what, _) in enumerate(engine_mutations(Checkpoint(original), random.Random(0), prefix)):
                ck = Checkpoint(original)
                edit = engine_mutations(ck, random.Random(rng.randrange(1 << 30)), prefix)[index][1]
                edit()
                d = os.path.join(self.work, "crafted", f"{model}-{index}")
                os.makedirs(d, exist_ok=True)
                case = os.path.join(d, "run.h5")
                shutil.copyfile(traj, case)
                with open(case + ".checkpoint", "wb") as f:
                    f.write(ck.sealed())
                name = f"crafted {model}: {what}"
                code, out, err, _ = run([self.exe("coolgas-simulate"), "--resume", case, "--set", "run.t_end=4", "-q"])
                self.check(name, code == 2 and self.one_line_error(err) and ".checkpoint'" in err and not out,
                           f"exit {code}, stderr {err.strip()[:300]!r}")
                ok, why = self.valid(case)
                self.check(name + " (trajectory still valid)", ok, why)

    def collapse(self):
        base = {"system.N": "500", "system.phi": "0.1", "collision.model": '"inelastic"', "run.t_end": "1000"}
        for seed, r0, delta in [(1, "1e-13", "1e-4"), (2, "1e-14", "1e-4"), (3, "1e-13", "1e-4"), (1, "0.05", "0")]:
            d = os.path.join(self.work, "collapse", f"{seed}-{r0}-{delta}")
            os.makedirs(d, exist_ok=True)
            scene = os.path.join(d, "scene.toml")
            with open(scene, "w") as f:
                f.write(toml({**base, "system.seed": str(seed), "collision.r0": r0, "collision.delta": delta}))
            traj = os.path.join(d, "run.h5")
            code, _, err, secs = run([self.exe("coolgas-simulate"), scene, "-o", traj, "--force", "-q"])
            name = f"collapse seed {seed} r0 {r0} delta {delta}"
            self.check(name, code == 4 and "inelastic collapse" in err,
                       f"exit {code} after {secs:.1f} s, stderr {err.strip()[:300]!r}")
            ok, why = self.valid(traj)
            self.check(name + " (trajectory valid)", ok, why)

    def full_device(self):
        traj = self.start_run("inelastic")
        d = os.path.join(self.work, "full")
        os.makedirs(d, exist_ok=True)
        case = os.path.join(d, "run.h5")
        for suffix in ("", ".checkpoint"):
            shutil.copyfile(traj + suffix, case + suffix)
        partial = case + ".checkpoint.partial"
        if os.path.lexists(partial):
            os.remove(partial)
        os.symlink("/dev/full", partial)  # the checkpoint's write meets a full device
        with open(case + ".checkpoint", "rb") as f:
            before = f.read()
        env = dict(os.environ, COOLGAS_CHECKPOINT_INTERVAL="0")
        code, out, err, _ = run([self.exe("coolgas-simulate"), "--resume", case, "--set", "run.t_end=6", "-q"], env)
        self.check("full device", code == 5 and self.one_line_error(err) and "No space left" in err,
                   f"exit {code}, stderr {err.strip()[:300]!r}")
        with open(case + ".checkpoint", "rb") as f:
            self.check("full device: previous checkpoint kept", f.read() == before, "the checkpoint changed")
        ok, why = self.valid(case)
        self.check("full device: trajectory valid", ok, why)

    def overlap(self):
        import h5py  # Debian's python3-h5py (the interpreter ctest runs)
        traj = self.start_run("aggregation")
        d = os.path.join(self.work, "overlap")
        os.makedirs(d, exist_ok=True)
        case = os.path.join(d, "run.h5")
        shutil.copyfile(traj, case)
        with h5py.File(case, "r+") as f:
            pos, ids = f["particles/all/position/value"], f["particles/all/id/value"]
            last = ids.shape[0] - 1
            present = [int(i) for i in (ids[last] >= 0).nonzero()[0]]
            r = pos[last]
            r[present[1]] = r[present[0]] + 0.25  # well inside contact (diameters >= 1)
            pos[last] = r
        code, out, _, _ = run([self.exe("coolgas-validate"), case])
        self.check("overlapping aggregates in the last dump", code == 2 and f"dump {last}" in out and "overlap" in out,
                   f"exit {code}, stdout {out.strip()[:300]!r}")
        ok, why = self.valid(traj)
        self.check("the aggregation run itself has no overlap", ok, why)

    def signals(self):
        d = os.path.join(self.work, "signal")
        os.makedirs(d, exist_ok=True)
        scene = os.path.join(d, "many.toml")
        times = ", ".join(str(1 + i % 97) for i in range(100000))
        with open(scene, "w") as f:
            f.write(toml({"system.N": "300", "system.phi": "0.1", "run.t_end": "200"}) +
                    f"[output]\ndump_times = [{times}]\n")
        # The scene is refused before the run first looks for a signal: exit 2 with or without one.
        for sig in (None, "TERM"):
            code, _, err, secs = run([self.exe("coolgas-simulate"), scene, "-o", os.path.join(d, "m.h5"), "--force",
                                      "-q"], pending_signal=sig)
            self.check(f"10^5 dump_times (SIG{sig} pending)",
                       code == 2 and "output.dump_times" in err and "dumps_per_decade" not in err,
                       f"exit {code} after {secs:.1f} s, stderr {err.strip()[:300]!r}")
        traj = self.start_run("inelastic")
        for sig, expected in ((None, 0), ("TERM", 3)):
            code, out, err, secs = run([self.exe("coolgas-clusters"), traj, "--bins-per-decade", "1000000000"],
                                       pending_signal=sig)
            self.check(f"clusters 10^9 bins per decade (SIG{sig} pending)", code == expected,
                       f"exit {code} after {secs:.1f} s, expected {expected}, stderr {err.strip()[:300]!r}")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    bin_dir, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    corpus = Corpus(bin_dir, work)
    rng = random.Random(41)
    corpus.crafted(rng)
    corpus.collapse()
    corpus.full_device()
    corpus.overlap()
    corpus.signals()
    for f in corpus.failures:
        print("FAIL", f)
    print(f"{corpus.cases - len(corpus.failures)} of {corpus.cases} fault cases passed")
    sys.exit(1 if corpus.failures else 0)


if __name__ == "__main__":
    main()
