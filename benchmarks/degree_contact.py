#!/usr/bin/env python3
"""The polynomial degree with contact against rigid obstacles: accuracy
against unknowns and wall time for elements of degree 1 and 2.

1. Hertz, rigid cylinder (prm/examples/rigid_cylinder.prm: R = 1 into an
   elastic block, indentation 0.01, quasi-static), on n x n cells with
   degree 1 and n/2 x n/2 with degree 2 (the same nodes), mortar and
   node-to-segment. The load at the fixed indentation against a reference
   extrapolated (Richardson, with the order the loads of degree 2, mortar,
   show on 40, 80 and 160 cells per direction), and the half-width (second
   moment of the nodal pressures) and the peak nodal pressure against
   Hertz's values for the run's own load (the block is finite: both
   degrees converge to about -1.3 % and +1.5 % of Hertz). Also adapted
   to the contact (3 levels from 20 x 20 or 10 x 10 cells).
2. Bar impact on a rigid wall (prm/examples/bar_impact_rigid_wall.prm:
   exact contact force 0.01 on t in (0.1, 2.1]), mortar with persistency:
   the L2 error of the contact force per step and of its two-step average,
   the energy change and the contact duration.

3. With --sphere instead: Hertz, rigid sphere (prm/examples/
   rigid_sphere.prm, a quarter block, mortar), degree 1 on 10^3 ... 30^3
   and degree 2 on 5^3 ... 15^3 cells, one run each (the largest take
   minutes): the load against a Richardson extrapolation of degree 1 on
   20^3 and 30^3 with the order 2 its four meshes show, and the peak
   memory.

4. With --two-bodies instead: Hertz between two meshed bodies
   (prm/examples/hertz.prm: the half-cylinder R = 1 pressed 0.02 into the
   block, quasi-static, one step, mortar), degree 1 on Refinement factor
   0.5, 1, 2 and degree 2 on 0.25, 0.5, 1 (the same nodes): the load against
   degree 2 on factor 2 (its loads are not monotone: no extrapolation),
   half-width and peak against Hertz for the run's load.

Whole runs (process start to exit, one process; the runs write the
contact CSV, so their output is in the time), medians over the repeats.

  python3 benchmarks/degree_contact.py [--repeats 3]
  python3 benchmarks/degree_contact.py --sphere
  python3 benchmarks/degree_contact.py --two-bodies [--repeats 3]

Writes benchmarks/results/degree_contact.csv and
doc/degree-contact-table.md (--sphere: degree_contact_sphere.csv and
doc/degree-contact-sphere-table.md; --two-bodies: degree_contact_two_bodies.csv
and doc/degree-contact-two-bodies-table.md).
"""
import argparse
import csv
import glob
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
HERTZ = REPO / "prm" / "examples" / "rigid_cylinder.prm"
BAR = REPO / "prm" / "examples" / "bar_impact_rigid_wall.prm"
SPHERE = REPO / "prm" / "examples" / "rigid_sphere.prm"
TWO_BODIES = REPO / "prm" / "examples" / "hertz.prm"
E_STAR = 1000 / (1 - 0.3 ** 2)


def execute(exe, work, name, base, changes):
    prm, out = work / f"{name}.prm", work / name
    changes = dict(changes, **{"Output/Output directory": str(out)})
    bench_common.write_prm(prm, base, changes)
    t0 = time.time()
    p = subprocess.run([str(exe), str(prm)], capture_output=True, text=True,
                       cwd=work)
    wall = time.time() - t0
    if p.returncode != 0:
        raise RuntimeError(f"{name}:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    info = bench_common.parse_run_log(p.stdout, ["Newton solve"])
    # an adapted mesh: the unknowns of the last one
    changes = re.findall(r"-> (\d+) unknowns", p.stdout)
    if changes:
        info["unknowns"] = int(changes[-1])
    names, rows = bench_common.read_csv_rows(out / "statistics.csv")
    names = [n.split("(")[0].strip() for n in names]
    stats = [dict(zip(names, r)) for r in rows]
    return out, stats, dict(wall_s=wall, unknowns=info.get("unknowns", ""))


def nodal_weights(xs, degree):
    """int N_j along a straight surface with the nodes at xs (sorted)."""
    w = [0.0] * len(xs)
    if degree == 1:
        for i in range(len(xs) - 1):
            w[i] += (xs[i + 1] - xs[i]) / 2
            w[i + 1] += (xs[i + 1] - xs[i]) / 2
    else:
        for i in range(0, len(xs) - 2, 2):
            length = xs[i + 2] - xs[i]
            for k, f in ((0, 1 / 6), (1, 4 / 6), (2, 1 / 6)):
                w[i + k] += f * length
    return w


def hertz(exe, work, degree, n, formulation, levels=0):
    changes = {"Finite element/Polynomial degree": degree,
               "Scene/Block/Subdivisions": f"{n}, {n}",
               "Contact/Formulation": formulation,
               "Output/VTU interval": 2}
    if levels:
        changes.update({"Mesh refinement/Adapt to contact": "true",
                        "Mesh refinement/Maximum levels": levels,
                        "Mesh refinement/Buffer cells": 8,
                        "Mesh refinement/Passes per step": 5})
    out, stats, r = execute(
        exe, work, f"hertz_{formulation}_q{degree}_{n}_{levels}", HERTZ,
        changes)
    return dict(r, scene="hertz", formulation=formulation, degree=degree,
                cells=n, levels=levels,
                **profile(out, float(stats[-1]["roller_force_y"]), degree,
                          E_STAR))


def profile(out, load, degree, e_star):
    """The load, and the half-width (second moment of the nodal pressures)
    and peak nodal pressure of the last contact CSV relative to Hertz's for
    that load."""
    last = sorted(glob.glob(str(out / "contact_surface-*.csv")))[-1]
    with open(last) as f:
        nodes = sorted((float(row["x"]), float(row["pressure"]))
                       for row in csv.DictReader(f))
    xs, ps = [x for x, _ in nodes], [p for _, p in nodes]
    w = nodal_weights(xs, degree)
    force = sum(p * wj for p, wj in zip(ps, w))
    moment = sum(p * x * x * wj for p, x, wj in zip(ps, xs, w))
    centre = sum(p * x * wj for p, x, wj in zip(ps, xs, w)) / force
    moment -= centre * centre * force
    a = math.sqrt(4 * load / (math.pi * e_star))
    p0 = 2 * load / (math.pi * a)
    return dict(load=load, half_width=math.sqrt(4 * moment / force) / a - 1,
                peak=max(ps) / p0 - 1)


def two_bodies(exe, work, degree, factor):
    out, stats, r = execute(exe, work, f"two_q{degree}_{factor}", TWO_BODIES, {
        "Finite element/Polynomial degree": degree,
        "Scene/Refinement factor": factor,
        "Time integration/Time step": 1,
        "Output/VTU interval": 1})  # (the contact CSV comes with it)
    # equal bodies: E* = E / (2 (1 - nu^2))
    return dict(r, degree=degree, factor=factor,
                **profile(out, abs(float(stats[-1]["contact_force_y"])), degree,
                          E_STAR / 2))


def two_bodies_study(args, work):
    pairs = [(1, 0.5), (2, 0.25), (1, 1), (2, 0.5), (1, 2), (2, 1)]
    rows = []
    for repeat in range(args.repeats):
        for degree, factor in pairs + ([(2, 2)] if repeat == 0 else []):
            rows.append(dict(two_bodies(args.exe, work, degree, factor),
                             repeat=repeat))
            print(rows[-1], flush=True)
    with open(args.results / "degree_contact_two_bodies.csv", "w",
              newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    load = {(r["degree"], r["factor"]): r["load"] for r in rows}
    # (degree 2's loads do not converge monotonically here: no Richardson
    # extrapolation; the finest run is the reference)
    reference = load[(2, 2)]
    lines = [
        "<!-- generated by benchmarks/degree_contact.py --two-bodies; do "
        "not edit -->",
        f"Medians of {args.repeats} run(s) each (degree 2 on factor 2: one "
        f"run), one process, 2 cores, {time.strftime('%Y-%m-%d')}. "
        "`prm/examples/hertz.prm` in one step, mortar between the meshed "
        "cylinder and block. Load error against the finest run, degree 2 "
        f"on factor 2 ({reference:.7g}; degree 2's loads on factors 0.25 "
        "to 2 are not monotone, so no extrapolation); half-width and peak "
        "nodal pressure against Hertz for the run's load (the finite "
        "bodies: about -1.3 % and +1.5 % converged). Whole run: process "
        "start to exit, including one VTU and contact CSV.",
        "",
        "| degree | refinement factor | unknowns | load error | half-width "
        "vs Hertz | peak vs Hertz | whole run (s) |",
        "|---|---|---|---|---|---|---|"]
    for degree, factor in sorted(set(pairs + [(2, 2)])):
        mine = [r for r in rows if r["degree"] == degree and
                r["factor"] == factor]
        m = mine[0]
        lines.append(
            f"| {degree} | {factor} | {int(m['unknowns']):,} | "
            f"{abs(m['load'] / reference - 1):.1e} | "
            f"{m['half_width']:+.2%} | {m['peak']:+.2%} | "
            f"{median(mine, 'wall_s'):.3g} |")
    table = args.table.with_name("degree-contact-two-bodies-table.md")
    table.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


def bar(exe, work, degree, n, dt):
    _, stats, r = execute(exe, work, f"bar_q{degree}_{n}_{dt}", BAR, {
        "Finite element/Polynomial degree": degree,
        "Scene/Block/Subdivisions": f"{n}, {n // 10}",
        "Time integration/Time step": dt,
        "Output/VTU interval": 0})
    exact = 0.01
    t = [float(s["time"]) for s in stats]
    f = [abs(float(s["wall_force_x"])) for s in stats]
    step = avg = 0.0
    for i in range(1, len(t)):
        step += (f[i] - (exact if 0.1 < t[i] <= 2.1 + 1e-12 else 0)) ** 2
        if i > 1:
            mid = t[i] - dt / 2
            avg += ((f[i] + f[i - 1]) / 2 -
                    (exact if 0.1 < mid <= 2.1 else 0)) ** 2
    norm = exact ** 2 * 2 / dt
    active = [t[i] for i, s in enumerate(stats)
              if int(float(s["active_contact_nodes"])) > 0]
    e0 = 0.5 * 0.1 * 0.1 ** 2
    e1 = float(stats[-1]["kinetic_energy"]) + float(stats[-1]["elastic_energy"])
    return dict(r, scene="bar", formulation="mortar", degree=degree, cells=n,
                dt=dt, force_step=math.sqrt(step / norm),
                force_avg=math.sqrt(avg / norm), energy=e1 / e0 - 1,
                duration=active[-1] - active[0] + dt - 2,
                newton=stats[-1]["cumulative_newton_iterations"])


def sphere(exe, work, degree, n):
    prm, out = work / f"sphere_q{degree}_{n}.prm", work / f"sphere_q{degree}_{n}"
    bench_common.write_prm(prm, SPHERE, {
        "Finite element/Polynomial degree": degree,
        "Scene/Block/Subdivisions": f"{n}, {n}, {n}",
        "Output/VTU interval": 0, "Output/Output directory": str(out)})
    log, peak_kb = bench_common.run_measured([str(exe), str(prm)])
    info = bench_common.parse_run_log(log, [])
    names, rows = bench_common.read_csv_rows(out / "statistics.csv")
    names = [n.split("(")[0].strip() for n in names]
    last = dict(zip(names, rows[-1]))
    return dict(degree=degree, cells=n, unknowns=info["unknowns"],
                load=float(last["ball_force_y"]), wall_s=info["total"],
                memory_gb=peak_kb / 1e6)


def sphere_study(args, work):
    runs = [sphere(args.exe, work, degree, n)
            for degree, n in ((1, 10), (2, 5), (1, 16), (1, 20), (2, 10),
                              (1, 30), (2, 15))]
    for r in runs:
        print(r, flush=True)
    with open(args.results / "degree_contact_sphere.csv", "w",
              newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(runs[0].keys()))
        w.writeheader()
        w.writerows(runs)
    load = {(r["degree"], r["cells"]): r["load"] for r in runs}
    # degree 1 converges with order 2 here (its four meshes): Richardson
    # from 20^3 and 30^3
    ratio = (30 / 20) ** 2
    reference = (ratio * load[(1, 30)] - load[(1, 20)]) / (ratio - 1)
    lines = [
        "<!-- generated by benchmarks/degree_contact.py --sphere; do not "
        "edit -->",
        f"One run each, one process, 2 cores, {time.strftime('%Y-%m-%d')}. "
        "`prm/examples/rigid_sphere.prm` (a quarter block, mortar, UMFPACK). "
        f"Load error against {reference:.6g}, the Richardson extrapolation "
        "of degree 1 on 20^3 and 30^3 cells with order 2. Whole run: the "
        "program's own timer (set-up to end); memory: peak resident set.",
        "",
        "| degree | cells | unknowns | load | load error | whole run (s) | "
        "memory (GB) |",
        "|---|---|---|---|---|---|---|"]
    for r in sorted(runs, key=lambda r: (r["degree"], r["cells"])):
        lines.append(
            f"| {r['degree']} | {r['cells']}^3 | {r['unknowns']:,} | "
            f"{r['load']:.6f} | {abs(r['load'] / reference - 1):.1e} | "
            f"{r['wall_s']:.3g} | {r['memory_gb']:.2f} |")
    table = args.table.with_name("degree-contact-sphere-table.md")
    table.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


def median(rows, key):
    return statistics.median(float(r[key]) for r in rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--exe", type=Path,
                    default=REPO / "build" / "contact-dynamics")
    ap.add_argument("--results", type=Path,
                    default=REPO / "benchmarks" / "results")
    ap.add_argument("--table", type=Path,
                    default=REPO / "doc" / "degree-contact-table.md")
    ap.add_argument("--sphere", action="store_true",
                    help="the 3-D rigid sphere instead (minutes per run)")
    ap.add_argument("--two-bodies", action="store_true",
                    help="Hertz between two meshed bodies instead")
    args = ap.parse_args()
    work = Path("/tmp/degree_contact")
    work.mkdir(exist_ok=True)
    args.results.mkdir(parents=True, exist_ok=True)
    if args.sphere:
        sphere_study(args, work)
        return
    if args.two_bodies:
        two_bodies_study(args, work)
        return

    cells = {1: [20, 40, 80, 160], 2: [10, 20, 40, 80]}
    # adapted: from 20 x 20 (degree 1) or 10 x 10 (degree 2) cells, 3 levels
    adaptive = {1: 20, 2: 10}
    finest = hertz(args.exe, work, 2, 160, "mortar")["load"]
    bars = [(1, 40, 0.0125), (2, 20, 0.0125), (1, 80, 0.00625),
            (2, 40, 0.00625)]
    rows = []
    for repeat in range(args.repeats):
        # the degrees alternate, so that a drift of the machine hits both
        for formulation in ("mortar", "nts"):
            for n1, n2 in zip(cells[1], cells[2]):
                for degree, n in ((1, n1), (2, n2)):
                    rows.append(dict(hertz(args.exe, work, degree, n,
                                           formulation), repeat=repeat))
                    print(rows[-1], flush=True)
            for degree, n in adaptive.items():
                rows.append(dict(hertz(args.exe, work, degree, n, formulation,
                                       3), repeat=repeat))
                print(rows[-1], flush=True)
        for b in bars:
            rows.append(dict(bar(args.exe, work, *b), repeat=repeat))
            print(rows[-1], flush=True)
    def load(degree, n):
        return next(r["load"] for r in rows if r["scene"] == "hertz" and
                    r["formulation"] == "mortar" and r["degree"] == degree
                    and r["cells"] == n and r["levels"] == 0)
    coarse, middle = load(2, 40), load(2, 80)
    order = math.log2((coarse - middle) / (middle - finest))
    reference = finest - (middle - finest) / (2 ** order - 1)
    keys = sorted({k for r in rows for k in r})
    with open(args.results / "degree_contact.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)

    lines = [
        "<!-- generated by benchmarks/degree_contact.py; do not edit -->",
        f"Medians of {args.repeats} run(s) each, one process, 2 cores, "
        f"load average at the end {os.getloadavg()[0]:.2f}; "
        f"{time.strftime('%Y-%m-%d')}. Whole run: process start to exit.",
        "",
        "**Hertz, rigid cylinder** (`prm/examples/rigid_cylinder.prm`, "
        "indentation 0.01). Load error against the Richardson extrapolation "
        f"{reference:.8g} of degree 2, mortar: loads {coarse:.8g}, "
        f"{middle:.8g}, {finest:.8g} on 40, 80, 160 cells per direction, "
        f"observed order {order:.2f}; half-width and peak nodal pressure "
        "against Hertz for the run's load (the finite block: both degrees "
        "tend to about -1.3 % and +1.5 %).",
        "",
        "| formulation | degree | cells | unknowns (last mesh) | load error | "
        "half-width vs Hertz | peak vs Hertz | whole run (s) |",
        "|---|---|---|---|---|---|---|---|"]
    for formulation in ("mortar", "nts"):
        for degree in (1, 2):
            for n, levels in [(n, 0) for n in cells[degree]] + \
                    [(adaptive[degree], 3)]:
                mine = [r for r in rows if r["scene"] == "hertz" and
                        r["formulation"] == formulation and
                        r["degree"] == degree and r["cells"] == n and
                        r["levels"] == levels]
                m = mine[0]
                mesh = f"{n} x {n}" + (f" + {levels} levels adapted"
                                       if levels else "")
                lines.append(
                    f"| {formulation} | {degree} | {mesh} | "
                    f"{m['unknowns']:,} | "
                    f"{abs(m['load'] / reference - 1):.1e} | "
                    f"{m['half_width']:+.2%} | {m['peak']:+.2%} | "
                    f"{median(mine, 'wall_s'):.3g} |")
    lines += [
        "",
        "**Bar impact on a rigid wall** (`prm/examples/"
        "bar_impact_rigid_wall.prm`, mortar, persistency): relative L2 "
        "errors of the contact force against the exact 0.01 per step and "
        "averaged over two steps, the energy change at t = 3, the contact "
        "duration minus the exact 2.",
        "",
        "| degree | cells | dt | unknowns | force per step | two-step "
        "average | energy change | duration error | Newton | whole run (s) |",
        "|---|---|---|---|---|---|---|---|---|---|"]
    for degree, n, dt in bars:
        mine = [r for r in rows if r["scene"] == "bar" and
                r["degree"] == degree and r["cells"] == n]
        m = mine[0]
        lines.append(
            f"| {degree} | {n} x {n // 10} | {dt} | {m['unknowns']:,} | "
            f"{m['force_step']:.3f} | {m['force_avg']:.3f} | "
            f"{m['energy']:+.2e} | {m['duration']:+.4f} | {m['newton']} | "
            f"{median(mine, 'wall_s'):.3g} |")
    args.table.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
