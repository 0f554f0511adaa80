#!/usr/bin/env python3
"""Whole runs split into setup and steps, against the number of unknowns.

Issue 40: a setup that grows faster than the problem hides behind
per-iteration figures. This runs the shipped ironing (2-D at Refinement
factors 1-4, 3-D at three sizes) for three steps with the distributed mesh
and the AMG solver, on 1 and 2 MPI processes, and splits each run's wall
time (process start to exit) into the TimerOutput's `setup` (mesh, dofs,
sparsity with the condensation's fill-in, contact surfaces), `initial
conditions` (initial acceleration, contact check) and `Newton solve`, and
the rest (library loading, mesh creation, parameter reading, output).
A second run writes a checkpoint after its third step (TimerOutput
`checkpoint`: the write and the reload that makes the run continue exactly
as a restart would), a third reads it back (`--restart` with one more step:
its whole run less that step's Newton solve) and a fourth run of the same scene adapts the mesh to the
contact (one level; TimerOutput `mesh adaptation` per mesh change: marking,
refinement, the transfer of every field and the new setup).

  python3 benchmarks/setup_scaling.py [--processes 1 2] [--repeats 1]
      [--factors-2d 1 2 3 4] [--factors-3d 1 1.5 2]

Writes benchmarks/results/setup_scaling.csv (one row per run) and
doc/setup-scaling-table.md (medians; setup per unknown and the growth
exponent of setup between consecutive sizes: 1 is linear, 2 quadratic).
"""
import argparse
import csv
import math
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_common  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
SCENES = {"2-D": ("prm/ironing/mortar.prm", 0.03),
          "3-D": ("prm/ironing/mortar_3d.prm", None)}
SECTIONS = ["setup", "initial conditions", "Newton solve", "checkpoint",
            "mesh adaptation"]


def parse(log):
    """Seconds per timer section, total, steps, Newton iterations."""
    return bench_common.parse_run_log(log, SECTIONS)


def run_one(args, work, dim, factor, np_, repeat, env):
    source, end_time = SCENES[dim]
    name = f"{dim}_f{factor}_np{np_}_{repeat}"
    prm = work / f"{name}.prm"
    changes = {"Scene/Refinement factor": factor,
               "Parallel/Mesh": "distributed",
               "Nonlinear solver/Linear solver": "AMG",
               "Output/Output directory": str(work / name),
               "Output/VTU interval": 0}
    # three steps: the 2-D ironing's dt is 0.01; the 3-D file's own
    base = bench_common.prm_values(REPO / source, {})
    dt = float(base.get("Time integration/Time step", 0.01))
    changes["Time integration/End time"] = end_time if end_time else 3 * dt
    bench_common.write_prm(prm, REPO / source, changes)

    def timed(command, log_name):
        t0 = time.time()
        p = subprocess.run(["mpirun", "-np", str(np_), str(args.exe)] + command,
                           cwd=work, env=env, capture_output=True, text=True)
        (work / log_name).write_text(p.stdout + p.stderr)
        return p, time.time() - t0

    p, wall = timed([str(prm)], f"{name}.log")
    info = parse(p.stdout)
    row = dict(scene=dim, factor=factor, processes=np_, repeat=repeat,
               status="ok" if p.returncode == 0 else "failed",
               unknowns=info.get("unknowns", ""), steps=info.get("steps", ""),
               process_wall_s=round(wall, 3), timer_total_s=info.get("total", ""))
    for s in SECTIONS[:3]:
        row[s.replace(" ", "_") + "_s"] = info.get(s, 0.0)
    # the same run writing a checkpoint after its third step (its own run:
    # the write reloads the checkpoint, whose setup would count as setup)
    checkpointed = work / f"{name}_checkpoint.prm"
    bench_common.write_prm(checkpointed, REPO / source,
                           {**changes, "Output/Checkpoint interval": 3,
                            "Output/Output directory": str(work / f"{name}_checkpoint")})
    p, wall = timed([str(checkpointed)], f"{name}_checkpoint.log")
    row["checkpoint_s"] = parse(p.stdout).get("checkpoint", "") if p.returncode == 0 else ""
    # the checkpoint read back, and one more step (a restart needs a later
    # End time), whose Newton solve is not counted
    restart_prm = work / f"{name}_restart.prm"
    bench_common.write_prm(restart_prm, REPO / source,
                           {**changes, "Output/Checkpoint interval": 3,
                            "Output/Output directory": str(work / f"{name}_checkpoint"),
                            "Time integration/End time":
                            4 / 3 * float(changes["Time integration/End time"])})
    p, wall = timed(["--restart", str(work / f"{name}_checkpoint"), str(restart_prm)],
                    f"{name}_restart.log")
    row["restart_wall_s"] = (round(wall - parse(p.stdout).get("Newton solve", 0.), 3)
                             if p.returncode == 0 else "")
    # the same scene with a mesh that follows the contact
    adaptive = work / f"{name}_adaptive.prm"
    changes.update({"Mesh refinement/Adapt to contact": "true",
                    "Mesh refinement/Maximum levels": 1,
                    "Output/Output directory": str(work / f"{name}_adaptive")})
    bench_common.write_prm(adaptive, REPO / source, changes)
    p, wall = timed([str(adaptive)], f"{name}_adaptive.log")
    info = parse(p.stdout)
    row["adaptive_status"] = "ok" if p.returncode == 0 else "failed"
    # (the section also times the marking of steps that change nothing)
    row["mesh_adaptation_s"] = info.get("mesh adaptation", 0.0)
    row["mesh_adaptation_calls"] = row["adaptive_final_unknowns"] = ""
    stats = work / f"{name}_adaptive" / "statistics.csv"
    if stats.is_file():
        last = list(csv.DictReader(open(stats)))[-1]
        row["mesh_adaptation_calls"] = last.get("mesh_changes", "")
        row["adaptive_final_unknowns"] = last.get("unknowns", "")
    return row


def table(rows, args):
    def median(dim, factor, np_, key):
        vals = [float(r[key]) for r in rows
                if (r["scene"], r["factor"], r["processes"]) == (dim, factor, np_)
                and r["status"] == "ok" and r.get(key, "") != ""]
        return statistics.median(vals) if vals else float("nan")

    def exponent(previous, n, value):
        """Growth exponent of `value` from the previous size: 1 linear."""
        if previous and previous[1] > 0 and value > 0 and n > previous[0]:
            return f"{math.log(value / previous[1]) / math.log(n / previous[0]):.2f}"
        return "-"

    out = ["| scene | factor | unknowns | processes | whole run (s) | setup (s) | setup per unknown (us) | growth exponent of setup | initial conditions (s) | Newton solves, 3 steps (s) | rest (s) |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    second = ["", "Per checkpoint and per mesh change (the same scenes; a checkpoint write "
              "includes the reload that makes the run continue as a restart would; the "
              "adaptive runs refine one level near the contact, so their meshes are larger; "
              "the 3-D tool touches nothing in three steps, so its mesh does not change):", "",
              "| scene | factor | unknowns | processes | checkpoint write (s) | write per unknown (us) | "
              "restart: whole run less its one step (s) | mesh changes | mesh adaptation per change (s) | per change and unknown after it (us) | "
              "growth exponent per change |",
              "|---|---|---|---|---|---|---|---|---|---|---|"]
    for dim, factors in (("2-D", args.factors_2d), ("3-D", args.factors_3d)):
        for np_ in args.processes:
            previous = previous_change = None
            for f in factors:
                def m(key):
                    return median(dim, f, np_, key)
                n, setup = m("unknowns"), m("setup_s")
                wall, init, newton = m("process_wall_s"), m("initial_conditions_s"), m("Newton_solve_s")
                out.append(f"| {dim} | {f:g} | {n:,.0f} | {np_} | {wall:.3g} | {setup:.3g} | "
                           f"{1e6 * setup / n:.3g} | {exponent(previous, n, setup)} | {init:.3g} | "
                           f"{newton:.3g} | {wall - setup - init - newton:.3g} |")
                previous = (n, setup)
                write, calls = m("checkpoint_s"), m("mesh_adaptation_calls")
                per_change = "- | - | -"
                if calls > 0:
                    change, n_after = m("mesh_adaptation_s") / calls, m("adaptive_final_unknowns")
                    per_change = (f"{change:.3g} | {1e6 * change / n_after:.3g} | "
                                  f"{exponent(previous_change, n_after, change)}")
                    previous_change = (n_after, change)
                second.append(f"| {dim} | {f:g} | {n:,.0f} | {np_} | {write:.3g} | "
                              f"{1e6 * write / n:.3g} | {m('restart_wall_s'):.3g} | {calls:.0f} | "
                              f"{per_change} |")
    out += second
    load = os.getloadavg()
    return ("<!-- generated by benchmarks/setup_scaling.py; do not edit -->\n"
            f"Medians of {args.repeats} run(s) each, {os.cpu_count()} cores, load average at "
            f"the end {load[0]:.2f}; {time.strftime('%Y-%m-%d')}. Whole run: process start "
            "to exit under mpirun; sections from TimerOutput (maximum over processes); "
            "rest: library loading, parameters, mesh creation, output.\n\n"
            + "\n".join(out) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--processes", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--factors-2d", type=float, nargs="+", default=[1, 2, 3, 4])
    ap.add_argument("--factors-3d", type=float, nargs="+", default=[1, 1.5, 2])
    ap.add_argument("--exe", type=Path, default=REPO / "build" / "contact-dynamics")
    ap.add_argument("--results", type=Path, default=REPO / "benchmarks" / "results")
    ap.add_argument("--table", type=Path, default=REPO / "doc" / "setup-scaling-table.md")
    args = ap.parse_args()
    if not args.exe.is_file():
        sys.exit(f"{args.exe} is missing: build it first (./run.sh build)")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    work = args.results / "setup_scaling"
    work.mkdir(parents=True, exist_ok=True)
    rows, started = [], time.time()
    for dim, factors in (("2-D", args.factors_2d), ("3-D", args.factors_3d)):
        for f in factors:
            for np_ in args.processes:
                for r in range(args.repeats):
                    row = run_one(args, work, dim, f, np_, r, env)
                    rows.append(row)
                    print(f"[{time.time() - started:6.0f} s] {dim} factor {f:g}, {np_} process(es): "
                          f"{row['status']}, {row['unknowns']} unknowns, whole run "
                          f"{row['process_wall_s']} s, setup {row['setup_s']} s, restart "
                          f"{row['restart_wall_s']} s, {row['mesh_adaptation_calls']} mesh changes "
                          f"{row['mesh_adaptation_s']} s", flush=True)
    with open(args.results / "setup_scaling.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    text = table(rows, args)
    args.table.write_text(text)
    print(text)


if __name__ == "__main__":
    main()
