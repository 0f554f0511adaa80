#!/usr/bin/env python3
"""Strong scaling on 1 and 2 MPI processes, per linear solver.

Runs shortened shipped scenes with mpirun -np P (P = 1 and 2 by default)
and each linear solver (KLU, MUMPS, GMRES), repeats every run and keeps the
median, and reads from each run's TimerOutput table where the time goes.

  python3 benchmarks/parallel_scaling.py [--processes 1 2] [--repeats 3]
      [--only hertz,ironing,bouncing_block] [--solvers KLU,MUMPS,GMRES]

Writes benchmarks/results/parallel_scaling.csv (one row per run) and
doc/parallel-scaling-table.md (medians, speed-ups and shares); prints the
table. Scenes and their length:
  hertz           prm/examples/hertz.prm as shipped (quasi-static, 4 steps,
                  13586 cells, a big volume and a small contact surface)
  ironing         prm/ironing/mortar.prm to t = 0.2 (20 steps, 8176 cells)
  bouncing_block  prm/bouncing_block/mortar_stabilized.prm to t = 1 (40
                  steps, 590 cells: too small to gain from a second process)
  bouncing_block_3d  prm/bouncing_block/mortar_3d.prm to t = 0.3 (12 steps,
                  5900 cells, 44,286 unknowns; first contact at 0.225 s);
                  run with --solvers AMG (the 3-D table of doc/benchmarks.md:
                  --only bouncing_block_3d --solvers AMG
                  --table doc/bouncing-block-3d-table.md
                  --csv benchmarks/results/bouncing_block_3d.csv)
  ironing_3d      prm/ironing/mortar_3d.prm to t = 1.3 (the indentation and
                  0.3 of sliding, 1788 cells, 15,906 unknowns); the 3-D
                  contact share (--only ironing_3d --solvers KLU,AMG
                  --table doc/ironing-3d-table.md
                  --csv benchmarks/results/ironing_3d.csv)
VTU output is off: the measurements are of the solver.
"""
import argparse
import csv
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_common  # noqa: E402  (parameter files with changed entries)

REPO = Path(__file__).resolve().parent.parent
SCENES = {
    "hertz": ("prm/examples/hertz.prm", None),
    "ironing": ("prm/ironing/mortar.prm", 0.2),
    "bouncing_block": ("prm/bouncing_block/mortar_stabilized.prm", 1.0),
    "bouncing_block_3d": ("prm/bouncing_block/mortar_3d.prm", 0.3),
    "ironing_3d": ("prm/ironing/mortar_3d.prm", 1.3),
}
SECTIONS = ["bulk assembly", "contact search", "contact assembly",
            "linear solve", "energies", "output"]


def write_prm(path, scene, solver, directory):
    source, end_time = SCENES[scene]
    changes = {"Nonlinear solver/Linear solver": solver,
               "Output/Output directory": directory,
               "Output/VTU interval": 0}
    if end_time is not None:
        changes["Time integration/End time"] = end_time
    bench_common.write_prm(path, REPO / source, changes)


def parse(log):
    """Seconds per timer section, total, steps, Newton iterations."""
    return bench_common.parse_run_log(log, SECTIONS)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--processes", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--only", default=",".join(SCENES))
    ap.add_argument("--solvers", default="KLU,MUMPS,GMRES")
    ap.add_argument("--exe", type=Path, default=REPO / "build" / "contact-dynamics")
    ap.add_argument("--results", type=Path, default=REPO / "benchmarks" / "results")
    ap.add_argument("--table", type=Path, default=REPO / "doc" / "parallel-scaling-table.md")
    ap.add_argument("--csv", type=Path, default=None,
                    help="one row per run (default: RESULTS/parallel_scaling.csv)")
    args = ap.parse_args()
    if not args.exe.is_file():
        sys.exit(f"{args.exe} is missing: build it first (./run.sh build)")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    work = args.results / "parallel_scaling"
    work.mkdir(parents=True, exist_ok=True)
    # peak memory of each process, where GNU time is installed
    timer = ["/usr/bin/time", "-f", "maxrss_kb %M"] if os.path.exists("/usr/bin/time") else []
    rows = []
    started = time.time()
    for scene in args.only.split(","):
        for solver in args.solvers.split(","):
            for np_ in args.processes:
                for r in range(args.repeats):
                    name = f"{scene}_{solver}_np{np_}_{r}"
                    prm = work / f"{name}.prm"
                    write_prm(prm, scene, solver, work / name)
                    cmd = ["mpirun", "-np", str(np_)] + timer + [str(args.exe), str(prm)]
                    t0 = time.time()
                    p = subprocess.run(cmd, cwd=work, env=env, capture_output=True, text=True)
                    wall = time.time() - t0
                    (work / f"{name}.log").write_text(p.stdout + p.stderr)
                    info = parse(p.stdout)
                    rss = [int(x) for x in re.findall(r"maxrss_kb (\d+)", p.stderr)]
                    row = dict(scene=scene, solver=solver, processes=np_, repeat=r,
                               process_wall_s=round(wall, 3), status="ok" if p.returncode == 0 else "failed",
                               steps=info.get("steps", ""), newton=info.get("newton", ""),
                               total_s=info.get("total", ""),
                               peak_memory_per_process_mb=round(max(rss) / 1024, 1) if rss else "")
                    for s in SECTIONS:
                        row[s.replace(" ", "_") + "_s"] = info.get(s, 0.0)
                    rows.append(row)
                    print(f"[{time.time() - started:6.0f} s] {name}: {row['status']}, "
                          f"{row['total_s']} s, {row['newton']} Newton iterations", flush=True)
    with open(args.csv or args.results / "parallel_scaling.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)

    def median(scene, solver, np_, key):
        vals = [float(r[key]) for r in rows if r["scene"] == scene and r["solver"] == solver
                and r["processes"] == np_ and r["status"] == "ok" and r[key] != ""]
        return statistics.median(vals) if vals else float("nan")

    out = ["| scene | solver | processes | steps | Newton its | wall per step (s), median | speed-up vs 1 process | vs KLU on 1 process | bulk assembly | contact (search + assembly) | linear solve | peak memory per process (MB) |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for scene in args.only.split(","):
        base_klu = None
        for solver in args.solvers.split(","):
            base = None
            for np_ in args.processes:
                total = median(scene, solver, np_, "total_s")
                steps = median(scene, solver, np_, "steps")
                newton = median(scene, solver, np_, "newton")
                per_step = total / steps if steps == steps and steps > 0 else float("nan")
                if np_ == args.processes[0]:
                    base = per_step
                    if solver == "KLU":
                        base_klu = per_step
                shares = []
                for keys in (["bulk_assembly_s"], ["contact_search_s", "contact_assembly_s"],
                             ["linear_solve_s"]):
                    part = sum(median(scene, solver, np_, k) for k in keys)
                    shares.append(f"{100 * part / total:.1f} %" if total > 0 else "-")
                out.append(f"| {scene} | {solver} | {np_} | {steps:.0f} | {newton:.0f} | {per_step:.4g} | "
                           f"{base / per_step:.2f} | "
                           f"{(base_klu / per_step) if base_klu else float('nan'):.2f} | "
                           + " | ".join(shares)
                           + f" | {median(scene, solver, np_, 'peak_memory_per_process_mb'):.0f} |")
    load = os.getloadavg()
    text = ("<!-- generated by benchmarks/parallel_scaling.py; do not edit -->\n"
            f"Medians of {args.repeats} runs each, {os.cpu_count()} cores, load average at the end "
            f"{load[0]:.2f}; {time.strftime('%Y-%m-%d')}. Shares are of the total wall time "
            "(TimerOutput, maximum over processes).\n\n" + "\n".join(out) + "\n")
    args.table.write_text(text)
    print(text)


if __name__ == "__main__":
    main()
