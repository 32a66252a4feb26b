#!/usr/bin/env python3
"""Two programs' rates as one ratio, measured in turns (tests/bench/README.md).

    python3 tests/bench/interleave.py [-n RUNS] -e KEY -- 'COMMAND A' 'COMMAND B'

Runs A, then B, RUNS times over (default 5), each a fresh shell process, and
reads from each run's output (stdout and stderr) the number that follows the
first KEY (e.g. 'per_cpu_s='). Prints every value, then both medians and the
ratio of the medians A / B. This machine's speed drifts by tens of percent
within minutes: taking turns exposes both programs to the same drift, where
two figures measured at different moments would compare two moments.
"""
import argparse
import re
import statistics
import subprocess
import sys


def value_after(key, text, command):
    m = re.search(re.escape(key) + r"\s*([-+0-9.eE]+)", text)
    if not m:
        sys.exit(f"interleave: no '{key}' followed by a number in the output of: {command}")
    return float(m.group(1))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                usage="%(prog)s [-n RUNS] -e KEY -- 'COMMAND A' 'COMMAND B'")
    p.add_argument("-n", type=int, default=5, help="runs of each command (default 5)")
    p.add_argument("-e", required=True, metavar="KEY", help="the text before the number to read, e.g. 'per_cpu_s='")
    p.add_argument("commands", nargs=2, metavar="COMMAND")
    a = p.parse_args()
    if a.n < 1:
        p.error(f"-n {a.n}: give at least one run")
    values = {c: [] for c in a.commands}
    for i in range(a.n):
        for c in a.commands:
            r = subprocess.run(c, shell=True, capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit(f"interleave: exit {r.returncode} from: {c}\n{r.stderr.strip()}")
            values[c].append(value_after(a.e, r.stdout + r.stderr, c))
            print(f"run {i + 1} {'AB'[a.commands.index(c)]}: {values[c][-1]:g}", flush=True)
    med = [statistics.median(values[c]) for c in a.commands]
    print(f"median A: {med[0]:g}  median B: {med[1]:g}  ratio A/B: {med[0] / med[1]:.3f}  ({a.n} runs each, in turns)")


if __name__ == "__main__":
    main()
