#!/usr/bin/env python3
"""How right the ETA of coolgas-simulate's progress line is (tests/bench/README.md).

    python3 tests/bench/eta_check.py BIN_DIR OUT_DIR [SCENE ...]

Runs each scene below with stderr on a pseudo-terminal (the progress line is
shown only on a terminal), records every ETA printed with the wall time at
which it was printed, and once the run has ended compares each with the truth:
the wall time the run really still took. Prints, per scene, the ratio
ETA / true remaining time at 10 %, 20 %, ... 90 % of the run's wall time (the
last ETA printed by then), and the smallest and largest ratio of all the ETAs
printed between 10 % and 90 % of it. The ETA includes the dumps and
checkpoints still due, so it has no part that the machine's load leaves
alone: the elastic scene, whose work is known exactly, shows what the load
alone does to the ratio. Also writes OUT_DIR/eta_check.tsv (one row per ETA printed, with the progress
line it came from).
"""
import os
import pty
import re
import subprocess
import sys
import time

# name -> coolgas-simulate --set overrides. 30-60 s each on one core of an idle
# machine (smaller boxes ran too short: a few whole-second ETAs).
SCENES = {
    # The paper's gas (r0 = 0.1, delta = 1e-4, phi = 0.208) in a small box:
    # homogeneous cooling, clustering, then the finite-size regime.
    "gas_L48": ["system.L=48", "system.phi=0.208", "collision.model=inelastic", "collision.r0=0.1",
                "collision.delta=1e-4", "run.t_end=2e5"],
    # Elastic: a constant collision rate.
    "elastic_L48": ["system.L=48", "system.phi=0.208", "collision.model=elastic", "run.t_end=1000"],
    # Ballistic aggregation: the merges die out as the aggregates thin out.
    "ba_L120": ["system.L=120", "system.phi=0.208", "system.equilibrate=0", "collision.model=aggregation",
                 "run.t_end=100"],
    # A dilute gas: Fig. 2's phi = 0.052.
    "dilute_L100": ["system.L=100", "system.phi=0.052", "system.equilibrate=0", "collision.model=inelastic",
                     "collision.r0=0.1", "collision.delta=1e-4", "run.t_end=1e5"],
}
# The run's first progress line is due this long after its start (common/progress.cc):
# the run's wall time is counted from then on, without the set-up.
FIRST_LINE_S = 0.5
# "left ~1h02m", "left ~3m05s", "left ~12s", or "left estimating..." while
# the estimate is held back (simulate/run/eta_gate.h).
ETA = re.compile(r"left (?:~(?:(\d+)h)?(?:(\d+)m)?(?:(\d+)s)?|estimating\.\.\.)")


def seconds(m):
    if m.group(0) == "left estimating...":
        return None
    h, mi, s = (int(g) if g else 0 for g in m.groups())
    return 3600 * h + 60 * mi + s


def run(bin_dir, out_dir, name):
    """Returns the run's wall time and its (wall time, ETA seconds, progress line) list."""
    args = [os.path.join(bin_dir, "coolgas-simulate"), "/dev/null", "--force", "-o",
            os.path.join(out_dir, name + ".h5")]
    for s in SCENES[name]:
        args += ["--set", s]
    master, slave = pty.openpty()
    start = time.monotonic()
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=slave)
    os.close(slave)
    etas, pending = [], b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # the child closed the terminal
            chunk = b""
        if not chunk:
            break
        now = time.monotonic() - start
        pending += chunk
        *lines, pending = re.split(rb"[\r\n]", pending)
        for line in lines:
            text = line.decode(errors="replace")
            m = ETA.search(text)
            if m and text.startswith("t = "):
                etas.append((now, seconds(m), text.split("  ETA")[0]))
    code = proc.wait()
    end = time.monotonic() - start
    os.close(master)
    if code != 0 or not etas:
        sys.exit(f"eta_check: {name} exited with {code} after {len(etas)} progress lines")
    origin = etas[0][0] - FIRST_LINE_S
    return end - origin, [(at - origin, eta, line) for at, eta, line in etas]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    bin_dir, out_dir = sys.argv[1], sys.argv[2]
    names = sys.argv[3:] or list(SCENES)
    os.makedirs(out_dir, exist_ok=True)
    fractions = [k / 10 for k in range(1, 10)]
    with open(os.path.join(out_dir, "eta_check.tsv"), "w") as tsv:
        tsv.write("scene\twall_s\teta_s\ttrue_s\tprogress_line\n")
        print("scene\twall_s\t" + "\t".join(f"{f:.0%}" for f in fractions) + "\tmin\tmax")
        for name in names:
            wall, etas = run(bin_dir, out_dir, name)
            for at, eta, line in etas:
                tsv.write(f"{name}\t{at:.2f}\t{'nan' if eta is None else eta}\t{wall - at:.2f}\t{line}\n")
            tsv.flush()
            ratios = []
            for f in fractions:
                known = [(at, eta) for at, eta, _ in etas if at <= f * wall]
                at, eta = known[-1] if known else (0, None)
                ratios.append(float("nan") if eta is None else eta / (wall - at))
            # Every ETA printed between the first and the last tenth (rounding
            # to whole seconds dominates the ratio near the end).
            good = [eta / (wall - at) for at, eta, _ in etas if eta is not None and 0.1 <= at / wall <= 0.9]
            extremes = f"{min(good):.2f}\t{max(good):.2f}" if good else "nan\tnan"
            print(f"{name}\t{wall:.0f}\t" + "\t".join(f"{r:.2f}" for r in ratios) + f"\t{extremes}", flush=True)


if __name__ == "__main__":
    main()
