#!/usr/bin/env python3
"""What checkpoints cost (issue 19, item 1): `Output/Checkpoint interval`.

For each scene, runs of the same steps without checkpoints, with one every
10 steps and with one every step (3-D: every 2 steps), each twice (the
faster one is kept: wall times on a shared 2-core machine scatter):

  wall time per step           and its ratio to the run without checkpoints
  write time per checkpoint    (TimerOutput's "checkpoint", which includes
                                the reload of a distributed mesh)
  checkpoint size              the last checkpoint directory, in MB, and
                                bytes per unknown
  deviation                    the largest difference of any statistics
                                column (without wall time, residual and
                                GMRES iterations) between the runs with and
                                without checkpoints, relative to the
                                column's largest value: a checkpoint starts
                                the linear solver afresh (doc/restart.md)

Writes doc/restart-table.md. One process, one run at a time (about 8
minutes).

    benchmarks/checkpoint_cost.py [--build build]
"""
import argparse
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "benchmarks"))
import bench_common  # noqa: E402

WORK = ROOT / "benchmarks" / "results" / "checkpoint_cost"

# name, parameter file, changed entries, steps, intervals
CASES = [
    ("bouncing block 2-D (mortar)", "prm/bouncing_block/mortar_stabilized.prm",
     {"Time integration/End time": "1.5"}, 60, [0, 10, 1]),
    ("ironing 2-D, friction", "prm/ironing/mortar_friction.prm",
     {"Time integration/End time": "0.5"}, 50, [0, 10, 1]),
    ("ironing 2-D, adaptive mesh", "prm/ironing/mortar_adaptive.prm",
     {"Time integration/End time": "0.5"}, 50, [0, 10, 1]),
    # (the direct solver it was measured with; the shipped file takes AMG)
    ("bouncing block 3-D (mortar)", "prm/bouncing_block/mortar_3d.prm",
     {"Time integration/End time": "0.2",
      "Nonlinear solver/Linear solver": "auto"}, 8, [0, 2]),
]


def run(exe, tag, base, changes, interval):
    directory = WORK / tag
    shutil.rmtree(directory, ignore_errors=True)
    directory.mkdir(parents=True)
    changes = {"Output/VTU interval": "0", **changes,
               "Output/Output directory": str(directory),
               "Output/Checkpoint interval": str(interval)}
    prm = directory / "run.prm"
    bench_common.write_prm(str(prm), str(ROOT / base), changes)
    out = subprocess.run([str(exe), str(prm)], cwd=ROOT, capture_output=True, text=True)
    (directory / "screen.log").write_text(out.stdout + out.stderr)
    if out.returncode != 0:
        sys.exit(f"{tag} failed:\n{out.stdout[-2000:]}\n{out.stderr[-2000:]}")
    head, rows = bench_common.read_csv_rows(directory / "statistics.csv")
    values = [[float(x) for x in r] for r in rows]
    wall = values[-1][head.index("wall_time")]
    m = re.search(r"\|\s*checkpoint\s*\|\s*(\d+)\s*\|\s*([0-9.e+-]+)s", out.stdout)
    write = float(m.group(2)) / int(m.group(1)) if m else 0.0
    size = 0
    checkpoints = sorted((directory / "checkpoints").glob("step-*")) if interval else []
    if checkpoints:
        size = sum(f.stat().st_size for f in checkpoints[-1].rglob("*") if f.is_file())
    unknowns = int(re.search(r"cells, (\d+) unknowns", out.stdout).group(1))
    print(f"  {tag}: {wall:.1f} s", flush=True)
    return dict(head=head, values=values, wall=wall, write=write, size=size,
                unknowns=unknowns, steps=len(values) - 1)


def deviation(a, b):
    skip = {"wall_time", "final_residual", "linear_iterations"}
    worst = 0.0
    if len(a["values"]) != len(b["values"]):
        return float("inf")
    for k, name in enumerate(a["head"]):
        if name in skip:
            continue
        scale = max(abs(r[k]) for r in a["values"]) or 1.0
        worst = max([worst] + [abs(x[k] - y[k]) / scale for x, y in zip(a["values"], b["values"])])
    return worst


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    args = parser.parse_args()
    exe = ROOT / args.build / "contact-dynamics"
    lines = ["# Checkpoint cost", "",
             "Written by `benchmarks/checkpoint_cost.py` (one process, the faster of two runs "
             "each; see doc/restart.md).", "",
             "| scene | unknowns | steps | checkpoint every | wall time per step (s) | "
             "ratio to none | write per checkpoint (s) | size (MB) | bytes per unknown | "
             "largest deviation from none |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for index, (name, base, changes, steps, intervals) in enumerate(CASES):
        print(name, flush=True)
        results = {}
        for interval in intervals:
            runs = [run(exe, f"case{index}_every{interval}_{r}", base, changes, interval)
                    for r in range(2)]
            results[interval] = min(runs, key=lambda x: x["wall"])
        none = results[0]
        for interval in intervals:
            r = results[interval]
            per_step = r["wall"] / r["steps"]
            lines.append(
                f"| {name} | {r['unknowns']} | {r['steps']} | "
                f"{'never' if interval == 0 else interval} | {per_step:.3f} | "
                f"{per_step / (none['wall'] / none['steps']):.2f} | "
                f"{r['write']:.3f} | {r['size'] / 1e6:.2f} | "
                f"{r['size'] / r['unknowns']:.0f} | "
                f"{'' if interval == 0 else '%.1e' % deviation(none, r)} |")
    (ROOT / "doc" / "restart-table.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
