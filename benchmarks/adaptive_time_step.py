#!/usr/bin/env python3
"""What adaptive time steps cost and buy (issue 19, item 3):
`Time integration/Error tolerance` against fixed time steps.

  bar_impact      prm/examples/bar_impact.prm to t = 3 (exact 1-D wave
                  solution: contact duration 2 L / c, force rho c v0 h, no
                  energy lost): fixed dt from 0.025 to 0.003125 against
                  adaptive steps (at most 0.025) for several tolerances:
                  contact force error (L2 in time of the two-step average,
                  against the exact step function), contact duration,
                  energy change, steps, Newton iterations, wall time.
  bouncing_block  prm/bouncing_block/mortar_stabilized.prm to t = 6 (both
                  contact spans): fixed dt 0.05 to 0.00625 against adaptive
                  steps (at most 0.05), all against a fixed dt = 0.003125
                  reference: kinetic energy and contact force histories
                  (relative L2 in time, the force averaged over two steps),
                  steps, Newton iterations, wall time.

Writes doc/adaptive-time-step-table.md. One process, one run at a time
(about 6 minutes).

    benchmarks/adaptive_time_step.py [--build build] [--only bar_impact|bouncing_block]
"""
import argparse
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "benchmarks"))
import bench_common  # noqa: E402
import accuracy_vs_cost as avc  # noqa: E402  (error measures, CSV reader)
from plot_env import np  # noqa: E402

WORK = ROOT / "benchmarks" / "results" / "adaptive_time_step"


def run(exe, name, base, changes):
    """Runs BASE with the entries changed; returns its directory, its
    statistics and its wall time."""
    directory = WORK / name
    directory.mkdir(parents=True, exist_ok=True)
    changes = {"Output/VTU interval": "0", **changes, "Output/Output directory": str(directory)}
    prm = directory / "run.prm"
    bench_common.write_prm(str(prm), str(ROOT / base), changes)
    start = time.time()
    out = subprocess.run([str(exe), str(prm)], cwd=ROOT, capture_output=True, text=True)
    wall = time.time() - start
    (directory / "screen.log").write_text(out.stdout + out.stderr)
    if out.returncode != 0:
        sys.exit(f"{name} failed:\n{out.stdout[-2000:]}\n{out.stderr[-2000:]}")
    print(f"  {name}: {wall:.1f} s", flush=True)
    return directory, avc.read_csv(directory / "statistics.csv"), wall


def counts(stats, wall):
    return dict(steps=len(stats["time"]) - 1, newton=int(stats["cumulative_newton_iterations"][-1]),
                rejected=int(stats["rejected_steps"][-1]) if "rejected_steps" in stats else 0,
                cuts=int(stats["time_step_cuts"][-1]), wall=wall,
                dt_min=float(np.min(stats["dt"][1:])), dt_max=float(np.max(stats["dt"][1:])))


def step_runs(prefix, fixed, largest, minimum, tolerances):
    """(directory name, label, prm changes) of the fixed-step runs and of
    the adaptive ones (steps between minimum and largest)."""
    runs = [(f"fixed dt = {dt:g}", {"Time integration/Time step": str(dt),
                                    "Time integration/Minimum time step": str(dt / 16)})
            for dt in fixed]
    runs += [(f"adaptive, tolerance {tol:g}", {"Time integration/Time step": str(largest),
                                               "Time integration/Minimum time step": str(minimum),
                                               "Time integration/Error tolerance": str(tol)})
             for tol in tolerances]
    return [(prefix + "_" + label.replace(" ", "_").replace(",", "").replace("=", ""), label, ch)
            for label, ch in runs]


def bar_impact(exe):
    base = "prm/examples/bar_impact.prm"
    rows = []
    for name, label, changes in step_runs("bar", (0.025, 0.0125, 0.00625, 0.003125), 0.025,
                                          0.0002, TOLERANCES["bar_impact"]):
        directory, stats, wall = run(exe, name, base, changes)
        active = stats["active_contact_nodes"] > 0
        # the duration's resolution: the step after the last active row
        last = np.nonzero(active)[0][-1] if active.any() else 0
        dt_end = stats["dt"][min(last + 1, len(stats["dt"]) - 1)]
        e = avc.bar_errors(directory, stats, dt_end)
        rows.append(dict(label=label, force=e["err_force_avg2"], duration=e["err_duration"],
                         energy=e["energy_change"], **counts(stats, wall)))
    return rows


def bouncing_block(exe):
    base = "prm/bouncing_block/mortar_stabilized.prm"
    end = {"Time integration/End time": "6"}
    _, ref, _ = run(exe, "bb_reference", base, {**end, "Time integration/Time step": "0.003125",
                                                 "Time integration/Minimum time step": "1e-4"})
    rows = []
    for name, label, changes in step_runs("bb", (0.05, 0.025, 0.0125, 0.00625), 0.05, 1e-4,
                                          TOLERANCES["bouncing_block"]):
        directory, stats, wall = run(exe, name, base, {**end, **changes})
        rows.append(dict(label=label,
                         kinetic=avc.history_error(stats, ref, "kinetic_energy"),
                         force=avc.history_error_avg2(stats, ref, "contact_force_y"),
                         **counts(stats, wall)))
    return rows


TOLERANCES = {"bar_impact": [3e-4, 1.5e-4, 7.5e-5, 3e-5], "bouncing_block": [3e-4, 1e-4, 3e-5, 1e-5]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--only", choices=["bar_impact", "bouncing_block"])
    args = parser.parse_args()
    exe = (ROOT / args.build / "contact-dynamics").resolve()
    sections = {}
    cost = ("| steps | rejected | solves | Newton iterations | dt min | dt max | wall time [s] |",
            "|---|---|---|---|---|---|---|")

    def cost_cells(r):
        return (f"| {r['steps']} | {r['rejected']} | {r['steps'] + r['rejected'] + r['cuts']} | "
                f"{r['newton']} | {r['dt_min']:.3g} | "
                f"{r['dt_max']:.3g} | {r['wall']:.1f} |")

    def section(title, header, accuracy, rows):
        lines = [f"### {title}\n", f"| time steps | {header} " + cost[0],
                 "|---|" + "---|" * header.count("|") + "---" + cost[1]]
        lines += [f"| {r['label']} | {accuracy(r)} " + cost_cells(r) for r in rows]
        return "\n".join(lines) + "\n"

    if args.only in (None, "bar_impact"):
        print("Bar impact:")
        sections["bar"] = section(
            "Bar impact (mortar, persistency, to t = 3), against the exact solution",
            "force error (2-step average) | duration error | energy change",
            lambda r: (f"{100 * r['force']:.2f} % | {100 * r['duration']:.2f} % | "
                       f"{100 * r['energy']:+.3f} %"),
            bar_impact(exe))
    if args.only in (None, "bouncing_block"):
        print("Bouncing block:")
        sections["bouncing"] = section(
            "Bouncing block (mortar, persistency, to t = 6), against fixed dt = 0.003125",
            "kinetic energy history L2 | contact force history L2 (2-step average)",
            lambda r: f"{100 * r['kinetic']:.2f} % | {100 * r['force']:.2f} %",
            bouncing_block(exe))
    name = ROOT / "doc" / "adaptive-time-step-table.md"
    old = {}
    if name.exists():
        for part in name.read_text().split("\n### ")[1:]:
            old[part.split(" ")[0].lower()] = "### " + part.rstrip() + "\n"
    old.update(sections)
    name.write_text("<!-- written by benchmarks/adaptive_time_step.py -->\n\n"
                    + "\n".join(old[k] for k in ("bar", "bouncing") if k in old))
    print(f"wrote {name}")


if __name__ == "__main__":
    main()
