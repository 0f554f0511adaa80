#!/usr/bin/env python3
"""The polynomial degree as a lever in bending: accuracy against unknowns
and wall time for elements of degree 1 and 2.

Runs prm/examples/cantilever.prm (a 10 x 1 plane-strain cantilever under
its own weight, quasi-static, linear elastic) on meshes of n x n/10 cells,
with Finite element/Polynomial degree 1 and 2, and compares the stored
energy (the compliance) with a reference: degree 2 on the finest mesh
given, refined once more. Whole runs (process start to exit, one process),
medians over the repeats.

  python3 benchmarks/degree_bending.py [--repeats 3]
      [--cells-1 20 40 80 160 320] [--cells-2 10 20 40 80 160]

Writes benchmarks/results/degree_bending.csv and
doc/degree-bending-table.md.

With --contact: prm/examples/cantilever_contact.prm instead (the same beam
without body force, pushed down by 0.05 at x = 9 by a rigid cylinder,
node-to-segment); the quantity is the load (roller_force_y at the end)
against degree 2 on twice the finest degree-2 mesh, and beside it
Timoshenko's load of a cantilever loaded at x = 9. Writes
benchmarks/results/degree_bending_contact.csv and
doc/degree-bending-contact-table.md.
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_common  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
BASE = REPO / "prm" / "examples" / "cantilever.prm"
CONTACT = REPO / "prm" / "examples" / "cantilever_contact.prm"
L, H, Q, E, NU = 10.0, 1.0, 1e-3, 1000.0, 0.3
# cantilever_contact.prm: the cylinder's lowest point and its push
A, DEFLECTION = 9.0, 0.05


def timoshenko():
    ep, i, g, k = E / (1 - NU * NU), H ** 3 / 12, E / (2 * (1 + NU)), 5 / 6
    return Q * Q * L ** 5 / (40 * ep * i) + Q * Q * L ** 3 / (6 * k * g * H)


def timoshenko_load():
    """The load that deflects a Timoshenko cantilever by DEFLECTION at A."""
    ep, i, g, k = E / (1 - NU * NU), H ** 3 / 12, E / (2 * (1 + NU)), 5 / 6
    return DEFLECTION / (A ** 3 / (3 * ep * i) + A / (k * g * H))


def run(exe, work, degree, n, contact=False):
    name = f"{'contact_' if contact else ''}q{degree}_{n}"
    prm = work / f"{name}.prm"
    out = work / name
    bench_common.write_prm(prm, CONTACT if contact else BASE, {
        "Finite element/Polynomial degree": degree,
        "Scene/Block/Subdivisions": f"{n}, {max(1, n // 10)}",
        "Output/Output directory": str(out),
        "Output/VTU interval": 0})
    t0 = time.time()
    p = subprocess.run([str(exe), str(prm)], capture_output=True, text=True,
                       cwd=work)
    wall = time.time() - t0
    if p.returncode != 0:
        raise RuntimeError(f"{name} failed:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    names, rows = bench_common.read_csv_rows(out / "statistics.csv")
    names = [n.split("(")[0].strip() for n in names]
    info = bench_common.parse_run_log(p.stdout, ["setup", "Newton solve"])
    last = dict(zip(names, rows[-1]))
    return dict(degree=degree, cells_x=n, cells=n * max(1, n // 10),
                unknowns=info.get("unknowns", ""),
                energy=float(last["elastic_energy"]),
                load=float(last["roller_force_y"]) if contact else "",
                active=int(float(last["active_contact_nodes"]))
                if contact else "",
                newton=info.get("newton", ""), wall_s=wall,
                setup_s=info.get("setup", ""),
                newton_s=info.get("Newton solve", ""))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--cells-1", type=int, nargs="+",
                    default=[20, 40, 80, 160, 320])
    ap.add_argument("--cells-2", type=int, nargs="+",
                    default=[10, 20, 40, 80, 160])
    ap.add_argument("--exe", type=Path,
                    default=REPO / "build" / "contact-dynamics")
    ap.add_argument("--results", type=Path,
                    default=REPO / "benchmarks" / "results")
    ap.add_argument("--table", type=Path, default=None,
                    help="default doc/degree-bending-table.md "
                    "(--contact: doc/degree-bending-contact-table.md)")
    ap.add_argument("--contact", action="store_true",
                    help="prm/examples/cantilever_contact.prm: the load "
                    "under a rigid cylinder instead of the stored energy")
    args = ap.parse_args()
    if args.table is None:
        args.table = REPO / "doc" / ("degree-bending-contact-table.md"
                                     if args.contact else
                                     "degree-bending-table.md")
    work = Path("/tmp/degree_bending")
    work.mkdir(exist_ok=True)
    args.results.mkdir(parents=True, exist_ok=True)
    quantity = "load" if args.contact else "energy"

    finest = run(args.exe, work, 2, 2 * max(args.cells_2), args.contact)
    reference = finest[quantity]
    rows = []
    for repeat in range(args.repeats):
        # degree 1 and 2 alternate, so that a drift of the machine hits both
        for n1, n2 in zip(args.cells_1, args.cells_2):
            for degree, n in ((1, n1), (2, n2)):
                r = run(args.exe, work, degree, n, args.contact)
                r["repeat"] = repeat
                rows.append(r)
                print(f"degree {degree}, {n} cells along: {r['unknowns']} "
                      f"unknowns, {quantity} {r[quantity]:.6e}, "
                      f"{r['wall_s']:.2f} s", flush=True)
    if args.contact:
        contact_table(args, rows, finest)
        return
    with open(args.results / "degree_bending.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)

    lines = [
        "<!-- generated by benchmarks/degree_bending.py; do not edit -->",
        f"Medians of {args.repeats} run(s) each, one process, 2 cores, "
        f"load average at the end {os.getloadavg()[0]:.2f}; "
        f"{time.strftime('%Y-%m-%d')}. `prm/examples/cantilever.prm`; "
        f"reference: degree 2 on {2 * max(args.cells_2)} x "
        f"{2 * max(args.cells_2) // 10} cells, stored energy "
        f"{reference:.8e} (Timoshenko {timoshenko():.8e}, "
        f"{reference / timoshenko() - 1:+.2%}). Whole run: process start to "
        "exit.",
        "",
        "| degree | cells | unknowns | energy error | whole run (s) | "
        "setup (s) | Newton solve (s) |",
        "|---|---|---|---|---|---|---|"]
    for degree, cells in ((1, args.cells_1), (2, args.cells_2)):
        for n in cells:
            mine = [r for r in rows if r["degree"] == degree
                    and r["cells_x"] == n]
            med = {k: statistics.median(float(r[k]) for r in mine)
                   for k in ("wall_s", "setup_s", "newton_s")}
            error = abs(mine[0]["energy"] / reference - 1)
            lines.append(
                f"| {degree} | {n} x {max(1, n // 10)} | "
                f"{mine[0]['unknowns']:,} | {error:.2e} | "
                f"{med['wall_s']:.3g} | {med['setup_s']:.3g} | "
                f"{med['newton_s']:.3g} |")
    args.table.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


def contact_table(args, rows, finest):
    """benchmarks/results/degree_bending_contact.csv and its table."""
    reference = finest["load"]
    with open(args.results / "degree_bending_contact.csv", "w",
              newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows + [dict(finest, repeat="reference")])
    n_ref = 2 * max(args.cells_2)
    lines = [
        "<!-- generated by benchmarks/degree_bending.py --contact; do not "
        "edit -->",
        f"Medians of {args.repeats} run(s) each, one process, 2 cores, "
        f"load average at the end {os.getloadavg()[0]:.2f}; "
        f"{time.strftime('%Y-%m-%d')}. `prm/examples/cantilever_contact.prm` "
        "(rigid cylinder R = 0.25 pushes the 10 x 1 cantilever down by "
        f"{DEFLECTION} at x = {A:g}, node-to-segment); reference: degree 2 on "
        f"{n_ref} x {n_ref // 10} cells ({finest['unknowns']:,} unknowns), "
        f"load {reference:.8f} (Timoshenko {timoshenko_load():.8f}, "
        f"the reference {reference / timoshenko_load() - 1:+.2%}). Load "
        "error: signed, load / reference - 1. Whole run: process start to "
        "exit.",
        "",
        "| degree | cells | unknowns | load | load error | active nodes | "
        "Newton | whole run (s) | Newton solve (s) |",
        "|---|---|---|---|---|---|---|---|---|"]
    for degree, cells in ((1, args.cells_1), (2, args.cells_2)):
        for n in cells:
            mine = [r for r in rows if r["degree"] == degree
                    and r["cells_x"] == n]
            med = {k: statistics.median(float(r[k]) for r in mine)
                   for k in ("wall_s", "newton_s")}
            m = mine[0]
            lines.append(
                f"| {degree} | {n} x {max(1, n // 10)} | {m['unknowns']:,} | "
                f"{m['load']:.7f} | {m['load'] / reference - 1:+.2e} | "
                f"{m['active']} | {m['newton']} | {med['wall_s']:.3g} | "
                f"{med['newton_s']:.3g} |")
    args.table.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
