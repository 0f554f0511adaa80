#!/usr/bin/env python3
"""Cost per unit of work: bulk assembly per cell, linear solve per unknown,
contact assembly per secondary node, energies per cell, from the
TimerOutput table of short runs of the shipped ironing (neo-Hookean, as
shipped, and with both bodies linear elastic) and bouncing block.

  python3 benchmarks/unit_costs.py [--repeats 3] [--factor 1]

Per section: median over repeats of (section time / number of calls), then
divided by the count of its unit. Writes benchmarks/results/unit_costs.csv
and doc/unit-costs-table.md (the measured columns; doc/profiling.md puts
them next to the estimates of what the hardware allows).
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

REPO = Path(__file__).resolve().parent.parent
CASES = {
    "ironing, neo-Hookean": ("prm/ironing/mortar.prm", {"Time integration/End time": 0.2}),
    "ironing, linear elastic": ("prm/ironing/mortar.prm",
                                {"Time integration/End time": 0.2,
                                 "Material model": "linear elastic"}),
    "bouncing block": ("prm/bouncing_block/mortar_stabilized.prm",
                       {"Time integration/End time": 2.0}),
}


def timer_table(log):
    """section -> (calls, seconds)"""
    out = {}
    for line in log.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) >= 5 and cells[2].isdigit():
            out[cells[1]] = (int(cells[2]), float(cells[3].rstrip("s")))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--factor", default="1")
    ap.add_argument("--solver", default="auto")
    ap.add_argument("--exe", type=Path, default=REPO / "build" / "contact-dynamics")
    args = ap.parse_args()
    work = REPO / "benchmarks" / "results" / "unit_costs"
    work.mkdir(parents=True, exist_ok=True)
    rows = []
    for case, (source, changes) in CASES.items():
        per = {}
        for r in range(args.repeats):
            name = re.sub(r"[^a-z]+", "_", case) + f"_{r}"
            c = dict(changes)
            c.update({"Scene/Refinement factor": args.factor,
                      "Nonlinear solver/Linear solver": args.solver,
                      "Output/Output directory": str(work / name),
                      "Output/VTU interval": 100000})
            prm = work / f"{name}.prm"
            bench_common.write_prm(prm, REPO / source, c)
            p = subprocess.run([str(args.exe), str(prm)], capture_output=True, text=True,
                               env=dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                                        OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1"))
            if p.returncode != 0:
                sys.exit(f"{case}: run failed, see {work / name}.log")
            (work / f"{name}.log").write_text(p.stdout)
            m = re.search(r"(\d+) cells, (\d+) unknowns", p.stdout)
            cells, unknowns = int(m.group(1)), int(m.group(2))
            names, values = bench_common.read_csv_rows(work / name / "contact_surface-00000.csv")
            nodes = len(values)
            table = timer_table(p.stdout)
            units = {"bulk assembly": ("cell", cells), "energies": ("cell", cells),
                     "contact assembly": ("secondary node", nodes),
                     "linear solve": ("unknown", unknowns),
                     "condensation": ("secondary node", nodes),
                     "contact search": ("secondary node", nodes),
                     "Newton solve": ("unknown", unknowns)}
            for section, (unit, count) in units.items():
                if section in table and table[section][0] > 0:
                    calls, secs = table[section]
                    per.setdefault(section, []).append((secs / calls, unit, count, calls))
            per.setdefault("total", []).append((float(re.search(
                r"Total wallclock time elapsed since start\s*\|\s*([0-9.]+)s", p.stdout).group(1)),
                "run", 1, 1))
        for section, samples in per.items():
            t = statistics.median(s[0] for s in samples)
            unit, count, calls = samples[0][1], samples[0][2], samples[0][3]
            rows.append(dict(case=case, section=section, calls=calls, ms_per_call=round(1e3 * t, 3),
                             unit=unit, units=count, us_per_unit=round(1e6 * t / count, 4)))
            print(rows[-1], flush=True)
    with open(REPO / "benchmarks" / "results" / "unit_costs.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    out = ["| case | section | calls | ms per call (median) | unit | units | us per unit |",
           "|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['case']} | {r['section']} | {r['calls']} | {r['ms_per_call']} | "
                   f"{r['unit']} | {r['units']} | {r['us_per_unit']} |")
    load = os.getloadavg()
    text = ("<!-- generated by benchmarks/unit_costs.py; do not edit -->\n"
            f"Medians of {args.repeats} runs, refinement factor {args.factor}, linear solver "
            f"{args.solver}, {os.cpu_count()} cores, load average at the end {load[0]:.2f}, "
            f"{time.strftime('%Y-%m-%d')}.\n\n" + "\n".join(out) + "\n")
    (REPO / "doc" / "unit-costs-table.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
