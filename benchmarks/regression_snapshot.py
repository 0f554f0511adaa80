#!/usr/bin/env python3
"""Outputs of every shipped parameter file, shortened to a few steps, for a
bitwise comparison before and after a change that must not change results
(a restructuring, issue 38).

    regression_snapshot.py run SNAPSHOT [--steps N] [--exe PATH] [--match S]
        run every prm/**/*.prm for N time steps (default 8; fewer if the
        file ends earlier; --skip-done keeps the cases SNAPSHOT has): on one process
        with a checkpoint every N/2 steps and the output of every step,
        and on two processes; then
        restart the one-process run from its step-N/2 checkpoint. Each run's
        statistics.csv (without its wall_time column), contact_history.csv
        and contact_surface-*.csv go to SNAPSHOT/<file>/<run>/, the
        step-N/2 checkpoint to SNAPSHOT/<file>/checkpoint/.
    regression_snapshot.py restart OLD NEW [--exe PATH] [--match S]
        restart the checkpoints that an earlier build wrote into OLD (with
        this build) and put the outputs into NEW/<file>/restart/: checks
        that checkpoints of the earlier build still load, and continue to
        the same numbers (checkpoints of a build before issue 39 have no
        checksum list and are refused: compare within builds since).
    (issue 39 added the statistics column energy_created: against older
    outputs, compare with --ignore-columns energy_created)
    regression_snapshot.py compare OLD NEW [--ignore-columns A,B]
        list the files that differ (CSV files without the named columns,
        which a change added on purpose); exit status 1 if any does.

Run from the repository root; the executable defaults to
build/contact-dynamics.
"""
import argparse
import csv
import filecmp
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_common import read_prm, write_prm  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}
UNTIMED = ("wall_time",)


def shipped(match):
    files = sorted((ROOT / "prm").rglob("*.prm"))
    return [f for f in files if not match or match in str(f.relative_to(ROOT))]


def copy_outputs(run_dir, target):
    """The compared outputs of a run, statistics.csv without wall times."""
    target.mkdir(parents=True, exist_ok=True)
    for f in sorted(run_dir.glob("*.csv")):
        if f.name == "statistics.csv":
            with open(f, newline="") as src:
                rows = list(csv.reader(src))
            keep = [i for i, n in enumerate(rows[0])
                    if n.split("(")[0].strip() not in UNTIMED] if rows else []
            with open(target / f.name, "w", newline="") as dst:
                csv.writer(dst).writerows([[r[i] for i in keep if i < len(r)] for r in rows])
        else:
            shutil.copy(f, target / f.name)


def execute(command, log, env_extra=None):
    env = dict(os.environ, **(env_extra or {}))
    with open(log, "w") as out:
        status = subprocess.call(command, stdout=out, stderr=subprocess.STDOUT,
                                 cwd=ROOT, env=env)
    return status


def case_name(prm):
    return str(prm.relative_to(ROOT / "prm")).replace("/", "_")[:-4]


def run_file(prm, snapshot, exe, steps):
    name = case_name(prm)
    values = read_prm(prm)
    dt = float(values.get("Time integration/Time step", "0.025"))
    # never beyond the file's own end (a quasi-static load ends there)
    end = min(steps * dt, float(values.get("Time integration/End time", "1")))
    steps = max(1, round(end / dt))
    half = max(1, steps // 2)
    target = snapshot / name
    if target.exists():
        shutil.rmtree(target)
    target.mkdir(parents=True)
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        runs = {"serial": ([str(exe)], {"Output/Checkpoint interval": half}),
                "mpirun2": (["mpirun", "-np", "2", str(exe)], {})}
        for run, (command, extra) in runs.items():
            out = work / run
            changes = {"Time integration/End time": repr(end),
                       "Output/Output directory": str(out),
                       # every step: contact_surface-*.csv come with VTU files
                       "Output/VTU interval": 1, **extra}
            wrapper = work / f"{run}.prm"
            write_prm(wrapper, prm, changes)
            status = execute(command + [str(wrapper)], work / f"{run}.log", MPI_ENV)
            (target / run).mkdir()
            (target / run / "exit_status").write_text(f"{status}\n")
            if out.exists():
                copy_outputs(out, target / run)
            if run == "serial":
                checkpoints = sorted((out / "checkpoints").glob("step-*")) if out.exists() else []
                first = [c for c in checkpoints if not c.name.endswith(".part")][:1]
                if first:
                    saved = target / "checkpoint"
                    saved.mkdir()
                    for f in ("statistics.csv", "contact_history.csv", "parameters.prm"):
                        if (out / f).exists():
                            shutil.copy(out / f, saved / f)
                    shutil.copytree(first[0], saved / "checkpoints" / first[0].name)
                    shutil.copy(wrapper, saved / "run.prm")
        restart_from(target / "checkpoint", target / "restart", exe)
    statuses = [(target / r / "exit_status").read_text().strip() for r in ("serial", "mpirun2")]
    print(f"{name}: dt {dt}, {steps} steps, exit status {' '.join(statuses)}", flush=True)


def restart_from(saved, target, exe):
    """Continue a saved checkpoint (a copy of it: the restart writes into
    its directory) to the end time of its run."""
    if not saved.exists():
        return
    with tempfile.TemporaryDirectory() as work:
        work = Path(work) / "run"
        shutil.copytree(saved, work)
        # the saved run.prm writes into the run's original directory
        text = (saved / "run.prm").read_text().splitlines()
        text = [f"  set Output directory = {work}" if "Output directory" in line else line
                for line in text]
        (work / "run.prm").write_text("\n".join(text) + "\n")
        status = execute([str(exe), "--restart", str(work), str(work / "run.prm")],
                         work.parent / "restart.log")
        target.mkdir(parents=True, exist_ok=True)
        (target / "exit_status").write_text(f"{status}\n")
        copy_outputs(work, target)


def without_columns(path, ignored):
    """The rows of a CSV file without the named columns."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    keep = [i for i, n in enumerate(rows[0]) if n not in ignored] if rows else []
    return [[r[i] for i in keep if i < len(r)] for r in rows]


def same(a, b, ignored):
    if ignored and a.suffix == ".csv":
        return without_columns(a, ignored) == without_columns(b, ignored)
    return filecmp.cmp(a, b, shallow=False)


def compare(old, new, ignored=()):
    differ = []
    for dirpath, _, files in os.walk(old):
        for f in files:
            a = Path(dirpath) / f
            rel = a.relative_to(old)
            if rel.parts[1:2] == ("checkpoint",):
                continue
            b = new / rel
            if not b.exists() or not same(a, b, ignored):
                differ.append(str(rel))
    for dirpath, _, files in os.walk(new):
        for f in files:
            rel = (Path(dirpath) / f).relative_to(new)
            if rel.parts[1:2] != ("checkpoint",) and not (old / rel).exists():
                differ.append(f"{rel} (new)")
    for d in sorted(differ):
        print("differs:", d)
    print(f"{len(differ)} files differ" if differ else "all outputs identical")
    return 1 if differ else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("command", choices=["run", "restart", "compare"])
    parser.add_argument("dirs", nargs="+")
    parser.add_argument("--steps", type=int, default=8)
    parser.add_argument("--exe", default=str(ROOT / "build" / "contact-dynamics"))
    parser.add_argument("--match", default="")
    parser.add_argument("--skip-done", action="store_true",
                        help="keep the cases SNAPSHOT has already")
    parser.add_argument("--ignore-columns", default="",
                        help="compare: CSV columns (comma-separated) a change "
                        "added on purpose, left out of the comparison")
    args = parser.parse_args()
    dirs = [Path(d).resolve() for d in args.dirs]
    exe = Path(args.exe).resolve()
    if args.command == "compare":
        return compare(*dirs[:2], tuple(filter(None, args.ignore_columns.split(","))))
    if args.command == "restart":
        old, new = dirs[:2]
        for case in sorted(p for p in old.iterdir() if (p / "checkpoint").exists()):
            if args.match and args.match not in case.name:
                continue
            restart_from(case / "checkpoint", new / case.name / "restart", exe)
            print(f"{case.name}: restarted", flush=True)
        return 0
    for prm in shipped(args.match):
        if args.skip_done and (dirs[0] / case_name(prm) / "mpirun2" / "exit_status").exists():
            continue
        run_file(prm, dirs[0], exe, args.steps)
    return 0


if __name__ == "__main__":
    sys.exit(main())
