#!/usr/bin/python3
"""eta_curves.py OUT_DIR RUN.h5 ...: the cumulative collisions C(t) of
finished coolgas-simulate runs, with the parameters the ETA rule depends on,
as one small TSV a run (OUT_DIR/NAME.tsv), for the replay test of the cost
model (tests/unit/simulate/run/run_eta_replay_test.cc). Nothing is timed:
the replay counts collisions, so the machine's load plays no part."""
import os
import sys

import h5py


def write_curve(path, out_dir):
    name = os.path.splitext(os.path.basename(path))[0]
    with h5py.File(path, "r") as f:
        p = f["parameters"].attrs
        t = f["observables/collisions/time"][:]
        c = f["observables/collisions/value"][:]
        keys = ["model", "N", "L", "phi", "r0", "delta"]
        values = {k: (p[k].decode() if isinstance(p[k], bytes) else p[k]) for k in keys if k in p}
        with open(os.path.join(out_dir, name + ".tsv"), "w") as out:
            out.write(f"# {name}: C(t) of a coolgas-simulate run ({p['program_version']}), by tests/bench/eta_curves.py\n")
            out.write("# " + " ".join(f"{k}={values[k]}" for k in keys if k in values) + "\n")
            out.write("t\tcollisions\n")
            for ti, ci in zip(t, c):
                out.write(f"{ti:.9g}\t{int(ci)}\n")


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: eta_curves.py OUT_DIR RUN.h5 ...")
    for path in sys.argv[2:]:
        write_curve(path, sys.argv[1])


if __name__ == "__main__":
    main()
