#!/usr/bin/python3
"""Hostile input for every program, as a fuzz corpus run by ctest.

Generates several hundred cases from a fixed seed (the same corpus on every
run) and runs each:
  refused   scenes, --set values, output paths, tool arguments and corrupt
            files to resume: exit code 2, one line on stderr, nothing on
            stdout, no file written or changed;
  no space  every tool writing its table to /dev/full or a closed stdout:
            a non-zero exit code and one line naming stdout;
  pipe      every tool into a closed pipe (| head -c 1): nothing on stderr;
  write     an output file option (--series-file) on a full device: exit
            code 5 and one line naming that file;
  overflow  Smoluchowski kernels whose solution overflows: exit code 2, one
            line on stderr, no row of nan or inf on stdout;
  invalid   coolgas-validate on a damaged file: exit code 2, nothing on
            stderr, problem lines on stdout each naming the file;
  interrupted  a long loop started with SIGINT or SIGTERM pending (blocked
            in the child before exec, so the program records it as it
            starts watching: no timing): exit code 3, one line naming the
            signal and where the loop stopped, nothing on stdout.
A refused case may run with its address space limited (ulimit -v), so that
"the memory available" is the same on every machine; under the sanitizers,
which reserve terabytes of address space, those cases are left out.
A refused case that names a file (damaged metadata) must name it in its line.
Each case has a time limit: a hang is a failure too.

usage: fuzz_cli.py BIN_DIR WORK_DIR [--list]
"""
import concurrent.futures
import hashlib
import os
import random
import shutil
import subprocess
import sys

TIMEOUT_S = 20

BASE = {
    "system.N": "200",
    "system.phi": "0.1",
    "system.seed": "3",
    "collision.model": '"inelastic"',
    "collision.r0": "0.5",
    "collision.delta": "1e-4",
    "run.t_end": "2",
}

# Values refused for every key of the type (wrong types, not finite, absurd).
NOT_A_NUMBER = ['"12"', "true", "[1, 2]", "{ a = 1 }", "1979-05-27", '"x\\ny"']
NOT_FINITE = ["inf", "-inf", "nan", "+inf"]
# Values out of each key's range or absurd in what they imply.
BAD = {
    "system.N": ["0", "1", "-5", "1e12", "1.5", "1e30", "9223372036854775807", "4294967297", "2.5e9"],
    "system.phi": ["0", "-0.1", "0.4", "0.75", "1", "1e-308", "1e300", "5e-324"],
    "system.seed": ["1.5", "1e30"],
    "system.init": ['"lattice"', '""', '"random "', '"' + "r" * 10000 + '"', '"ran\\u0000dom"', "1"],
    "system.equilibrate": ["-1", "1e300", "1e20", "-1e-300"],
    "collision.model": ['"sticky"', '"Elastic"', '""', "2", '"inelastic\\n"'],
    "collision.r0": ["0", "-0.5", "1.0000001", "2", "1e300"],
    "collision.delta": ["-1e-4", "-1e300"],
    "run.t_end": ["0", "-5", "-1e-300", "1e400"],
    "output.observables_per_decade": ["0", "-1", "4294967297", "2147483648", "1e5", "100000", "1e9", "0.5"],
    "output.dumps_per_decade": ["0", "-3", "4294967297", "2147483648", "1e9", "1000000", "2.5"],
    "output.t_min": ["0", "-1", "-1e-300"],
    "output.dump_times": ["[-1]", "[nan]", "[inf]", "5", '["a"]', "[[1]]", "[1, -2]", "[1e400]", "[1, 2, -1e400]"],
}
KEYS = list(BAD)
STRING_KEYS = {"system.init", "collision.model"}


def toml(kv):
    tables = {}
    for key, value in kv.items():
        table, name = key.split(".", 1)
        tables.setdefault(table, []).append(f"{name} = {value}")
    return "".join(f"[{t}]\n" + "\n".join(lines) + "\n\n" for t, lines in tables.items())


class Corpus:
    def __init__(self, bin_dir, work):
        self.bin, self.work, self.cases = bin_dir, work, []
        self.rng = random.Random(20261201)

    def prog(self, name):
        return os.path.join(self.bin, name)

    def path(self, name):
        return os.path.join(self.work, name)

    def add(self, kind, what, command, stdin=None, watch=None, names=None, signal=None, memory=None):
        self.cases.append({"kind": kind, "what": what, "command": command, "watch": watch, "names": names,
                           "signal": signal, "memory": memory})

    def scene_file(self, text):
        name = self.path(f"scene{len(self.cases)}.toml")
        with open(name, "w", encoding="utf-8", errors="surrogateescape") as f:
            f.write(text)
        return name

    def refused_scene(self, what, text, extra=""):
        out = self.path(f"out{len(self.cases)}.h5")
        cmd = f"{self.prog('coolgas-simulate')} -q {self.scene_file(text)} -o {out} {extra}"
        self.add("refused", what, cmd, watch=out)

    # Scenes: each key with each of its bad values, in the file and as --set.
    def scenes(self):
        for key in KEYS:
            wrong_type = [v for v in NOT_A_NUMBER if not (key == "output.dump_times" and v == "[1, 2]")]
            bad = BAD[key] + (NOT_A_NUMBER[3:] if key in STRING_KEYS else wrong_type + NOT_FINITE)
            for value in bad:
                kv = dict(BASE)
                kv[key] = value
                self.refused_scene(f"scene {key} = {value[:40]}", toml(kv))
                out = self.path(f"out{len(self.cases)}.h5")
                arg = f"{key}={value}".replace("'", "'\\''")
                cmd = f"{self.prog('coolgas-simulate')} -q {self.scene_file(toml(BASE))} -o {out} --set '{arg}'"
                self.add("refused", f"--set {key}={value[:40]}", cmd, watch=out)

    # Structure: typos, missing keys, nesting, size, garbage bytes.
    def structures(self):
        letters = "abcdefghijklmnopqrstuvwxyz._"
        for _ in range(40):
            key = self.rng.choice(KEYS)
            i = self.rng.randrange(len(key))
            typo = key[:i] + self.rng.choice(letters) + key[i + 1:]
            if typo in BASE or typo in BAD or typo.count(".") != 1 or typo.startswith(".") or typo.endswith("."):
                continue
            kv = dict(BASE)
            kv[typo] = "1"
            self.refused_scene(f"unknown key {typo}", toml(kv))
        for drop in ["run.t_end", "system.N", "system.phi"]:
            kv = {k: v for k, v in BASE.items() if k != drop}
            if drop != "run.t_end":
                kv.pop("system.phi" if drop == "system.N" else "system.N")
            self.refused_scene(f"missing {drop}", toml(kv))
        for depth in [17, 100, 5000, 100000]:
            self.refused_scene(f"nested {depth}", toml(BASE) + "[output]\ndump_times = " + "[" * depth + "]" * depth + "\n")
            self.refused_scene(f"inline tables {depth}", toml(BASE) + "x = " + "{a=" * depth + "1" + "}" * depth + "\n")
        self.refused_scene("10 MB value", toml(BASE).replace('"inelastic"', '"' + "x" * 10_000_000 + '"'))
        self.refused_scene("2 MB comment", "#" + "c" * 2_000_000 + "\n" + toml(BASE))
        for n in range(30):
            garbage = bytes(self.rng.randrange(256) for _ in range(self.rng.randrange(1, 400)))
            self.refused_scene(f"garbage {n}", garbage.decode("latin-1"))
        self.refused_scene("empty scene", "")
        self.refused_scene("N, L, phi disagree", toml({**BASE, "system.L": "5"}))
        self.refused_scene("box too small", toml({**BASE, "system.N": "2", "system.phi": "0.3"}))
        self.refused_scene("N = 2, L = 3e9", toml({"system.N": "2", "system.L": "3e9", "run.t_end": "1"}))
        self.refused_scene("aggregation with r0", toml({**BASE, "collision.model": '"aggregation"'}))
        for bad in ["", "=", "=5", "noequals", "system.N", "run.t_end=" + "[" * 20000]:
            self.refused_scene(f"--set '{bad[:30]}'", toml(BASE), f"--set '{bad}'")

    # Output paths and command lines of coolgas-simulate.
    def simulate_paths(self):
        scene = self.scene_file(toml(BASE))
        os.makedirs(self.path("a_directory"), exist_ok=True)
        sim = self.prog("coolgas-simulate") + " -q"
        for what, args in [
            ("-o a directory", f"-o {self.path('a_directory')} --force"),
            ("-o a directory/", f"-o {self.path('a_directory')}/"),
            ("-o /dev/null --force", "-o /dev/null --force"),
            ("-o a missing folder", f"-o {self.path('no/such/dir/x.h5')}"),
            ("-o through a file", f"-o {scene}/x.h5"),
            ("-o a 300-character name", f"-o {self.path('n' * 300 + '.h5')}"),
            ("-o an empty name", "-o ''"),
            ("unknown option", "--no-such-option"),
        ]:
            self.add("refused", "simulate " + what, f"{sim} {scene} {args}")
        for what, args in [
            ("missing scene", self.path("missing.toml")),
            ("scene is a directory", self.path("a_directory")),
            ("scene unreadable (read fails)", "/proc/self/mem"),
            ("scene /dev/zero", "/dev/zero"),
            ("scene and --resume", f"{scene} --resume {scene}"),
            ("nothing", ""),
            ("--resume missing", "--resume " + self.path("missing.h5")),
            ("--resume a directory", "--resume " + self.path("a_directory")),
            ("--resume /dev/null", "--resume /dev/null"),
            ("--resume a text file", "--resume " + scene),
        ]:
            self.add("refused", "simulate " + what, f"{sim} {args}")
        # Starts from a file that is not a configuration.
        start = f"{sim} {scene} -o {self.path('from.h5')} --set system.init=file"
        for what, path in [("missing", self.path("missing.xyz")), ("a directory", self.path("a_directory")),
                           ("/dev/null", "/dev/null"), ("a scene", scene), ("empty", "''")]:
            self.add("refused", "simulate from " + what, f"{start} --set system.from={path}")

    # Analysis tools: bad options and bad inputs.
    def tools(self, run, table):
        os.makedirs(self.path("a_directory"), exist_ok=True)
        text = self.scene_file("not a trajectory\n")
        bad_inputs = [self.path("missing.h5"), self.path("a_directory"), "/dev/null", text]
        p = self.prog
        for tool in ["coolgas-energy", "coolgas-clusters", "coolgas-velocity", "coolgas-validate", "coolgas-convert"]:
            for b in bad_inputs:
                self.add("refused", f"{tool} {b[-30:]}", f"{p(tool)} {b}")
        for b in bad_inputs[:2] + [run]:
            self.add("refused", f"coolgas-fit --power {b[-30:]}", f"{p('coolgas-fit')} --power {b}")
            self.add("refused", f"coolgas-collapse {b[-30:]}", f"{p('coolgas-collapse')} {b}")
        options = {
            "coolgas-energy": [f"{run} --per-decade {v}" for v in ["0", "-1", "1e9", "2000000000", "x", "99999999999"]],
            "coolgas-velocity": [f"{run} --bins {v}" for v in ["0", "7", "1e9", "1000000000", "-2", "x"]]
            + [f"{run} --ymax {v}" for v in ["0", "-1", "nan", "inf"]]
            + [f"{run} --tail-from {v}" for v in ["0", "-1", "nan"]]
            + [f"{run} --min-count {v}" for v in ["0", "-5"]] + [f"{run} --tail --series"],
            "coolgas-clusters": [f"{run} --bins-per-decade {v}" for v in ["0", "-1", "x"]] + [f"{run} --series --scaled"],
            "coolgas-fit": [f"--power --t-window {w} {table}" for w in ["x:y", "5:1", "1e300:1e301", "::"]]
            + [f"--local-slope --smooth {s} {table}" for s in ["0", "-1", "nan"]]
            + [f"--power --t-column nope {table}", "--power --haff " + table, table],
            "coolgas-collapse": [f"--bootstrap {b} --optimize {table} {table}" for b in ["-1", "1000000000"]]
            + [f"--min-overlap -1 {table}", f"--t-window 5:1 {table}", f"--e-column nope {table}"]
            # exponents whose scaled points overflow or vanish: refused, never inf or 0 in the table
            + [f"--theta {th} --z {z} {table}" for th, z in
               [(f"{self.rng.choice([1, -1]) * 10.0 ** self.rng.randrange(160, 309):g}", "2.5") for _ in range(4)]
               + [("1", f"{self.rng.choice([1, -1]) * self.rng.randrange(400, 10**6)}") for _ in range(3)]],
            "coolgas-snapshot": [f"{run} --time 0 -o {self.path('a_directory')}",
                                 f"{run} --time 0 -o {self.path('no/dir/x.png')}",
                                 f"{run} --time 0 -o x.png --colored 99", f"{run} --time 0 -o x.png --size 1e9",
                                 f"{run} --time 0 -o x.png --size 5", f"{run} --time 0 -o x.png --view 2d",
                                 f"{run} --time 0 -o x.png --max-points 0", f"{run} --time 0 -o x.png --thickness -1"],
            "coolgas-convert": [f"{run} --format {f}" for f in ["pdb", "", "XYZ"]]
            + [f"{run} --time {t}" for t in ["x", "nan", ""]] + [f"{run} --last --time 1"],
            "coolgas-smoluchowski": [f"--M {m} --time 1" for m in ["0", "1", "1e12", "1000000000000", "-5"]]
            + ["--kernel nope --time 1", "--method nope --time 1", "--time -1", "--time x", "--M 64",
               "--until-mean-mass 1e300 --M 64", "--kernel separable:0,1,1 --time 1", "--rtol -1 --time 1"],
        }
        for tool, args in options.items():
            for a in args:
                self.add("refused", f"{tool} {a.replace(self.work, '')[:50]}", f"{p(tool)} {a}")
            self.add("refused", f"{tool} unknown option", f"{p(tool)} --no-such-option")

    # Resuming corrupt files: each a copy of a good run with one fault.
    def corrupt_resumes(self, run):
        import h5py
        import numpy as np

        def fault(name, change):
            path = self.path(f"corrupt_{name}.h5")
            shutil.copy(run, path)
            with h5py.File(path, "r+") as f:
                change(f)
            self.add("refused", f"--resume {name}", f"{self.prog('coolgas-simulate')} -q --resume {path} --set run.t_end=4",
                     watch=path)

        pos = "particles/all/position/value"

        def set_position(i, value):
            def change(f):
                p = f[pos][-1]
                p[i] = value
                f[pos][-1] = p
            return change

        def two_spheres_close(f):
            p = f[pos][-1]
            p[7] = p[3] + np.array([0.3, 0, 0])
            p[7][0] %= f["parameters"].attrs["L"]
            f[pos][-1] = p

        def set_attr(name, value):
            def change(f):
                f["parameters"].attrs[name] = value
            return change

        fault("outside_the_box", set_position(5, [1e6, 1, 1]))
        fault("negative_position", set_position(5, [-0.5, 1, 1]))
        fault("position_1e300", set_position(9, [1e300, 1e300, 1e300]))
        fault("nan_position", set_position(2, [np.nan, 1, 1]))
        fault("inf_position", set_position(2, [1, np.inf, 1]))
        fault("two_spheres_0.3_apart", two_spheres_close)
        fault("L_inf", set_attr("L", np.inf))
        fault("L_nan", set_attr("L", np.nan))
        fault("L_tiny", set_attr("L", 2.0))
        fault("L_huge", set_attr("L", 3e9))

        # Absurd particle counts: refused before anything is allocated.
        fault("N_1e12", set_attr("N", np.int64(10**12)))
        fault("N_2e9", set_attr("N", np.int64(2 * 10**9)))

        def huge_position_rows(f):
            frames = f[pos].shape[0]
            del f[pos]
            f.create_dataset(pos, shape=(frames, 10**12, 3), dtype="f8", chunks=(1, 4096, 3))
        fault("position_rows_of_1e12", huge_position_rows)

        # Damaged bytes: the global heap of the /parameters strings, the
        # fractal heap of the /parameters attribute table.
        for signature in [b"GCOL", b"FHDB"]:
            path = self.path(f"corrupt_{signature.decode()}.h5")
            data = bytearray(open(run, "rb").read())
            at = data.find(signature)
            data[at:at + 4] = b"\xff" * 4
            open(path, "wb").write(data)
            self.add("refused", f"--resume damaged {signature.decode()}",
                     f"{self.prog('coolgas-simulate')} -q --resume {path} --set run.t_end=4", watch=path)

        # Series a resume cannot carry on (issue 52, class 7): once resumed
        # with exit 5 after changing the file, as coolgas-validate passed them.
        def fixed_size(path, rows=None):
            def change(f):
                data = f[path][()]
                del f[path]
                f[path] = data if rows is None else data[:rows]
            return change

        def shortened(element, by):
            def change(f):
                for x in ("step", "time", "value"):
                    d = f[f"{element}/{x}"]
                    d.resize(d.shape[0] - by, axis=0)
            return change
        fault("observable_of_fixed_size", fixed_size("observables/kinetic_energy/value"))
        fault("observable_fixed_and_short", fixed_size("observables/collisions/time", 3))
        fault("positions_of_fixed_size", fixed_size("particles/all/position/value"))
        fault("reference_observable_3_rows_short", shortened("observables/kinetic_energy", 3))
        fault("an_observable_5_rows_short", shortened("observables/total_momentum", 5))
        for name in ["observable_of_fixed_size", "reference_observable_3_rows_short", "positions_of_fixed_size"]:
            path = self.path(f"corrupt_{name}.h5")
            self.add("invalid", f"validate {name}", f"{self.prog('coolgas-validate')} {path}",
                     names=os.path.basename(path))

        def nan_velocity(f):
            v = f["particles/all/velocity/value"][-1]
            v[4] = [np.nan, 0, 0]
            f["particles/all/velocity/value"][-1] = v
        fault("nan_velocity", nan_velocity)

    # Starts from files whose counts, shapes and times lie: extended XYZ
    # count lines far beyond the lines the file holds, times that are not
    # finite and >= 0, foreign H5MD frames declared beyond any memory. Each
    # is refused naming the file before anything is allocated.
    def lying_starts(self):
        import h5py
        import numpy as np
        scene = self.scene_file(toml({k: v for k, v in BASE.items() if k not in ("system.N", "system.phi")}))
        box = 'Lattice="10 0 0 0 10 0 0 0 10"'

        def start(what, name, text):
            path = self.path(name)
            with open(path, "w") as f:
                f.write(text)
            self.add("refused", "start from " + what, self.start_command(scene, path))

        lines = "".join(f"X {1 + i % 8} {1 + i // 8 % 8} {1 + i // 64}\n" for i in range(200))
        for k in range(6):
            count = self.rng.choice([10**9, 2**31 - 1001, 10**6, 4000]) + self.rng.randrange(1000)
            start(f"xyz count {count}", f"count{k}.xyz", f"{count}\n{box} Time=1\n{lines}")
        for k, t in enumerate(["nan", "inf", "-inf", "-5", "-1e-300", "NaN", "1e309"]):
            start(f"xyz Time={t}", f"time{k}.xyz", f"200\n{box} Time={t}\n{lines}")
        # (5, 1e9, 3): 24 GB a frame, within some machines' memory, but with
        # the engine's 180 B a particle far beyond (issue 52, class 5).
        for k, shape in enumerate([(1, 10**12, 3), (3, 10**11, 3), (1, 2**62, 3), (5, 10**9, 3)]):
            path = self.path(f"declared{k}.h5")
            with h5py.File(path, "w") as f:
                f.create_group("h5md")
                f.create_dataset("particles/all/position/value", shape=shape, dtype="f8", chunks=(1, 4096, 3))
                f.create_dataset("particles/all/position/time", data=np.arange(shape[0], dtype="f8"))
                f.create_dataset("particles/all/box/edges", data=[10.0, 10.0, 10.0])
            self.add("refused", f"start from H5MD of shape {shape}", self.start_command(scene, path))

        # issue 52: a foreign file whose time rows outnumber its frames
        # (7 times, 2 frames) named the wrong frame's time; its boundary in
        # ASCII strings, as h5py writes bytes, must not be what refuses it.
        path = self.path("times_and_frames.h5")
        with h5py.File(path, "w") as f:
            f.create_group("h5md")
            grid = np.column_stack([1 + np.arange(200) % 8, 1 + np.arange(200) // 8 % 8, 1 + np.arange(200) // 64])
            f["particles/all/position/value"] = np.stack([grid.astype(float)] * 2)
            f["particles/all/position/time"] = np.arange(7, dtype=float)
            f["particles/all/position/step"] = np.arange(7)
            f["particles/all/box/edges"] = [10.0, 10.0, 10.0]
            f["particles/all/box"].attrs["dimension"] = 3
            f["particles/all/box"].attrs["boundary"] = [b"periodic"] * 3
        self.add("refused", "start from H5MD of 2 frames and 7 times", self.start_command(scene, path),
                 names="7 times for 2 frames")

    # Issue 52, classes 4 and 5: input or requests without bound. Every table
    # reader stops at 1 MiB a line (a device of no newlines read for ever); a
    # Smoluchowski start beyond the cut-off is refused before the vector of
    # masses grows to it; --M, a structure grid beyond the memory available
    # (3 GB of address space) are refused naming the option and the limit.
    def unbounded(self, run):
        p = self.prog
        line = "a line longer than 1048576 bytes"
        for what, cmd in [("coolgas-fit --power /dev/zero", f"{p('coolgas-fit')} --power /dev/zero"),
                          ("coolgas-fit --local-slope - < /dev/zero", f"{p('coolgas-fit')} --local-slope - < /dev/zero"),
                          ("coolgas-collapse /dev/zero", f"{p('coolgas-collapse')} /dev/zero"),
                          ("coolgas-collapse --optimize - < /dev/zero", f"{p('coolgas-collapse')} --optimize - < /dev/zero"),
                          ("coolgas-smoluchowski --initial /dev/zero",
                           f"{p('coolgas-smoluchowski')} --initial /dev/zero --t-end 1"),
                          ("coolgas-smoluchowski --initial - < /dev/zero",
                           f"{p('coolgas-smoluchowski')} --initial - --t-end 1 < /dev/zero")]:
            self.add("refused", what, cmd, names=line)
        # One line of 1 MiB + 1 that is a column line, a comment, a row.
        for k, text in enumerate(["t\tE\n" + "1\t" * 600000 + "\n", "#" * (2**20 + 1) + "\n",
                                  "t\tE\n1\t2\n" + "9" * (2**20 + 1) + "\n"]):
            path = self.path(f"long_line{k}.tsv")
            with open(path, "w") as f:
                f.write(text)
            self.add("refused", f"coolgas-fit --power, a table whose line {k} is 1 MiB long",
                     f"{p('coolgas-fit')} --power {path}", names="at most 1048576 bytes")
        # An extended XYZ start of 200 particles, valid but for one line of
        # 1 MiB + 1 (padding that was once read whole, and accepted): the
        # count line, the comment line, a particle line.
        scene = self.scene_file(toml({k: v for k, v in BASE.items() if k not in ("system.N", "system.phi")}))
        box = 'Lattice="10 0 0 0 10 0 0 0 10" Time=1'
        rows = [f"X {1 + i % 8} {1 + i // 8 % 8} {1 + i // 64}" for i in range(200)]
        pad = " " * 2**20
        for where, lines in [("count", ["200" + pad, box] + rows), ("comment", ["200", box + pad] + rows),
                             ("particle", ["200", box] + rows[:7] + [rows[7] + pad] + rows[8:])]:
            path = self.path(f"long_{where}_line.xyz")
            with open(path, "w") as f:
                f.write("\n".join(lines) + "\n")
            self.add("refused", f"start from XYZ whose {where} line is 1 MiB long", self.start_command(scene, path),
                     names="an extended XYZ file's lines are at most 1048576 bytes")
        smol = p("coolgas-smoluchowski")
        for k, (columns, row) in enumerate([("m\tN", "1e15\t1"), ("m\tN", "1e300\t1"), ("m\tN", "65\t1"),
                                            ("m\tdm\tN", "30\t1e12\t1"), ("m\tdm\tN", "1e200\t3\t1"),
                                            ("m\tN", f"{2**62}\t1")]):
            path = self.path(f"initial{k}.tsv")
            with open(path, "w") as f:
                f.write(f"{columns}\n1{chr(9) + '1' if 'dm' in columns else ''}\t1\n{row}\n")
            self.add("refused", f"coolgas-smoluchowski --M 64 --initial with {row.split(chr(9))[0]}",
                     f"{smol} --M 64 --t-end 1 --initial {path}", names="above the cut-off M = 64")
        limit = 3 * 2**30
        for method in ["fft", "direct", "geometric"]:
            for M in ["100000000", "268435456"]:
                self.add("refused", f"coolgas-smoluchowski --method {method} --M {M} in 3 GB",
                         f"{smol} --method {method} --grid-ratio 1.0000001 --M {M} --t-end 1", memory=limit,
                         names=f"cut-off mass --M {M} would need")
        for grid in ["1024", "900"]:
            self.add("refused", f"coolgas-structure --grid {grid} in 3 GB",
                     f"{p('coolgas-structure')} --grid {grid} {run}", memory=limit, names=f"--grid {grid} would need")

    # Long loops stopped by a signal pending from the start (issue 52, class
    # 4): the pilot of --estimate equilibrating for 1e7 collision times (once
    # "internal error", exit 1), a Smoluchowski kernel table, a table read.
    def interrupted(self):
        p = self.prog
        scene = self.scene_file(toml({**BASE, "system.N": "20000", "system.equilibrate": "1e7", "run.t_end": "1e3"}))
        rows = self.path("rows.tsv")
        with open(rows, "w") as f:
            f.write("t\tE\n# L: 16\n" + "".join(f"{1 + i}\t{(1 + i) ** -1.2}\n" for i in range(20000)))
        counts = self.path("counts.tsv")
        with open(counts, "w") as f:
            f.write("m\tN\n" + "".join(f"{1 + i}\t1\n" for i in range(10000)))
        for sig in ["INT", "TERM"]:
            self.add("interrupted", f"--estimate, equilibrate = 1e7, SIG{sig}",
                     [p("coolgas-simulate"), "--estimate", scene], signal=sig,
                     names="in the set-up of the pilot run of --estimate")
            self.add("interrupted", f"coolgas-smoluchowski --M 2e6, SIG{sig}",
                     [p("coolgas-smoluchowski"), "--M", "2000000", "--t-end", "1"], signal=sig,
                     names="while tabulating the kernel")
            self.add("interrupted", f"coolgas-collapse of 20000 rows, SIG{sig}", [p("coolgas-collapse"), rows],
                     signal=sig, names="while reading")
            self.add("interrupted", f"coolgas-smoluchowski --initial of 10000 rows, SIG{sig}",
                     [p("coolgas-smoluchowski"), "--M", "20000", "--t-end", "1", "--initial", counts],
                     signal=sig, names="while reading")

    def start_command(self, scene, path):
        out = self.path(f"out{len(self.cases)}.h5")
        return f"{self.prog('coolgas-simulate')} -q {scene} -o {out} --set system.init=file --set system.from={path}"

    # Checkpoints beside a good run that are not one: a device, a directory,
    # sections whose lengths exceed the file. Refused naming the checkpoint,
    # at once (a link to /dev/zero was read for gigabytes).
    def bad_checkpoints(self, run):
        import struct
        good = open(run + ".checkpoint", "rb").read()
        name_length = struct.unpack_from("<I", good, 24)[0]
        count_at = 24 + 4 + name_length + 8

        def resume(what, make):
            path = self.path(f"ckpt_{len(self.cases)}.h5")
            shutil.copy(run, path)
            make(path + ".checkpoint")
            self.add("refused", "--resume with checkpoint " + what,
                     f"{self.prog('coolgas-simulate')} -q --resume {path} --set run.t_end=4", watch=path)

        resume("-> /dev/zero", lambda c: os.symlink("/dev/zero", c))
        resume("-> /dev/urandom", lambda c: os.symlink("/dev/urandom", c))
        resume("a directory", os.makedirs)
        for k in range(4):
            count = self.rng.choice([2**60, 2**40, len(good), 2**64 - 1]) + k

            def lying(c, count=count):
                data = bytearray(good)
                struct.pack_into("<Q", data, count_at, count % 2**64)
                open(c, "wb").write(data)
            resume(f"section count {count}", lying)

    # Damaged compressed chunks: every reader names the file and dataset
    # (exit 2), never "internal error: HDF5". One copy per damaged dataset.
    def damaged_chunks(self, run):
        import h5py
        for element in ["position", "velocity"]:
            path = self.path(f"chunk_{element}.h5")
            shutil.copy(run, path)
            with h5py.File(path, "r") as f:
                d = f[f"particles/all/{element}/value"]
                info = d.id.get_chunk_info(d.id.get_num_chunks() - 1)
            data = bytearray(open(path, "rb").read())
            at = info.byte_offset + info.size // 3
            data[at:at + 64] = bytes(b ^ 0x5A for b in data[at:at + 64])
            open(path, "wb").write(data)
            p = self.prog
            scene = self.scene_file(toml({k: v for k, v in BASE.items() if k not in ("system.N", "system.phi")}))
            readers = [("convert", f"{p('coolgas-convert')} --last {path}"),
                       ("--resume", f"{p('coolgas-simulate')} -q --resume {path} --set run.t_end=4"),
                       ("start from", self.start_command(scene, path))]
            if element == "position":  # the tools that read positions only
                readers += [("clusters", f"{p('coolgas-clusters')} {path}"),
                            ("snapshot", f"{p('coolgas-snapshot')} {path} --time 2 -o {self.path('chunk.png')}")]
            else:
                readers += [("velocity", f"{p('coolgas-velocity')} {path}")]
            for what, cmd in readers:
                self.add("refused", f"{what} with a damaged {element} chunk", cmd,
                         watch=path if what == "--resume" else None)

    # Damaged attributes and metadata (issue 52, classes 1 and 6): a
    # box/dimension that is an array, a string, 2.5 or out of range, an array
    # /parameters/N, and object headers overwritten. Every reader refuses the
    # file naming it (exit 2, one line, never a segfault or "internal error:
    # HDF5"); coolgas-validate lists the problem on stdout (exit 2).
    def damaged_metadata(self, run):
        import h5py
        import numpy as np
        p = self.prog
        scene = self.scene_file(toml({k: v for k, v in BASE.items() if k not in ("system.N", "system.phi")}))

        def attribute(group, name, value):
            def change(f):
                del f[group].attrs[name]
                f[group].attrs[name] = value
            return change

        def header(path):
            def damage(copy):
                with h5py.File(copy, "r") as f:
                    at = h5py.h5o.get_info(f[path].id).addr
                data = bytearray(open(copy, "rb").read())
                data[at:at + 4] = b"\xff" * 4
                open(copy, "wb").write(data)
            return damage

        box = "particles/all/box"
        # Each fault with the readers that read what it damages (the energy
        # table reads observables, not positions; a start reads no observables).
        dumps = ["convert", "clusters", "velocity", "structure", "shape", "snapshot", "--resume", "start from"]
        every = ["energy"] + dumps
        faults = [("dimension [2, 2]", attribute(box, "dimension", np.array([2, 2])), every),
                  ("dimension [3, 3, 3, 3, 3]", attribute(box, "dimension", np.full(5, 3)), every),
                  ("dimension '3'", attribute(box, "dimension", "3"), every),
                  ("dimension b'2'", attribute(box, "dimension", np.bytes_(b"2")), every),
                  ("dimension 2.5", attribute(box, "dimension", 2.5), every),
                  ("dimension 3.0", attribute(box, "dimension", 3.0), every),
                  ("dimension 0", attribute(box, "dimension", np.int64(0)), every),
                  ("dimension 4", attribute(box, "dimension", np.int64(4)), every),
                  ("dimension -2**62", attribute(box, "dimension", np.int64(-2**62)), every),
                  ("/parameters/N [200, 200]", attribute("parameters", "N", np.array([200, 200])),
                   ["energy", "convert", "clusters", "--resume", "start from"]),
                  ("/parameters/L [10, 10, 10]", attribute("parameters", "L", np.array([10.0, 10.0, 10.0])),
                   ["energy", "convert", "clusters", "--resume", "start from"]),
                  ("/parameters/model ['a', 'b']", attribute("parameters", "model", ["inelastic", "elastic"]),
                   ["energy", "--resume"]),
                  ("box header damaged", header(box), every),
                  ("position header damaged", header("particles/all/position"),
                   ["convert", "clusters", "structure", "shape", "snapshot", "--resume", "start from"]),
                  ("observables header damaged", header("observables"), ["energy", "--resume"])]
        for k, (what, change, tools) in enumerate(faults):
            path = self.path(f"meta{k}.h5")
            shutil.copy(run, path)
            if change.__name__ == "damage":
                change(path)
            else:
                with h5py.File(path, "r+") as f:
                    change(f)
            name = os.path.basename(path)
            readers = {"convert": f"{p('coolgas-convert')} {path}",
                       "energy": f"{p('coolgas-energy')} {path}",
                       "clusters": f"{p('coolgas-clusters')} {path}",
                       "velocity": f"{p('coolgas-velocity')} {path}",
                       "structure": f"{p('coolgas-structure')} {path}",
                       "shape": f"{p('coolgas-shape')} {path}",
                       "snapshot": f"{p('coolgas-snapshot')} {path} --time 2 -o {self.path(f'meta{k}.png')}",
                       "--resume": f"{p('coolgas-simulate')} -q --resume {path} --set run.t_end=4",
                       "start from": self.start_command(scene, path)}
            for tool in tools:
                self.add("refused", f"{tool} with {what}", readers[tool], watch=path if tool == "--resume" else None,
                         names=name)
            self.add("invalid", f"validate with {what}", f"{p('coolgas-validate')} {path}", names=name)

    # Values a tool would print as nan (issue 52, class 8): a NaN dump time,
    # velocities of 1e300 (their moments overflow). Refused naming the file.
    def non_finite_values(self, run):
        import h5py
        import numpy as np
        p = self.prog
        path = self.path("nan_time.h5")
        shutil.copy(run, path)
        with h5py.File(path, "r+") as f:
            for element in ("position", "velocity", "image"):
                d = f[f"particles/all/{element}/time"]
                t = d[()]
                t[self.rng.randrange(1, len(t))] = np.nan
                d[...] = t
        for tool in ["clusters", "velocity", "structure", "shape"]:
            self.add("refused", f"{tool} --series with a NaN dump time", f"{p('coolgas-' + tool)} --series {path}",
                     names=os.path.basename(path))
        self.add("refused", "convert with a NaN dump time", f"{p('coolgas-convert')} {path}", names=os.path.basename(path))
        path = self.path("fast.h5")
        shutil.copy(run, path)
        with h5py.File(path, "r+") as f:
            d = f["particles/all/velocity/value"]
            v = d[()]
            v[-1] = 1e300
            d[...] = v
        for table in ["--series", "--tail", ""]:
            self.add("refused", f"velocity {table} with velocities of 1e300", f"{p('coolgas-velocity')} {table} {path}",
                     names=os.path.basename(path))

    # Output names around the stated limit: every length the check passes
    # must work (the run adds .partial, .checkpoint, .checkpoint.partial);
    # the longer ones are refused.
    def long_names(self):
        scene = self.scene_file(toml(BASE))
        limit = os.pathconf(self.work, "PC_NAME_MAX") - len(".checkpoint.partial")
        for length in range(limit + 1, limit + 12):
            self.add("refused", f"-o a {length}-character name",
                     f"{self.prog('coolgas-simulate')} -q {scene} -o {self.path('n' * (length - 3) + '.h5')}")

    # Kernels whose rates overflow or whose solution blows up within the
    # first steps: one line, exit 2, and never a row of nan or inf.
    def overflowing_kernels(self):
        smol = self.prog("coolgas-smoluchowski")
        for _ in range(4):
            c = f"{10.0 ** self.rng.randrange(200, 308):g}"
            self.add("overflow", f"--kernel separable:{c},1,1", f"{smol} --M 256 --kernel separable:{c},1,1 --t-end 10")
        for _ in range(4):
            p = self.rng.randrange(30, 200)
            self.add("overflow", f"--kernel separable:1,{p},{p}",
                     f"{smol} --M 256 --kernel separable:1,{p},{p} --t-end 10")

    # Output that cannot be written, and closed pipes.
    def outputs(self, run, table):
        p = self.prog
        commands = {
            "coolgas-energy": f"{p('coolgas-energy')} --per-decade 2000 {run}",
            "coolgas-fit": f"{p('coolgas-fit')} --local-slope {table}",
            "coolgas-collapse": f"{p('coolgas-collapse')} {table}",
            "coolgas-clusters": f"{p('coolgas-clusters')} {run}",
            "coolgas-velocity": f"{p('coolgas-velocity')} --bins 20000 {run}",
            "coolgas-smoluchowski": f"{p('coolgas-smoluchowski')} --kernel constant --M 4096 --time 1,2,3",
            "coolgas-validate": f"{p('coolgas-validate')} {run}",
            "coolgas-convert": f"{p('coolgas-convert')} {run}",
            "coolgas-simulate --help": f"{p('coolgas-simulate')} --help",
        }
        # Output files given by option: a full device is exit code 5 naming it.
        smol = f"{p('coolgas-smoluchowski')} --M 256 --time 0.2,0.5"
        for kernel in ["constant", "additive", "ballistic"]:
            self.add("write", f"coolgas-smoluchowski --kernel {kernel} --series-file /dev/full",
                     f"{smol} --kernel {kernel} --series-file /dev/full > /dev/null", names="/dev/full")
        for tool, cmd in commands.items():
            self.add("no space", f"{tool} > /dev/full", cmd + " > /dev/full")
            self.add("no space", f"{tool} >&-", cmd + " >&-")
            self.add("pipe", f"{tool} | head -c 1", cmd + " | head -c 1 > /dev/null")


def pending(signal_name):
    """A child's set-up before exec: the signal blocked and sent, so that it
    is pending when the program starts (exec keeps both) and is recorded as
    the program starts watching for it (common/interrupt.h)."""
    import signal
    number = getattr(signal, "SIG" + signal_name)

    def set_up():
        signal.pthread_sigmask(signal.SIG_BLOCK, [number])
        os.kill(os.getpid(), number)
    return set_up


def limited(memory):
    """A child's set-up before exec: its address space limited to `memory` bytes."""
    def set_up():
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
    return set_up


def run_case(case, work):
    before = sorted(os.listdir(work))
    digest = None
    if case["watch"] and os.path.exists(case["watch"]):
        digest = hashlib.sha256(open(case["watch"], "rb").read()).hexdigest()
    command = case["command"] if isinstance(case["command"], list) else ["/bin/sh", "-c", case["command"]]
    set_up = pending(case["signal"]) if case["signal"] else limited(case["memory"]) if case["memory"] else None
    # A session of its own, killed whole at the time limit: a program that
    # hangs (a regression reading /dev/zero for ever) must not live on as an
    # orphan of its shell, growing until the machine's out-of-memory killer.
    with subprocess.Popen(command, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.PIPE, preexec_fn=set_up,
                          start_new_session=True) as child:
        try:
            out, err = child.communicate(timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            os.killpg(child.pid, 9)
            child.communicate()
            return f"no answer within {TIMEOUT_S} s"
    r = subprocess.CompletedProcess(command, child.returncode, out, err)
    err = r.stderr.decode("utf-8", "replace")
    lines = err.count("\n") + (1 if err and not err.endswith("\n") else 0)
    kind = case["kind"]
    if kind == "refused":
        if r.returncode != 2:
            return f"exit code {r.returncode}, expected 2: {err[:300]}"
        if lines != 1:
            return f"{lines} lines on stderr, expected 1: {err[:300]}"
        if len(err.rstrip("\n")) > 600:  # about 200 characters (UTF-8, escapes)
            return f"an error line of {len(err)} bytes"
        if "internal error" in err:
            return "internal error: " + err
        if r.stdout:
            return "stdout not empty: " + r.stdout[:200].decode("utf-8", "replace")
        if case["names"] and case["names"] not in err:
            return f"the error line does not name {case['names']}: {err[:300]}"
        if case["watch"]:
            if digest is None and os.path.exists(case["watch"]):
                return "output file written: " + case["watch"]
            if digest and hashlib.sha256(open(case["watch"], "rb").read()).hexdigest() != digest:
                return "file changed: " + case["watch"]
        after = sorted(os.listdir(work))
        if after != before:
            return "files written: " + ", ".join(sorted(set(after) - set(before)))
    elif kind == "invalid":  # coolgas-validate: problems on stdout, one line each naming the file
        out = r.stdout.decode("utf-8", "replace")
        if r.returncode != 2 or err:
            return f"exit code {r.returncode} and stderr {err[:300]!r}, expected 2 and nothing"
        if not out or any(not line.split(": ")[0].endswith(case["names"]) for line in out.splitlines()):
            return f"expected problem lines naming {case['names']}, got: {out[:300]}"
        if "internal error" in out:
            return "internal error: " + out[:300]
    elif kind == "no space":
        if r.returncode == 0:
            return "exit code 0 although stdout could not be written"
        if lines != 1 or "stdout" not in err:
            return f"expected one line naming stdout, got: {err[:300]}"
    elif kind == "write":
        if r.returncode != 5:
            return f"exit code {r.returncode}, expected 5: {err[:300]}"
        if lines != 1 or case["names"] not in err:
            return f"expected one line naming {case['names']}, got: {err[:300]}"
    elif kind == "overflow":
        out = r.stdout.decode("utf-8", "replace").lower()
        if r.returncode != 2 or lines != 1:
            return f"exit code {r.returncode} and {lines} lines on stderr, expected 2 and 1: {err[:300]}"
        if "nan" in out or "inf" in out:
            return "a row of nan or inf on stdout"
    elif kind == "pipe":
        if err:
            return "stderr not empty: " + err[:300]
    elif kind == "interrupted":
        if r.returncode != 3 or lines != 1:
            return f"exit code {r.returncode} and {lines} lines on stderr, expected 3 and 1: {err[:300]}"
        if f"interrupted by SIG{case['signal']}" not in err or case["names"] not in err:
            return f"expected one line naming SIG{case['signal']} and {case['names']!r}: {err[:300]}"
        if r.stdout:
            return "stdout not empty: " + r.stdout[:200].decode("utf-8", "replace")
    return None


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    bin_dir, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    corpus = Corpus(bin_dir, work)
    # A small good run and its energy table, for the tools and the corrupt resumes.
    run, table = corpus.path("good.h5"), corpus.path("good.tsv")
    good = subprocess.run([corpus.prog("coolgas-simulate"), "-q", corpus.scene_file(toml(BASE)), "-o", run],
                          capture_output=True, timeout=120)
    if good.returncode != 0:
        sys.exit("cannot make the good run: " + good.stderr.decode())
    with open(table, "wb") as f:
        subprocess.run([corpus.prog("coolgas-energy"), run], stdout=f, check=True, timeout=60)
    corpus.scenes()
    corpus.structures()
    corpus.simulate_paths()
    corpus.tools(run, table)
    corpus.corrupt_resumes(run)
    corpus.lying_starts()
    corpus.bad_checkpoints(run)
    corpus.damaged_chunks(run)
    corpus.damaged_metadata(run)
    corpus.non_finite_values(run)
    corpus.overflowing_kernels()
    corpus.long_names()
    corpus.outputs(run, table)
    corpus.unbounded(run)
    corpus.interrupted()
    # Sanitized programs reserve terabytes of address space: no case runs
    # them within a limit of it.
    if b"__asan_init" in open(corpus.prog("coolgas-smoluchowski"), "rb").read():
        corpus.cases = [c for c in corpus.cases if not c["memory"]]
    # COOLGAS_FUZZ_STRIDE=k keeps every k-th refused case (and every case of the
    # other kinds): the sanitizer lane of .ci/run, where each of these ~600
    # processes costs 0.2 s of start-up, runs half the corpus; the first lane
    # runs all of it.
    stride = int(os.environ.get("COOLGAS_FUZZ_STRIDE", "1"))
    if stride > 1:
        corpus.cases = [c for i, c in enumerate(corpus.cases) if c["kind"] != "refused" or i % stride == 0]
    if "--list" in sys.argv:
        for c in corpus.cases:
            print(c["kind"], "|", c["what"])
        return
    failures = 0
    # Two at a time (the machine's two cores); the report keeps the corpus order.
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        problems = list(pool.map(lambda c: run_case(c, work), corpus.cases))
    for case, problem in zip(corpus.cases, problems):
        if problem:
            failures += 1
            print(f"FAIL [{case['kind']}] {case['what']}: {problem}")
    kinds = {}
    for c in corpus.cases:
        kinds[c["kind"]] = kinds.get(c["kind"], 0) + 1
    every = f", 1 in {stride} refused cases (COOLGAS_FUZZ_STRIDE)" if stride > 1 else ""
    print(f"{len(corpus.cases)} cases ({', '.join(f'{n} {k}' for k, n in kinds.items())}{every}), {failures} failed")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
