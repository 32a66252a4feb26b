"""Facts the documents state in more than one place agree with their one
source. Usage: docs_agree.py SOURCE_DIR BIN_DIR SCRATCH_DIR

- The aggregation limit: coolgas-simulate stops ballistic aggregation when
  the largest aggregate is half the box wide (its --help, exit code 4). No
  page, scale file or notebook says a third.
- When it stops: pipelines/README.md says at which t the pipelines' BA scene
  (phi = 0.208, seed 1) reaches the limit for L = 16 and L = 48; those runs
  are made here (seconds) and must stop within 10 % of it, and every scale
  whose BA box is one of them must end its BA runs before.
- The workstation scale's cost: docs/studies.md states it once (runs,
  core-hours and the wall time on 2 cores); `make -C pipelines/workstation
  estimate` must plan the same, and the other pages that name the scale
  give no duration of their own.
Prints each finding and exits 1 if any."""
import os
import re
import subprocess
import sys

problems = []


def problem(text):
    problems.append(text)
    print("FAILED: " + text)


def read(source, path):
    with open(os.path.join(source, path), encoding="utf-8") as f:
        return f.read()


def prose_files(source):
    out = ["README.md", "pipelines/README.md", "pipelines/notebooks/first_look.py"]
    for folder, ext in (("docs", ".md"), ("data-schema", ".md"), ("pipelines/scales", ".mk")):
        out += sorted(os.path.join(folder, f) for f in os.listdir(os.path.join(source, folder)) if f.endswith(ext))
    return out


def check_aggregation_limit(source, bin_dir):
    help_text = subprocess.run([f"{bin_dir}/coolgas-simulate", "--help"], capture_output=True, text=True).stdout
    if "an aggregate grown to half the box" not in help_text:
        problem("coolgas-simulate --help no longer says aggregation stops at half the box: update this test and the docs")
    for path in prose_files(source):
        text = " ".join(read(source, path).replace("#", " ").split())
        for sentence in re.split(r"(?<=[.;:])\s", text):
            if re.search(r"aggregat", sentence, re.I) and re.search(r"\bthird of\b|L/3\b", sentence):
                problem(f"{path}: says the aggregation limit is a third of the box: {sentence[:160]}")


def stop_time(bin_dir, scratch, L):
    scene = os.path.join(scratch, "ba.toml")
    with open(scene, "w") as f:
        f.write('[system]\nphi = 0.208\nseed = 1\n[collision]\nmodel = "aggregation"\n[run]\nt_end = 1e6\n')
    out = os.path.join(scratch, f"ba_L{L}.h5")
    for stale in (out, out + ".checkpoint"):
        if os.path.exists(stale):
            os.remove(stale)
    r = subprocess.run([f"{bin_dir}/coolgas-simulate", scene, "--set", f"system.L={L}", "-o", out, "--quiet"],
                       capture_output=True, text=True)
    m = re.search(r"aggregation at t = ([0-9.e+]+): the largest aggregate", r.stderr)
    if r.returncode != 4 or not m:
        problem(f"BA at L = {L} did not stop at the limit (exit {r.returncode}): {r.stderr[-300:]}")
        return None
    return float(m.group(1))


def make_variable(text, name):
    m = re.search(rf"^{name}\s*:?=\s*(\S+)", text, re.MULTILINE)
    return m.group(1) if m else None


def check_aggregation_times(source, bin_dir, scratch):
    text = " ".join(read(source, "pipelines/README.md").split())
    m = re.search(r"that happens near t = (\d+) for L = 16 and t = (\d+) for L = 48", text)
    if not m:
        problem("pipelines/README.md: no sentence 'that happens near t = ... for L = 16 and t = ... for L = 48'")
        return
    for L, stated in ((16, float(m.group(1))), (48, float(m.group(2)))):
        t = stop_time(bin_dir, scratch, L)
        if t is None:
            continue
        print(f"BA at L = {L}: stops at t = {t:g}, pipelines/README.md says {stated:g}")
        if abs(t / stated - 1) > 0.1:
            problem(f"pipelines/README.md: BA at L = {L} reaches half the box at t = {stated:g}; it does at {t:g}")
        for scale in sorted(os.listdir(os.path.join(source, "pipelines/scales"))):
            mk = read(source, os.path.join("pipelines/scales", scale))
            if make_variable(mk, "BA_L") == str(L) and float(make_variable(mk, "BA_T_END")) >= t:
                problem(f"pipelines/scales/{scale}: BA_T_END = {make_variable(mk, 'BA_T_END')} is past the stop at t = {t:g}")


def check_workstation_plan(source, bin_dir, scratch):
    text = " ".join(read(source, "docs/studies.md").split())
    m = re.search(r"`make -C pipelines/workstation estimate` plans (\d+) runs and ([0-9.]+) core-hours, about "
                  r"([0-9.]+) hours of wall time with `-j2`", text)
    if not m:
        problem("docs/studies.md: no sentence '`make -C pipelines/workstation estimate` plans N runs and X "
                "core-hours, about Y hours of wall time with `-j2`'")
        return
    runs, core_hours, wall = int(m.group(1)), m.group(2), float(m.group(3))
    r = subprocess.run(["make", "-s", "-C", os.path.join(source, "pipelines/workstation"), "estimate",
                        f"BIN={bin_dir}", f"OUT={scratch}/workstation"], capture_output=True, text=True)
    total = re.search(r"^total: (\d+) runs, ([0-9.]+) core-hours", r.stdout, re.MULTILINE)
    if r.returncode != 0 or not total:
        problem(f"make -C pipelines/workstation estimate failed (exit {r.returncode}): {r.stderr[-300:]}")
        return
    print(f"workstation: planned {total.group(1)} runs, {total.group(2)} core-hours; docs/studies.md says "
          f"{runs} runs, {core_hours} core-hours, {wall:g} hours on 2 cores")
    if (int(total.group(1)), total.group(2)) != (runs, core_hours):
        problem(f"docs/studies.md: the workstation plan is {total.group(1)} runs, {total.group(2)} core-hours, "
                f"not {runs} runs, {core_hours}")
    if abs(wall - float(total.group(2)) / 2) > 0.05:
        problem(f"docs/studies.md: {wall:g} hours on 2 cores is not half of {total.group(2)} core-hours")
    for path in ("README.md", "pipelines/README.md", "pipelines/workstation/Makefile",
                 "pipelines/scales/workstation.mk", "tests/cli/readme_commands.py"):
        said = re.search(r"afternoon|hour or two|\b\d(\.\d+)?\s*[-–]\s*\d(\.\d+)?\s*(h|hours)\b|[0-9.]+ core-hours planned",
                         read(source, path))
        if said:
            problem(f"{path}: states the workstation's duration ('{said.group(0)}'): docs/studies.md alone does")


def main():
    source, bin_dir, scratch = sys.argv[1:4]
    os.makedirs(scratch, exist_ok=True)
    check_aggregation_limit(source, bin_dir)
    check_aggregation_times(source, bin_dir, scratch)
    check_workstation_plan(source, bin_dir, scratch)
    print(f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
