"""Runs every shell command of README.md, pipelines/README.md and docs/*.md,
so that a documented example cannot rot. Usage: readme_commands.py SOURCE_DIR BIN_DIR SCRATCH_DIR

Commands are taken from the Markdown code blocks: a fenced ```sh block is one
script; each line of an indented block is one command. Each runs with /bin/sh
in SCRATCH_DIR, where build/bin links to BIN_DIR, BIN_DIR is on PATH and
GNUTERM=dumb (gnuplot without a display), pipelines links to the source's
pipelines/, and must exit 0. Small inputs stand
in where a command names files it does not make itself:
  out/demo/runs/size_L<L>_s<seed>.h5  what `make demo` leaves there (the
                   names are checked against the demo pipeline with make -n):
                   tiny real runs (phi = 0.208, r0 = 0.1, delta = 1e-4, to
                   t = 1e5) of L = 12, 16, 20 under the names of the demo's
                   L = 34, 48, 68, seeds 1 and 2 (a weighted collapse needs
                   two runs per L).
A line that is not run is either a synopsis (it holds [OPTIONS] in brackets
or NAME... placeholders) or in SKIPPED below with the reason; any other line
must run, so a new example is run from the day it is written."""
import glob
import os
import re
import subprocess
import sys

SKIPPED = {
    "make demo": "the whole demo pipeline: about 30 minutes of simulation (tests/cli/pipeline_test.cc runs the same recipes at SCALE=tiny)",
    "make test": "the whole test suite, of which this test is a part",
    "make -C pipelines/demo -j2": "the demo pipeline: about 30 minutes (the recipes run at SCALE=tiny in tests/cli/pipeline_test.cc)",
    "make -C pipelines/demo reanalyze": "needs an archive of demo runs; tests/cli/pipeline_test.cc runs reanalyze from the tiny runs",
    "make -C pipelines/paper -j": "the paper scale: hundreds of core-hours on a cluster (srun)",
    "make -C pipelines/workstation estimate": "the workstation's plan: a pilot of each of its 53 runs, minutes of CPU under load; tests/cli/docs_agree.py runs it and compares its totals with the docs",
    "make -C pipelines/workstation -j": "the workstation scale: hours on 2 cores, as its plan in docs/studies.md says (tests/cli/docs_agree.py runs the plan, make -C pipelines/workstation estimate)",
    "sbatch pipelines/cluster/paper.sbatch": "needs a Slurm cluster: ctest Slurm.* runs it on one (tests/cli/slurm_cluster_test.sh)",
    "sbatch --ntasks=2": "needs a Slurm cluster: ctest Slurm.* runs it on one (tests/cli/slurm_cluster_test.sh)",
    "j=$(sbatch": "a chain of paper-scale jobs on a Slurm cluster: ctest Slurm.* runs such a chain at SCALE=tiny",
    "sh pipelines/cluster/submit-runs.sh": "submits the paper scale to a Slurm cluster: ctest Slurm.* runs it at SCALE=tiny",
    "MAX_TIME=720 sh pipelines/cluster/submit-runs.sh": "submits the paper scale to a Slurm cluster: ctest Slurm.* runs its dry run with MAX_TIME=720",
    "make install": "installs into PREFIX; tests/cli/installed_tree.sh (ctest InstalledTree.*) installs into a fresh prefix and runs the pages, completion and pipelines there",
    "sh pipelines/readme-headline.sh": "rewrites README.md of the source tree; ctest Readme.HeadlineTableIsTheValidationTables runs it on a copy",
    "sh pipelines/readme-table.sh": "needs a pipeline's exponents.md and rewrites a document of the source tree; tests/cli/pipeline_scripts_cli_test.cc runs it on stand-ins",
    "make -C pipelines/dimensions -j2": "the dimension study: about an hour on 2 cores (tests/cli/pipeline_test.cc runs its recipes with PARAMETERS=tiny.mk)",
    "make -C pipelines/effects": "the effects pipeline: under a minute on 2 cores, as much again in CPU (tests/cli/pipeline_test.cc runs its recipes with PARAMETERS=tiny.mk)",
    "make -C pipelines/accuracy": "about 10 minutes of simulation (QUICK=1: under a minute); its recipes are plain coolgas commands tested elsewhere",
}


def blocks(path):
    """(line number, script) for each command of the file."""
    lines = open(path, encoding="utf-8").read().split("\n")
    out, fence, start, prev_blank = [], None, 0, True
    for i, line in enumerate(lines):
        if line.startswith("```"):
            if fence is None:
                fence, start = [], i + 2
                lang = line[3:].strip()
            else:
                if lang in ("sh", "bash", ""):
                    out.append((start, "\n".join(fence)))
                fence = None
            continue
        if fence is not None:
            fence.append(line)
        elif line.startswith("    ") and not line.startswith("     ") and (prev_blank or lines[i - 1].startswith("    ")):
            out.append((i + 1, line.strip()))
        prev_blank = line.strip() == ""
    return out


def is_synopsis(command):
    """A one-line usage summary: options in brackets, or "..." for more."""
    text = command.split("#")[0]
    return "\n" not in command and (re.search(r"\[--?[A-Za-z]", text) is not None or "..." in text)


def skip_reason(command):
    for prefix, why in SKIPPED.items():
        if command.startswith(prefix):
            return why
    return None


def make_runs(source, bin_dir, scratch):
    runs = os.path.join(scratch, "out", "demo", "runs")
    os.makedirs(runs, exist_ok=True)
    for demo_L, L in ((34, 12), (48, 16), (68, 20)):
        for seed in (1, 2):
            name = f"size_L{demo_L}_s{seed}.h5"
            # the demo pipeline makes a file of this name (make -n: its recipe, nothing run)
            r = subprocess.run(["make", "-n", "-C", os.path.join(source, "pipelines", "demo"), f"BIN={bin_dir}",
                                f"OUT={scratch}/out/demo", f"{runs}/{name}"], capture_output=True, text=True)
            if r.returncode != 0 or "coolgas-simulate" not in r.stdout:
                sys.exit(f"the demo pipeline makes no {name}: {r.stderr[-500:]}")
            sets = f"--set system.L={L} --set system.phi=0.208 --set system.seed={seed} --set run.t_end=1e5 " \
                   "--set collision.model=inelastic --set collision.r0=0.1 --set collision.delta=1e-4"
            subprocess.run(f"{bin_dir}/coolgas-simulate -q {sets} -o {runs}/{name} /dev/null",
                           shell=True, cwd=scratch, check=True)


def main():
    source, bin_dir, scratch = sys.argv[1:4]
    os.makedirs(os.path.join(scratch, "build"), exist_ok=True)
    link = os.path.join(scratch, "build", "bin")
    if not os.path.exists(link):
        os.symlink(bin_dir, link)
    if not os.path.exists(os.path.join(scratch, "pipelines")):
        os.symlink(os.path.join(source, "pipelines"), os.path.join(scratch, "pipelines"))
    for script in ("paper.sbatch", "run.sbatch", "submit-runs.sh"):
        subprocess.run(["sh", "-n", os.path.join(source, "pipelines/cluster", script)], check=True)
    make_runs(source, bin_dir, scratch)
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"], GNUTERM="dumb")
    failed = ran = 0
    docs = ["README.md", "pipelines/README.md"] + sorted(
        os.path.relpath(p, source) for p in glob.glob(os.path.join(source, "docs", "*.md")))
    for doc in docs:
        for line, command in blocks(os.path.join(source, doc)):
            where = f"{doc}:{line}"
            if is_synopsis(command):
                print(f"{where}: synopsis, not run: {command[:60]}")
                continue
            why = skip_reason(command)
            if why:
                print(f"{where}: skipped ({why}): {command[:60]}")
                continue
            r = subprocess.run(command, shell=True, cwd=scratch, env=env, capture_output=True, text=True,
                               executable="/bin/sh")
            ran += 1
            if r.returncode != 0:
                failed += 1
                print(f"{where}: FAILED (exit {r.returncode}): {command}\n{r.stderr[-2000:]}")
            else:
                print(f"{where}: ran: {command[:60]}")
    print(f"{ran} commands run, {failed} failed")
    return 1 if failed or ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
