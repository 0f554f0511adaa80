#!/usr/bin/env python3
"""What adaptive refinement near contact costs and buys (issue 18):

  hertz    prm/examples/hertz.prm at a load small enough for Hertz's
           assumptions (top pushed down by 0.001 in one step: a/R = 0.019),
           uniform meshes (Scene/Refinement factor 0.5 to 8) against
           adaptive ones (factor 0.5 and 1 to 5 levels near the contact,
           Buffer cells = 8): half-width and peak pressure errors against
           Hertz for the measured load, unknowns, wall time, peak memory.
  sphere   prm/examples/hertz_3d.prm (a quarter of a sphere on a block)
           at two loads small enough for Hertz's assumptions (the top
           pushed down by 0.002 and 0.0005: a/R = 0.045 and 0.023),
           uniform meshes (factor 1 to 2, the largest that fit in memory)
           against adaptive ones (factor 0.5 and 3 to 5 levels near the
           contact, Buffer cells 2 and 3): contact radius (second
           moment of the nodal pressures, integrated on a triangulation of
           the nodes) and peak pressure against Hertz, unknowns, time,
           memory.
  ironing  prm/ironing/mortar.prm to t = 3: the uniform
           factor 1 mesh against factor 0.5 with one level in a band that
           follows the tool: mean tool forces over t in [2, 3], relative
           L2 difference of the force histories (raw, and averaged over
           one element passage), wall time; and the reference's own
           spread under a change of the Capture tolerance.

Writes doc/adaptive-refinement-table.md and doc/figures/hertz_adaptive.png.
Runs one process at a time (wall times); about 10 minutes and 12 GB (the
uniform factor 8 Hertz mesh: 3.5 million unknowns, UMFPACK), and 15 more
minutes for the sphere (its uniform factor 2 mesh: 0.34 million unknowns,
10 GB) and 5 for ironing.

    benchmarks/adaptive_refinement.py [--build build] [--only hertz|sphere|ironing]
    benchmarks/adaptive_refinement.py --sphere-degree2 [FACTOR ...]
"""
import argparse
import math
import re
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "benchmarks"))
import bench_common  # noqa: E402
import accuracy_vs_cost as avc  # noqa: E402  (Hertz errors, CSV reader)
from plot_env import np, plt  # noqa: E402

WORK = ROOT / "benchmarks" / "results" / "adaptive_refinement"


def run(exe, name, base, changes):
    """Runs BASE.prm with the entries changed; returns its directory and
    the peak memory in MB (GNU time if present)."""
    directory = WORK / name
    directory.mkdir(parents=True, exist_ok=True)
    changes = dict(changes)
    changes["Output/Output directory"] = str(directory)
    prm = directory / "run.prm"
    bench_common.write_prm(str(prm), str(ROOT / base), changes)
    cmd = [str(exe), str(prm)]
    memory = math.nan
    if Path("/usr/bin/time").exists():
        cmd = ["/usr/bin/time", "-f", "peak %M KB"] + cmd
    start = time.time()
    out = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"{name} failed:\n{out.stdout[-2000:]}\n{out.stderr[-2000:]}")
    m = re.search(r"peak (\d+) KB", out.stderr)
    if m:
        memory = int(m.group(1)) / 1024
    print(f"  {name}: {time.time() - start:.1f} s", flush=True)
    (directory / "screen.log").write_text(out.stdout)
    return directory, memory


def unknowns_of(directory, stats):
    if "unknowns" in stats:
        return int(stats["unknowns"][-1])
    m = re.search(r"(\d+) unknowns", (directory / "screen.log").read_text())
    return int(m.group(1))


def hertz(exe):
    common = {"Boundary conditions/Dirichlet":
              "block_bottom: xy: 0; cylinder_top: x: 0; cylinder_top: y: -0.001*t",
              "Time integration/Time step": "1", "Output/VTU interval": "1"}
    rows = []
    for f in [0.5, 1, 2, 4, 8]:
        rows.append(("uniform", f, 0, run(exe, f"hertz_uniform_{f:g}", "prm/examples/hertz.prm",
                                        {**common, "Scene/Refinement factor": str(f)})))
    for levels in range(1, 6):
        rows.append(("adaptive", 0.5, levels, run(
            exe, f"hertz_adaptive_{levels}", "prm/examples/hertz.prm",
            {**common, "Scene/Refinement factor": "0.5",
             "Mesh refinement/Adapt to contact": "true",
             "Mesh refinement/Maximum levels": str(levels),
             "Mesh refinement/Passes per step": str(levels + 1),
             "Mesh refinement/Buffer cells": "8"})))
    table = []
    for kind, factor, levels, (directory, memory) in rows:
        stats = avc.read_csv(directory / "statistics.csv")
        e = avc.hertz_errors(directory, stats)
        table.append(dict(kind=kind, factor=factor, levels=levels,
                          unknowns=unknowns_of(directory, stats),
                          wall=float(stats["wall_time"][-1]), memory=memory,
                          a=e["err_half_width"], p0=e["err_peak_pressure"],
                          h=e["h"], a_over_R=e["hertz_a"]))
    return table


def sphere_errors(directory, stats):
    """Contact radius and peak pressure of the 3-D quarter sphere against
    Hertz for the measured load P (four times the quarter's force): a from
    the second moment a^2 = 5/2 int p r^2 / int p, integrated with linear
    interpolation on a Delaunay triangulation of the nodes (x, z) within
    3 a of the axis; p0 the largest nodal pressure."""
    import matplotlib.tri as mtri
    s, _ = avc.last_surface(directory, stats)
    x, z, p = (np.asarray(s[c]) for c in ("x", "z", "pressure"))
    P = 4 * abs(stats["contact_force_y"][-1])
    E, nu, R = 1000.0, 0.3, 1.0
    E_star = E / (2 * (1 - nu * nu))
    a = (3 * P * R / (4 * E_star)) ** (1 / 3)
    p0 = 3 * P / (2 * math.pi * a * a)
    near = np.hypot(x, z) < 3 * a
    x, z, p_near = x[near], z[near], p[near]
    moments = [0.0, 0.0]
    for t in mtri.Triangulation(x, z).triangles:
        area = 0.5 * abs((x[t[1]] - x[t[0]]) * (z[t[2]] - z[t[0]])
                         - (x[t[2]] - x[t[0]]) * (z[t[1]] - z[t[0]]))
        moments[0] += area * p_near[t].mean()
        moments[1] += area * (p_near[t] * (x[t] ** 2 + z[t] ** 2)).mean()
    a_h = math.sqrt(2.5 * moments[1] / moments[0])
    return dict(a=a_h / a - 1, p0=p.max() / p0 - 1, a_over_R=a / R,
                active=int(np.sum(np.asarray(s["active"]) > 0)),
                balance=4 * moments[0] / P - 1)


def sphere(exe):
    rows = []
    # (top displacement, uniform factors, (levels, Buffer cells) of the adaptive runs)
    for load, uniform, adaptive in ((0.002, [1, 1.5, 2], [(3, 2), (4, 2)]),
                                    (0.0005, [], [(3, 2), (4, 2), (5, 2), (4, 3), (5, 3)])):
        common = {"Boundary conditions/Dirichlet":
                  "block_bottom: xyz: 0; block_left: x: 0; block_front: z: 0; "
                  f"sphere_left: x: 0; sphere_front: z: 0; sphere_top: y: -{load}*t",
                  "Output/VTU interval": "1"}
        runs = [("uniform", f, 0, 0, {"Scene/Refinement factor": str(f)}) for f in uniform]
        runs += [("adaptive", 0.5, n, b, {
            "Scene/Refinement factor": "0.5", "Mesh refinement/Adapt to contact": "true",
            "Mesh refinement/Maximum levels": str(n), "Mesh refinement/Passes per step": str(n + 1),
            "Mesh refinement/Buffer cells": str(b)}) for n, b in adaptive]
        for kind, factor, n, b, changes in runs:
            directory, memory = run(exe, f"sphere_{load:g}_{kind}_{factor:g}_{n}_{b}",
                                    "prm/examples/hertz_3d.prm", {**common, **changes})
            stats = avc.read_csv(directory / "statistics.csv")
            rows.append(dict(load=load, kind=kind, factor=factor, levels=n, buffer=b,
                             unknowns=unknowns_of(directory, stats),
                             wall=float(stats["wall_time"][-1]), memory=memory,
                             **sphere_errors(directory, stats)))
    return rows


def sphere_degree2(exe, factors):
    """The sphere between two meshed bodies with elements of degree 2
    (frictionless dual mortar on 9-node faces, exact Jacobian): uniform
    meshes at the larger load, and meshes adapted to the contact from
    factor 0.25 (3 and 4 levels, buffer 1) at both loads of the degree-1
    study, and node-to-segment on the first adapted mesh."""
    rows = []
    runs = [(0.002, "uniform", f, 0, {"Scene/Refinement factor": str(f)}) for f in factors]
    runs += [(load, "adaptive", 0.25, n, {
        "Scene/Refinement factor": "0.25", "Mesh refinement/Adapt to contact": "true",
        "Mesh refinement/Maximum levels": str(n), "Mesh refinement/Passes per step": str(n + 1),
        "Mesh refinement/Buffer cells": "1"}) for load in (0.002, 0.0005) for n in (3, 4)]
    # node-to-segment of degree 2 on the first adapted mesh
    runs.append((0.002, "adaptive, node-to-segment", 0.25, 3,
                 {**runs[len(factors)][4], "Contact/Formulation": "nts"}))
    for load, kind, f, n, changes in runs:
        directory, memory = run(exe, f"sphere_{load:g}_degree2_{kind.split(',')[0]}"
                                f"{'_nts' if 'node' in kind else ''}_{f:g}_{n}",
                                "prm/examples/hertz_3d.prm", {
            "Boundary conditions/Dirichlet":
            "block_bottom: xyz: 0; block_left: x: 0; block_front: z: 0; "
            f"sphere_left: x: 0; sphere_front: z: 0; sphere_top: y: -{load}*t",
            "Output/VTU interval": "1", "Finite element/Polynomial degree": "2",
            "Contact/Mortar/Jacobian": "exact", **changes})
        stats = avc.read_csv(directory / "statistics.csv")
        mesh = (f"degree 2, uniform, factor {f:g}" if kind == "uniform" else
                f"degree 2, factor {f:g} + {n} levels, buffer 1")
        if "node-to-segment" in kind:
            mesh += ", node-to-segment"
        rows.append(dict(load=load, mesh=mesh, unknowns=unknowns_of(directory, stats),
                         wall=float(stats["wall_time"][-1]), memory=memory,
                         **sphere_errors(directory, stats)))
    return rows


# the reference mesh's element passage: the 2-D substrate's top has
# 200 elements on 12 at factor 1 (source/scenes/ironing.cc), the tool
# slides at 1, dt = 0.01: 6 steps
PASSAGE_STEPS = round(12 / 200 / 1.0 / 0.01)


def ironing(exe):
    base = "prm/ironing/mortar.prm"
    common = {"Time integration/End time": "3", "Output/VTU interval": "0"}
    runs = {
        "uniform 1": {"Scene/Refinement factor": "1"},
        # the reference's sensitivity to the Capture tolerance (x 0.3, x 3),
        # which decides which nodes are held
        "uniform 1, capture 3e-6": {"Scene/Refinement factor": "1",
                                    "Contact/Mortar/Capture tolerance": "3e-6"},
        "uniform 1, capture 3e-5": {"Scene/Refinement factor": "1",
                                    "Contact/Mortar/Capture tolerance": "3e-5"},
        "uniform 0.5": {"Scene/Refinement factor": "0.5"},
        "adaptive 0.5 + 1 level": {
            "Scene/Refinement factor": "0.5", "Mesh refinement/Adapt to contact": "true",
            "Mesh refinement/Maximum levels": "1", "Mesh refinement/Buffer cells": "3",
            "Mesh refinement/Passes per step": "0", "Mesh refinement/Interval": "4",
            "Mesh refinement/Lookahead steps": "8"},
    }
    out = {}
    for label, changes in runs.items():
        directory, memory = run(exe, "ironing_" + label.replace(", ", "_").replace(" ", "_")
                                .replace("+", "p"), base, {**common, **changes})
        out[label] = (avc.read_csv(directory / "statistics.csv"), memory)
    ref = out["uniform 1"][0]
    average = np.ones(PASSAGE_STEPS) / PASSAGE_STEPS
    table = []
    for label, (s, memory) in out.items():
        n = min(len(s["time"]), len(ref["time"]))
        if not np.allclose(s["time"][:n], ref["time"][:n], rtol=0, atol=1e-9):
            sys.exit(f"ironing {label}: its steps differ from the reference's (a cut step)")
        row = dict(label=label, wall=float(s["wall_time"][-1]), memory=memory,
                   unknowns=int(s["unknowns"][-1]) if "unknowns" in s else None,
                   changes=int(s["mesh_changes"][-1]) if "mesh_changes" in s else 0,
                   transfer=float(s["transfer_energy"][-1]) if "transfer_energy" in s else 0.0)
        late = np.asarray(ref["time"][:n]) >= 2.0
        for c in ("contact_force_x", "contact_force_y"):
            a, b = np.asarray(s[c][:n]), np.asarray(ref[c][:n])
            row[c + "_mean"] = a[late].mean() / b[late].mean() - 1
            row[c + "_l2"] = math.sqrt(np.sum((a - b) ** 2) / np.sum(b ** 2))
            a, b = (np.convolve(x, average, "valid") for x in (a, b))
            row[c + "_l2_passage"] = math.sqrt(np.sum((a - b) ** 2) / np.sum(b ** 2))
        table.append(row)
    return table


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--only", choices=["hertz", "sphere", "ironing"])
    parser.add_argument("--sphere-degree2", nargs="*", type=float, metavar="FACTOR",
                        help="only the sphere with degree 2: uniform on these factors "
                             "(default 0.5) and adapted to the contact: "
                             "doc/degree-sphere-two-bodies-table.md")
    args = parser.parse_args()
    exe = (ROOT / args.build / "contact-dynamics").resolve()
    if args.sphere_degree2 is not None:
        rows = sphere_degree2(exe, args.sphere_degree2 or [0.5])
        out = ["<!-- written by benchmarks/adaptive_refinement.py --sphere-degree2 -->", "",
               "| top displacement | a/R | mesh | unknowns | active nodes | a error | p0 error | "
               "int p / P - 1 | wall time [s] | peak memory [MB] |",
               "|---|---|---|---|---|---|---|---|---|---|"]
        for r in rows:
            out.append(f"| {r['load']:g} | {r['a_over_R']:.3f} | {r['mesh']} "
                       f"| {r['unknowns']} | {r['active']} | {100 * r['a']:+.2f} % | "
                       f"{100 * r['p0']:+.2f} % | {100 * r['balance']:+.2f} % | {r['wall']:.1f} | "
                       f"{r['memory']:.0f} |")
        name = ROOT / "doc" / "degree-sphere-two-bodies-table.md"
        name.write_text("\n".join(out) + "\n")
        print(f"wrote {name}")
        return
    lines = ["<!-- written by benchmarks/adaptive_refinement.py -->\n"]
    if args.only in (None, "hertz"):
        print("Hertz, uniform and adaptive:")
        rows = hertz(exe)
        for r in rows:
            r["err"] = max(abs(r["a"]), abs(r["p0"]))
        lines.append("### Hertz cylinder, a/R = %.3f: uniform against adaptive meshes\n"
                     % rows[-1]["a_over_R"])
        lines.append("| mesh | unknowns | h at contact | a error | p0 error | wall time [s] | peak memory [MB] |")
        lines.append("|---|---|---|---|---|---|---|")
        for r in rows:
            name = (f"uniform, factor {r['factor']:g}" if r["kind"] == "uniform"
                    else f"factor 0.5 + {r['levels']} levels")
            lines.append(f"| {name} | {r['unknowns']} | {r['h']:.2e} | {100 * r['a']:+.2f} % | "
                         f"{100 * r['p0']:+.2f} % | {r['wall']:.2f} | {r['memory']:.0f} |")
        uniform = [r for r in rows if r["kind"] == "uniform"]
        adaptive = [r for r in rows if r["kind"] == "adaptive"]
        lines.append("")
        lines.append("At equal element size at the contact (equal errors, both measured):")
        lines.append("")
        lines.append("| adaptive | uniform | unknowns ratio | time ratio | memory ratio |")
        lines.append("|---|---|---|---|---|")
        for r in adaptive:
            for u in uniform:
                if abs(r["h"] / u["h"] - 1) < 0.01:
                    lines.append(f"| factor 0.5 + {r['levels']} levels | factor {u['factor']:g} | "
                                 f"{r['unknowns'] / u['unknowns']:.3f} | {r['wall'] / u['wall']:.3f} | "
                                 f"{r['memory'] / u['memory']:.2f} |")
        good = [r for r in adaptive if r["err"] <= 0.005]
        if good:
            first = good[0]
            factor = 0.5 * 2 ** first["levels"]
            matched = [u for u in uniform if u["factor"] == factor]
            lines.append("")
            text = (f"The first adaptive mesh within 0.5 % on both (a {100 * first['a']:+.2f} %, "
                    f"p0 {100 * first['p0']:+.2f} %) has {first['unknowns']} unknowns and took "
                    f"{first['wall']:.2f} s. The uniform mesh with its element size at the "
                    f"contact is factor {factor:g}")
            if matched:
                u = matched[0]
                text += (f": {u['unknowns']} unknowns, {u['wall']:.1f} s (a {100 * u['a']:+.2f} %, "
                         f"p0 {100 * u['p0']:+.2f} %); ratios {first['unknowns'] / u['unknowns']:.3f} "
                         f"in unknowns and {first['wall'] / u['wall']:.3f} in time.")
            else:
                text += " (not run)."
            lines.append(text)
        fig, ax = plt.subplots(figsize=(6, 4))
        for kind, marker in (("uniform", "o-"), ("adaptive", "s-")):
            rs = [r for r in rows if r["kind"] == kind]
            ax.loglog([r["unknowns"] for r in rs], [abs(r["a"]) for r in rs], marker,
                      label=f"{kind}: |a error|")
            ax.loglog([r["unknowns"] for r in rs], [abs(r["p0"]) for r in rs], marker,
                      alpha=0.5, label=f"{kind}: |p0 error|")
        ax.axhline(0.005, color="gray", lw=0.8, ls="--")
        ax.set_xlabel("unknowns")
        ax.set_ylabel("relative error against Hertz")
        ax.legend(fontsize=8)
        ax.set_title("Hertz cylinder, a/R = 0.019")
        fig.tight_layout()
        (ROOT / "doc" / "figures").mkdir(exist_ok=True)
        fig.savefig(ROOT / "doc" / "figures" / "hertz_adaptive.png", dpi=120)
    if args.only in (None, "sphere"):
        print("Sphere (3-D Hertz), uniform and adaptive:")
        rows = sphere(exe)
        lines.append("\n### Sphere (3-D Hertz): uniform against adaptive meshes\n")
        lines.append("| top displacement | a/R | mesh | unknowns | active nodes | a error | "
                     "p0 error | int p / P - 1 | wall time [s] | peak memory [MB] |")
        lines.append("|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            name = (f"uniform, factor {r['factor']:g}" if r["kind"] == "uniform"
                    else f"factor 0.5 + {r['levels']} levels, buffer {r['buffer']}")
            lines.append(f"| {r['load']:g} | {r['a_over_R']:.3f} | {name} | {r['unknowns']} | "
                         f"{r['active']} | {100 * r['a']:+.2f} % | {100 * r['p0']:+.2f} % | "
                         f"{100 * r['balance']:+.2f} % | {r['wall']:.1f} | {r['memory']:.0f} |")
        lines.append("\nAdaptive meshes: Passes per step = levels + 1. "
                     "Active nodes: of the quarter's secondary surface. The last column checks the "
                     "integration of the nodal pressures (the load P is the contact force).")
    if args.only in (None, "ironing"):
        print("Ironing, uniform and adaptive band:")
        table = ironing(exe)
        lines.append("\n### Ironing (mortar, to t = 3): a band that follows the tool\n")
        lines.append("| mesh | final unknowns | mesh changes | F_x mean, t >= 2 | F_y mean | "
                     "F_x history L2 | F_y history L2 | F_x L2, passage average | "
                     "F_y L2, passage average | transfer energy | wall time [s] | peak memory [MB] |")
        lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for r in table:
            lines.append(
                f"| {r['label']} | {r['unknowns'] or '-'} | {r['changes']} | "
                f"{100 * r['contact_force_x_mean']:+.2f} % | {100 * r['contact_force_y_mean']:+.2f} % | "
                f"{100 * r['contact_force_x_l2']:.2f} % | {100 * r['contact_force_y_l2']:.2f} % | "
                f"{100 * r['contact_force_x_l2_passage']:.2f} % | "
                f"{100 * r['contact_force_y_l2_passage']:.2f} % | "
                f"{r['transfer']:.3g} | {r['wall']:.1f} | {r['memory']:.0f} |")
        lines.append("\nDifferences against the uniform factor 1 run (the reference row). The two "
                     "'capture' rows are the reference mesh itself with the mortar's Capture "
                     "tolerance (which decides which nodes are held) changed from 1e-5: how much "
                     "the force history moves under a change that is not a change of the model's "
                     f"resolution. Passage average: both histories averaged over {PASSAGE_STEPS} "
                     "steps, the time the tool takes to pass one substrate element of the "
                     "reference mesh.")
    name = ROOT / "doc" / "adaptive-refinement-table.md"
    # the part not run keeps its section
    sections = {}
    if name.exists():
        for part in name.read_text().split("\n### ")[1:]:
            sections[part.split(" ")[0].lower().strip()] = "### " + part.rstrip() + "\n"
    text = "\n".join(lines[1:]) + "\n"
    for part in text.split("\n### ")[0:]:
        part = part.strip()
        if part:
            part = part if part.startswith("### ") else "### " + part
            sections[part[4:].split(" ")[0].lower()] = part + "\n"
    name.write_text(lines[0] + "\n" + "\n".join(sections[k] for k in ("hertz", "sphere", "ironing")
                                                   if k in sections))
    print(f"wrote {name}")


if __name__ == "__main__":
    main()
