#!/usr/bin/env python3
"""Gmsh meshes of second order: what the curved cells cost and buy.

1. Accuracy: prm/examples/gmsh_hertz_order2.prm (half of an elastic disc,
   R = 1, pressed 0.02 onto a rigid plane, degree 2, mortar) on Gmsh meshes
   of prm/examples/half_disc.geo graded to `fine` = 0.02, 0.01 and 0.005 at
   the contact (Gmsh's subdivision halves it), of second order (curved
   cells: the mid-side nodes on the arc) and of first order (the same
   corners, straight cells), and the second-order mesh adapted to the
   contact (2 levels). Half-width and peak nodal pressure against Hertz's
   (a cylinder on a rigid flat, E* = E / (1 - nu^2)) for the run's load;
   whole-run wall time (process start to exit), median of the repeats.
   The finer meshes need `gmsh` (apt-get install gmsh); without it only
   the shipped 0.02 meshes run.
2. Reading cost: a quarter of a thick cylindrical shell (radii 1 and 2,
   height 1) in n_r x n_theta x n_z hexahedra written by this script with
   the exact nodes, of second order (27 nodes) and first order (the same
   corners), read and set up with degree 2 and End time = 0 (no solve):
   the whole process's wall time, median of the repeats.

  /usr/bin/python3 benchmarks/gmsh_second_order.py [--repeats 3]

Writes benchmarks/results/gmsh_second_order.csv and
doc/gmsh-second-order-table.md.
"""
import argparse
import csv
import math
import re
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_common  # noqa: E402
import degree_contact  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
HERTZ = REPO / "prm" / "examples" / "gmsh_hertz_order2.prm"
GEO = REPO / "prm" / "examples" / "half_disc.geo"
E_STAR = 1000 / (1 - 0.3 ** 2)

# Gmsh's hexahedron: corners, then edges and faces by their corners
HEX_CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
               (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
HEX_ENTITIES = [(0, 1), (0, 3), (0, 4), (1, 2), (1, 5), (2, 3), (2, 6),
                (3, 7), (4, 5), (4, 7), (5, 6), (6, 7), (0, 1, 2, 3),
                (0, 1, 4, 5), (0, 3, 4, 7), (1, 2, 5, 6), (2, 3, 6, 7),
                (4, 5, 6, 7), tuple(range(8))]


def hex_offsets(order):
    """Each node's offset in half-cells, in Gmsh's order."""
    corners = [tuple(2 * c for c in p) for p in HEX_CORNERS]
    if order == 1:
        return corners
    return corners + [tuple(sum(corners[i][d] for i in e) // len(e)
                            for d in range(3)) for e in HEX_ENTITIES]


def write_shell(path, n, order):
    """The quarter shell in n = (n_r, n_theta, n_z) hexahedra (format
    2.2); boundary faces as quadrilaterals of the same order."""
    nr, nt, nz = n
    size = (2 * nr + 1, 2 * nt + 1, 2 * nz + 1)

    def tag(i, j, k):
        return 1 + i + size[0] * (j + size[1] * k)

    nodes = []
    for k in range(size[2]):
        for j in range(size[1]):
            for i in range(size[0]):
                r, t = 1 + i / (2 * nr), (math.pi / 2) * j / (2 * nt)
                nodes.append(f"{tag(i, j, k)} {r * math.cos(t):.17g} "
                             f"{r * math.sin(t):.17g} {k / (2 * nz):.17g}")
    offsets = hex_offsets(order)
    cells, faces = [], []
    for c in range(nz):
        for b in range(nt):
            for a in range(nr):
                cells.append([tag(2 * a + o[0], 2 * b + o[1], 2 * c + o[2])
                              for o in offsets])
    # boundary faces: (surface tag, fixed axis, value) with a quadrilateral's
    # corners, edges and centre in the other two directions
    quad = [(0, 0), (2, 0), (2, 2), (0, 2)]
    if order == 2:
        quad += [(1, 0), (2, 1), (1, 2), (0, 1), (1, 1)]
    for surface, axis, value in ((1, 2, 0), (2, 2, 2 * nz), (3, 0, 0),
                                 (4, 0, 2 * nr), (5, 1, 0), (5, 1, 2 * nt)):
        other = [d for d in range(3) if d != axis]
        for u in range(0, size[other[0]] - 1, 2):
            for v in range(0, size[other[1]] - 1, 2):
                ids = []
                for du, dv in quad:
                    p = [0, 0, 0]
                    p[axis], p[other[0]], p[other[1]] = value, u + du, v + dv
                    ids.append(tag(*p))
                faces.append((surface, ids))
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n6\n"
                '2 1 "base"\n2 2 "top"\n2 3 "inner"\n2 4 "outer"\n'
                '2 5 "sides"\n3 6 "shell"\n$EndPhysicalNames\n')
        f.write(f"$Nodes\n{len(nodes)}\n" + "\n".join(nodes) +
                "\n$EndNodes\n")
        f.write(f"$Elements\n{len(faces) + len(cells)}\n")
        e = 1
        for surface, ids in faces:
            f.write(f"{e} {10 if order == 2 else 3} 2 {surface} {surface} "
                    + " ".join(map(str, ids)) + "\n")
            e += 1
        for ids in cells:
            f.write(f"{e} {12 if order == 2 else 5} 2 6 6 " +
                    " ".join(map(str, ids)) + "\n")
            e += 1
        f.write("$EndElements\n")


def timed(exe, prm, work):
    t0 = time.time()
    p = subprocess.run([str(exe), str(prm)], capture_output=True, text=True,
                       cwd=REPO)
    wall = time.time() - t0
    if p.returncode != 0:
        raise RuntimeError(f"{prm}:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    info = bench_common.parse_run_log(p.stdout, [])
    cells = re.findall(r"(\d+) cells", p.stdout)
    info["cells"] = int(cells[0]) if cells else ""
    # an adapted mesh: the unknowns of the last one
    changes = re.findall(r"-> (\d+) unknowns", p.stdout)
    if changes:
        info["unknowns"] = int(changes[-1])
    return wall, info


def hertz(exe, work, mesh, repeats, levels=0):
    name = f"hertz_{mesh.stem}_{levels}"
    out, prm = work / name, work / f"{name}.prm"
    changes = {"Scene/Mesh file": str(mesh), "Output/VTU interval": 2,
               "Output/Output directory": str(out)}
    if levels:
        changes.update({"Mesh refinement/Adapt to contact": "true",
                        "Mesh refinement/Maximum levels": levels})
    bench_common.write_prm(prm, HERTZ, changes)
    walls = []
    for _ in range(repeats):
        wall, info = timed(exe, prm, work)
        walls.append(wall)
    names, rows = bench_common.read_csv_rows(out / "statistics.csv")
    names = [n.split("(")[0].strip() for n in names]
    load = abs(float(dict(zip(names, rows[-1]))["ground_force_y"]))
    m = degree_contact.profile(out, load, 2, E_STAR)
    return dict(study="hertz", mesh=mesh.name, levels=levels,
                cells=info["cells"], unknowns=info.get("unknowns", ""),
                wall_s=statistics.median(walls), **m)


def shell(exe, work, n, order, repeats):
    mesh = work / f"shell_{n[0]}x{n[1]}x{n[2]}_order{order}.msh"
    write_shell(mesh, n, order)
    prm = work / f"shell_{n[0]}_order{order}.prm"
    prm.write_text(
        "set Dimension = 3\nsubsection Scene\n  set Scene = gmsh\n"
        f"  set Mesh file = {mesh}\nend\nsubsection Finite element\n"
        "  set Polynomial degree = 2\nend\nsubsection Boundary conditions\n"
        "  set Dirichlet = base: xyz: 0\nend\nsubsection Time integration\n"
        "  set Scheme = quasi-static\n  set End time = 0\nend\n"
        f"subsection Output\n  set Output directory = {work / 'shell_out'}"
        "\n  set VTU interval = 0\nend\n")
    walls = []
    for _ in range(repeats):
        wall, info = timed(exe, prm, work)
        walls.append(wall)
    return dict(study="read", mesh=mesh.name, order=order,
                cells=n[0] * n[1] * n[2], unknowns=info.get("unknowns", ""),
                megabytes=mesh.stat().st_size / 1e6,
                wall_s=statistics.median(walls))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--exe", default=str(REPO / "build" /
                                             "contact-dynamics"))
    args = parser.parse_args()
    work = REPO / "benchmarks" / "results" / "gmsh_second_order"
    work.mkdir(parents=True, exist_ok=True)

    meshes = [(0.02, REPO / "prm" / "examples" / f"half_disc_order{o}.msh",
               o) for o in (2, 1)]
    if shutil.which("gmsh"):
        for fine in (0.01, 0.005):
            for order in (2, 1):
                mesh = work / f"half_disc_{fine}_order{order}.msh"
                subprocess.run(["gmsh", str(GEO), "-2", "-setnumber", "fine",
                                str(fine), "-setnumber", "order", str(order),
                                "-format", "msh22", "-o", str(mesh)],
                               check=True, capture_output=True)
                meshes.append((fine, mesh, order))
    else:
        print("gmsh not found: only the shipped 0.02 meshes run")
    rows = []
    for fine, mesh, order in meshes:
        rows.append(dict(hertz(args.exe, work, mesh, args.repeats),
                         fine=fine, order=order))
        print(rows[-1], flush=True)
    rows.append(dict(hertz(args.exe, work, meshes[0][1], args.repeats, 2),
                     fine=0.02, order=2))
    print(rows[-1], flush=True)
    for n in ((4, 12, 4), (8, 24, 8), (12, 36, 12)):
        for order in (2, 1):
            rows.append(shell(args.exe, work, n, order, args.repeats))
            print(rows[-1], flush=True)

    keys = sorted({k for r in rows for k in r})
    with open(REPO / "benchmarks" / "results" / "gmsh_second_order.csv",
              "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    write_table(rows, args.repeats)


def write_table(rows, repeats):
    lines = [
        "# Gmsh meshes of second order: cost and accuracy",
        "",
        "Written by `benchmarks/gmsh_second_order.py` (repeats "
        f"{repeats}, medians; one process).",
        "",
        "Hertz on the half disc (`prm/examples/gmsh_hertz_order2.prm`, "
        "degree 2, mortar): curved cells (file of second order) against "
        "straight cells between the same corners (first order). Errors "
        "against Hertz's formulas for the run's load; the curved meshes' "
        "common offset (-2.9 %, +3.2 %) is the model's error (a half disc, "
        "a / R = 0.12), so compare each row with the finest curved one.",
        "",
        "| fine (contact h = fine/2) | cells | unknowns | geometry | "
        "half-width vs Hertz | peak vs Hertz | whole run (s) |",
        "|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["study"] != "hertz":
            continue
        geometry = ("curved" if r["order"] == 2 else "straight") + (
            f", adapted {r['levels']} levels" if r["levels"] else "")
        lines.append(f"| {r['fine']} | {r['cells']} | {r['unknowns']} | "
                     f"{geometry} | {r['half_width']:+.2%} | "
                     f"{r['peak']:+.2%} | {r['wall_s']:.2f} |")
    lines += ["", "Reading and setting up a quarter cylindrical shell of "
              "hexahedra (degree 2, End time = 0: no solve):", "",
              "| cells | unknowns | file | file MB | whole run (s) | "
              "second / first order |", "|---|---|---|---|---|---|"]
    reads = [r for r in rows if r["study"] == "read"]
    for r in reads:
        first = next(q for q in reads if q["cells"] == r["cells"] and
                     q["order"] == 1)
        lines.append(f"| {r['cells']} | {r['unknowns']} | order "
                     f"{r['order']} | {r['megabytes']:.1f} | "
                     f"{r['wall_s']:.2f} | "
                     f"{r['wall_s'] / first['wall_s']:.2f} |")
    (REPO / "doc" / "gmsh-second-order-table.md").write_text(
        "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
