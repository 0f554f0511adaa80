#!/usr/bin/env python3
"""Direct solvers by dimension: KLU, UMFPACK with AMD or METIS, MUMPS.

Issue 40, item 3. Each factorization's cost is set by the sparsity pattern
(the contact only changes values), so the short runs time the first five
steps (15 Newton iterations, one factorization each) of the ironing:

- 3-D ironing (prm/ironing/mortar_3d.prm) at refinement factors 1, 1.5
  and 2 (16k, 52k and 105k unknowns): UMFPACK with AMD and with METIS on
  one process, KLU at factor 1 (its refactorization costs seconds beyond);
  Amesos KLU and MUMPS on two processes at factors 1 and 1.5;
- 2-D ironing (prm/ironing/mortar.prm, 34k unknowns): KLU and UMFPACK
  with either ordering.

The long runs (--long) compare what `auto` chooses between in 3-D
dynamics with contact: UMFPACK and AMG over the indentation (t <= 1) at
factors 1 and 1.5.

  python3 benchmarks/direct_solvers.py [--repeats 3] [--long]
      [--long-repeats 1]

Writes benchmarks/results/direct_solvers.csv (one row per run) and
doc/direct-solvers-table.md (medians over the repeats, per factorization
and whole runs, with the peak resident memory of the largest process).
"""
import argparse
import csv
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_common  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
IRONING_3D = "prm/ironing/mortar_3d.prm"
IRONING_2D = "prm/ironing/mortar.prm"

# (scene file, refinement factor, solver, ordering, processes, end time)
SHORT = ([(IRONING_3D, f, "UMFPACK", o, 1, "0.1")
          for f in ["1", "1.5", "2"] for o in ["AMD", "METIS"]]
         + [(IRONING_3D, "1", "KLU", "-", 1, "0.1")]
         + [(IRONING_3D, f, s, "-", 2, "0.1")
            for f in ["1", "1.5"] for s in ["KLU", "MUMPS"]]
         + [(IRONING_2D, "1", s, o, 1, "0.1")
            for s, o in [("KLU", "-"), ("UMFPACK", "AMD"),
                         ("UMFPACK", "METIS")]])
LONG = [(IRONING_3D, f, s, "auto", 1, "1")
        for f in ["1", "1.5"] for s in ["UMFPACK", "AMG"]]


def run(exe, work, case, repeat):
    base, factor, solver, ordering, processes, end = case
    name = (f"{base.split('/')[-1][:-4]}_{factor}_{solver}_{ordering}_"
            f"{processes}_{end}_{repeat}")
    out = work / name
    changes = {"Scene/Refinement factor": factor,
               "Time integration/End time": end,
               "Nonlinear solver/Linear solver": solver,
               "Output/Output directory": str(out),
               "Output/VTU interval": "0"}
    if ordering != "-":
        changes["Nonlinear solver/Direct solver ordering"] = ordering
    prm = work / f"{name}.prm"
    bench_common.write_prm(prm, REPO / base, changes)
    command = [exe, str(prm)]
    if processes > 1:
        command = ["mpirun", "-np", str(processes)] + command
    log, peak = bench_common.run_measured(command)
    times = bench_common.parse_run_log(log, ["linear solve", "setup"])
    return {"scene": f"{'3-D' if '3d' in base else '2-D'} ironing",
            "factor": factor, "unknowns": times.get("unknowns"),
            "solver": solver, "ordering": ordering,
            "processes": processes, "end time": end, "repeat": repeat,
            "newton": times["newton"],
            "linear solve s": times["linear solve"],
            "per solve s": times["linear solve"] / times["linear solve calls"],
            "total s": times["total"],
            "peak MB": peak / 1024}


def table(results, cases, title):
    lines = [f"### {title}", "",
             "| scene | unknowns | solver | ordering | processes | Newton |"
             " per factorization and solve (s) | linear solve (s) |"
             " whole run (s) | peak memory (MB) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for case in cases:
        runs = [r for r in results
                if (r["scene"].startswith("3") == ("3d" in case[0])
                    and (r["factor"], r["solver"], r["ordering"],
                         r["processes"], r["end time"]) == case[1:])]
        if not runs:
            continue

        def med(key):
            return statistics.median(r[key] for r in runs)
        lines.append(
            f"| {runs[0]['scene']} | {runs[0]['unknowns']} | "
            f"{case[2]} | {case[3]} | {case[4]} | {runs[0]['newton']} | "
            f"{med('per solve s'):.3f} | {med('linear solve s'):.1f} | "
            f"{med('total s'):.1f} | {max(r['peak MB'] for r in runs):.0f} |")
    return lines + [""]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--long", action="store_true",
                        help="also UMFPACK against AMG over t <= 1 in 3-D")
    parser.add_argument("--long-repeats", type=int, default=1,
                        help="repeats of the long runs (minutes each)")
    parser.add_argument("--exe", default=str(REPO / "build/contact-dynamics"))
    args = parser.parse_args(argv)
    work = REPO / "benchmarks/results/direct_solvers"
    work.mkdir(parents=True, exist_ok=True)
    results = []
    for repeat in range(max(args.repeats, args.long_repeats)):
        cases = ((SHORT if repeat < args.repeats else [])
                 + (LONG if args.long and repeat < args.long_repeats else []))
        for case in cases:
            results.append(run(args.exe, work, case, repeat))
            print(results[-1], flush=True)
    with open(REPO / "benchmarks/results/direct_solvers.csv", "w",
              newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(results[0]))
        writer.writeheader()
        writer.writerows(results)
    load = open("/proc/loadavg").read().split()[0]
    lines = ["<!-- generated by benchmarks/direct_solvers.py; do not edit -->",
             "",
             f"Medians over {args.repeats} runs (unless a title says"
             " otherwise), 2 cores, load average at the"
             f" end {load}. Peak memory: the resident set of the run's"
             " largest process, the largest over the repeats.", ""]
    lines += table(results, SHORT,
                   "Five steps (15 factorizations): the cost of the pattern")
    if args.long:
        lines += table(results, LONG,
                       "3-D dynamics with contact, t <= 1: UMFPACK or AMG"
                       f" ({args.long_repeats} runs each)")
    (REPO / "doc/direct-solvers-table.md").write_text("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])
