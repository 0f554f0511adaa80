#!/usr/bin/env python3
"""AMG with and without the contact elimination in its hierarchy's matrix.

Issue 40, item 2: the condensed contact rows defeat the aggregation as the
contact zone grows. `Nonlinear solver/AMG contact elimination = true`
builds the hierarchy on a copy of the condensed matrix whose constrained
rows (active normal, stick) are reduced to their diagonal in rows and
columns, and rebuilds it when they change. This runs the shipped 2-D
ironing (mortar.prm, t <= 1) and the 3-D ironing (mortar_3d.prm, t <= 0.6:
the indentation) with `Linear solver = AMG`, both settings, and records
Newton and GMRES iterations and wall times (TimerOutput `linear solve`,
which includes the hierarchy builds, and the whole run).

  python3 benchmarks/amg_contact_elimination.py [--repeats 3]

Writes benchmarks/results/amg_contact_elimination.csv (one row per run) and
doc/amg-contact-elimination-table.md (medians over the repeats).
"""
import argparse
import csv
import statistics
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_common  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
SCENES = {
    "2-D ironing, t <= 1": ("prm/ironing/mortar.prm", "1"),
    "3-D ironing, t <= 0.6": ("prm/ironing/mortar_3d.prm", "0.6"),
}


def run(exe, work, scene, eliminate, repeat):
    base, end = SCENES[scene]
    name = f"{base.split('/')[-1][:-4]}_{eliminate}_{repeat}"
    out = work / name
    prm = work / f"{name}.prm"
    bench_common.write_prm(prm, REPO / base, {
        "Time integration/End time": end,
        "Nonlinear solver/Linear solver": "AMG",
        "Nonlinear solver/AMG contact elimination": eliminate,
        "Output/Output directory": str(out),
        "Output/VTU interval": "0"})
    log = subprocess.run([exe, str(prm)], capture_output=True, text=True,
                         check=True).stdout
    times = bench_common.parse_run_log(log, ["linear solve"])
    names, rows = bench_common.read_csv_rows(out / "statistics.csv")
    column = {n: i for i, n in enumerate(names)}
    newton = sum(int(r[column["newton_iterations"]]) for r in rows[1:])
    linear = sum(float(r[column["linear_iterations"]]) for r in rows[1:])
    return {"scene": scene, "elimination": eliminate, "repeat": repeat,
            "unknowns": times.get("unknowns"), "newton": newton,
            "gmres": linear, "gmres per newton": linear / newton,
            "linear solve s": times["linear solve"],
            "total s": times["total"]}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--exe", default=str(REPO / "build/contact-dynamics"))
    args = parser.parse_args(argv)
    work = REPO / "benchmarks/results/amg_contact_elimination"
    work.mkdir(parents=True, exist_ok=True)
    results = []
    for repeat in range(args.repeats):
        for scene in SCENES:
            for eliminate in ["false", "true"]:
                results.append(run(args.exe, work, scene, eliminate, repeat))
                print(results[-1], flush=True)
    with open(REPO / "benchmarks/results/amg_contact_elimination.csv", "w",
              newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(results[0]))
        writer.writeheader()
        writer.writerows(results)
    lines = ["# AMG contact elimination (benchmarks/amg_contact_elimination.py)",
             "",
             f"Medians over {args.repeats} runs; one process.",
             "",
             "| scene | unknowns | elimination | Newton | GMRES per Newton |"
             " linear solve (s) | whole run (s) |",
             "|---|---|---|---|---|---|---|"]
    for scene in SCENES:
        for eliminate in ["false", "true"]:
            runs = [r for r in results
                    if r["scene"] == scene and r["elimination"] == eliminate]

            def med(key):
                return statistics.median(r[key] for r in runs)
            lines.append(f"| {scene} | {runs[0]['unknowns']} | {eliminate} | "
                         f"{runs[0]['newton']} | {med('gmres per newton'):.1f}"
                         f" | {med('linear solve s'):.1f} | "
                         f"{med('total s'):.1f} |")
    (REPO / "doc/amg-contact-elimination-table.md").write_text(
        "\n".join(lines) + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
