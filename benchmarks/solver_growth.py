#!/usr/bin/env python3
"""How the cost of a Newton iteration grows with the problem and divides
with processes (issue 16): weak growth over refinement factors, strong
scaling over processes, and the largest run.

  python3 benchmarks/solver_growth.py weak   [--scenes ironing,hertz]
      [--factors 1,2,4] [--solvers AMG,UMFPACK] [--repeats 1]
  python3 benchmarks/solver_growth.py strong [--scenes ironing]
      [--factors 3] [--solvers AMG] [--processes 1 2] [--repeats 3]
  python3 benchmarks/solver_growth.py largest --scenes ironing --factors 8

Every run uses Parallel/Mesh = distributed, VTU output off, and a few steps
(ironing: to t = 0.03, 3 steps of the pressing phase; hertz: the shipped 4
quasi-static load steps). Per run it records the unknowns (from the log),
Newton and Krylov iterations (statistics.csv), the TimerOutput sections
(maximum over processes), and the peak resident memory of each process
(GNU time). Writes benchmarks/results/solver_growth_MODE.csv and
doc/solver-growth-MODE-table.md, and prints the table.
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
import bench_common  # noqa: E402
from parallel_scaling import parse  # noqa: E402  (the TimerOutput table)
from unit_costs import timer_table  # noqa: E402  (every section: calls, seconds)

REPO = Path(__file__).resolve().parent.parent
SCENES = {"ironing": ("prm/ironing/mortar.prm", 0.03),
          "hertz": ("prm/examples/hertz.prm", None)}


def run(args, scene, solver, factor, np_, repeat, work, env):
    name = f"{scene}_{solver}_f{factor}_np{np_}_{repeat}"
    source, end_time = SCENES[scene]
    changes = {"Nonlinear solver/Linear solver": solver,
               "Scene/Refinement factor": factor,
               "Parallel/Mesh": "distributed",
               "Output/Output directory": str(work / name),
               "Output/VTU interval": 0}
    if end_time is not None:
        changes["Time integration/End time"] = end_time
    prm = work / f"{name}.prm"
    bench_common.write_prm(prm, REPO / source, changes)
    timer = ["/usr/bin/time", "-f", "maxrss_kb %M"] if os.path.exists("/usr/bin/time") else []
    cmd = ["mpirun", "-np", str(np_)] + timer + [str(args.exe), str(prm)]
    log = work / f"{name}.log"
    if args.reuse and log.is_file() and "Finished at" in log.read_text():
        text, returncode = log.read_text(), 0
    else:
        p = subprocess.run(cmd, cwd=work, env=env, capture_output=True, text=True)
        text, returncode = p.stdout + p.stderr, p.returncode
        log.write_text(text)
    info = parse(text)
    m = re.search(r"(\d+) cells, (\d+) unknowns", text)
    rss = [int(x) for x in re.findall(r"maxrss_kb (\d+)", text)]
    krylov = 0
    stats = work / name / "statistics.csv"
    if stats.is_file():
        names, values = bench_common.read_csv_rows(stats)
        col = names.index("linear_iterations")
        krylov = sum(float(r[col]) for r in values[1:])
    newton = info.get("newton", 0)
    sections = timer_table(text)
    # per Newton iteration: the Newton solves only (not the setup, the
    # initial acceleration, the output)
    newton_s = sections.get("Newton solve", (0, 0.0))[1]
    row = dict(scene=scene, solver=solver, factor=factor, processes=np_, repeat=repeat,
               status="ok" if returncode == 0 else "failed",
               cells=int(m.group(1)) if m else "", unknowns=int(m.group(2)) if m else "",
               newton=newton, krylov_per_newton=round(krylov / newton, 2) if newton else "",
               total_s=info.get("total", ""),
               s_per_newton=round(newton_s / newton, 4) if newton and newton_s else "",
               setup_s=sections.get("setup", (0, 0.0))[1],
               initial_s=sections.get("initial conditions", (0, 0.0))[1],
               peak_mb_per_process=round(max(rss) / 1024, 1) if rss else "",
               total_mb=round(sum(rss) / 1024, 1) if rss else "")
    for s in ("bulk assembly", "contact assembly", "linear solve", "condensation"):
        row[s.replace(" ", "_") + "_s"] = sections.get(s, (0, 0.0))[1]
    print(f"{name}: {row['status']}, {row['unknowns']} unknowns, {row['total_s']} s, "
          f"{newton} Newton, {row['krylov_per_newton']} Krylov/Newton, "
          f"{row['peak_mb_per_process']} MB", flush=True)
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mode", choices=["weak", "strong", "largest"])
    ap.add_argument("--scenes", default="ironing,hertz")
    ap.add_argument("--factors", default=None)
    ap.add_argument("--solvers", default=None)
    ap.add_argument("--processes", type=int, nargs="+", default=None)
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--exe", type=Path, default=REPO / "build" / "contact-dynamics")
    ap.add_argument("--reuse", action="store_true",
                    help="take the runs whose logs are complete from an earlier call")
    ap.add_argument("--skip", default="",
                    help="runs left out, as scene:solver:factor, comma-separated")
    args = ap.parse_args()
    defaults = {"weak": ("1,2,4", "AMG,UMFPACK", [1]),
                "strong": ("3", "AMG", [1, 2]),
                "largest": ("8", "AMG", [2])}[args.mode]
    factors = (args.factors or defaults[0]).split(",")
    solvers = (args.solvers or defaults[1]).split(",")
    processes = args.processes or defaults[2]
    if not args.exe.is_file():
        sys.exit(f"{args.exe} is missing: build it first (./run.sh build)")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OPENBLAS_NUM_THREADS="1")
    work = REPO / "benchmarks" / "results" / f"solver_growth_{args.mode}"
    work.mkdir(parents=True, exist_ok=True)
    skip = set(args.skip.split(",")) if args.skip else set()
    rows = [run(args, scene, solver, f, np_, r, work, env)
            for scene in args.scenes.split(",") for solver in solvers for f in factors
            if f"{scene}:{solver}:{f}" not in skip
            for np_ in processes for r in range(args.repeats)]
    with open(REPO / "benchmarks" / "results" / f"solver_growth_{args.mode}.csv", "w",
              newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)

    def med(group, key):
        vals = [float(r[key]) for r in group if r["status"] == "ok" and r[key] != ""]
        return statistics.median(vals) if vals else float("nan")

    out = ["| scene | solver | factor | processes | unknowns | Newton its | Krylov its / Newton "
           "| s / Newton (median) | growth of s / Newton vs first | growth of Krylov / Newton "
           "| bulk / contact / solve share of the Newton solves | peak MB per process "
           "| KB per unknown (all processes) | setup + initial acceleration (s) |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for scene in args.scenes.split(","):
        for solver in solvers:
            first = None
            for f in factors:
                for np_ in processes:
                    g = [r for r in rows if (r["scene"], r["solver"], r["factor"], r["processes"])
                         == (scene, solver, f, np_)]
                    if not g:
                        continue
                    s, k = med(g, "s_per_newton"), med(g, "krylov_per_newton")
                    if first is None:
                        first = (s, k)
                    total = med(g, "s_per_newton") * med(g, "newton")
                    shares = " / ".join(f"{100 * med(g, c) / total:.0f} %" for c in
                                        ("bulk_assembly_s", "contact_assembly_s", "linear_solve_s"))
                    n = med(g, "unknowns")
                    out.append(f"| {scene} | {solver} | {f} | {np_} | {n:.0f} | {med(g, 'newton'):.0f} "
                               f"| {k:.1f} | {s:.3g} | {s / first[0]:.2f} | "
                               f"{(k / first[1]) if first[1] else float('nan'):.2f} | {shares} | "
                               f"{med(g, 'peak_mb_per_process'):.0f} | "
                               f"{1024 * med(g, 'total_mb') / n:.2f} | "
                               f"{med(g, 'setup_s') + med(g, 'initial_s'):.2f} |")
    load = os.getloadavg()
    text = (f"<!-- generated by benchmarks/solver_growth.py {args.mode}; do not edit -->\n"
            f"Medians of {args.repeats} run(s), {os.cpu_count()} cores, load average at the end "
            f"{load[0]:.2f}, {time.strftime('%Y-%m-%d')}. Mesh = distributed, OpenBLAS on one "
            "thread. s / Newton is the TimerOutput section `Newton solve` over the Newton "
            "iterations (setup and initial acceleration apart, in the last column).\n\n" + "\n".join(out) + "\n")
    (REPO / "doc" / f"solver-growth-{args.mode}-table.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
