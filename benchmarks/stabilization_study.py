#!/usr/bin/env python3
"""Ironing with the four mortar stabilizations side by side (and persistency
with a dissipative Newmark scheme).

Runs prm/ironing/mortar.prm (frictionless, 6 s, refinement factor 1) with
Contact/Mortar/Stabilization = persistency, velocity persistency, velocity
update and none (only the stabilization and the output directory change),
and persistency with Newmark gamma = 0.55, beta = 0.275625 (persistency_damped),
each into <output-root>/stabilization_<name>/ with its screen log (run.log)
and run_status.txt, then writes from the output files

  figures   <figures>/stabilization_penetration.png      (a) normalized gap of the
                monitored lowest tool node (contact_history.csv), (b) largest
                penetration of an active node (contact_surface snapshots)
            <figures>/stabilization_pressure_profiles.png  nodal pressure along
                the contact zone (active nodes of pair 0) at --instants
            <figures>/stabilization_contact_work.png      contact work (statistics.csv)
            <figures>/stabilization_pressure_roughness.png  roughness of every snapshot
  tables    <tables> (Markdown, also printed) and <csv>

A run that fails or stops early is reported in the table, not an error of
this script. Run from anywhere, e.g.

  python3 benchmarks/stabilization_study.py -j 2                    # the full study
  python3 benchmarks/stabilization_study.py --end-time 0.6 --refinement 0.5   # a quick test
  python3 benchmarks/stabilization_study.py --plots-only            # redraw from output/

benchmarks/stabilization_study.sh installs and builds first. Needs numpy and
matplotlib (Debian: apt-get install python3-numpy python3-matplotlib).
"""
import argparse
import csv
import math
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from plot_env import np, plt  # noqa: E402  (numpy, matplotlib with Agg; re-exec if missing)
import bench_common  # noqa: E402  (parameter files, CSV files by column name)
from paper_benchmarks import Run, fmt, save, shown  # noqa: E402  (output directory reader, table helpers)

REPO = Path(__file__).resolve().parent.parent
BASE_PRM = REPO / "prm/ironing/mortar.prm"
STABILIZATION = "Contact/Mortar/Stabilization"
# (output name, value of Contact/Mortar/Stabilization, colour, line style)
VARIANTS = [("persistency", "persistency", "tab:blue", "-"),
            ("persistency_damped", "persistency", "tab:purple", (0, (1, 1))),
            ("velocity_persistency", "velocity persistency", "tab:red", "--"),
            ("velocity_update", "velocity update", "tab:green", "-."),
            ("none", "none", "tab:orange", ":")]
STYLE = {key: (color, ls) for key, _, color, ls in VARIANTS}
# further changes of a variant: persistency with a slightly dissipative
# Newmark scheme (gamma = 0.55, beta = (gamma + 1/2)^2 / 4), which damps the
# trapezoidal rule's undamped step-to-step alternation of held multipliers
EXTRA = {"persistency_damped": {"Time integration/Newmark gamma": 0.55,
                                "Time integration/Newmark beta": 0.275625}}


# ----------------------------------------------------------------- running

def run_one(key, value, args):
    """Run the simulator for one stabilization; writes run.prm, run.log, run_status.txt."""
    out = args.output_root / f"stabilization_{key}"
    if out.exists():
        for p in out.iterdir():  # no stale snapshots of an earlier run
            if p.is_file():
                p.unlink()
    out.mkdir(parents=True, exist_ok=True)
    changes = {STABILIZATION: value, "Output/Output directory": str(out.resolve())}
    changes.update(EXTRA.get(key, {}))
    if args.end_time is not None:
        changes["Time integration/End time"] = args.end_time
    if args.refinement is not None:
        changes["Scene/Refinement factor"] = args.refinement
    bench_common.write_prm(out / "run.prm", BASE_PRM, changes)
    print(f"   start {key}", flush=True)
    start = time.time()
    with open(out / "run.log", "w") as log:
        try:
            rc = subprocess.run([str(args.binary), str(out / "run.prm")], cwd=REPO,
                                stdout=log, stderr=subprocess.STDOUT).returncode
        except OSError as e:
            log.write(f"could not start {args.binary}: {e}\n")
            rc = 127
    wall = time.time() - start
    status, reason = "completed", "reached the end time"
    if rc != 0:
        status = "stopped"
        text = " ".join(l for l in (out / "run.log").read_text(errors="replace").splitlines()
                        if not l.startswith("Step "))
        text = re.sub(r"\s+", " ", text)
        m = re.search(r"Error: (.*?)\. The run stops (?:here|at step)", text)
        reason = m.group(1) if m else (text[-300:].strip() or f"exit code {rc}")
    (out / "run_status.txt").write_text(
        f"status = {status}\nreason = {reason}\nwall_time_s = {wall:.1f}\n"
        f"exit_code = {rc}\njobs = {args.jobs}\nprocesses = 1\n")
    print(f"   done {key:22s} {status:9s} {wall:7.1f} s"
          + (f"  ({reason})" if status != "completed" else ""), flush=True)


def run_all(args):
    """Run the selected stabilizations, args.jobs at a time."""
    if not args.binary.is_file():
        sys.exit(f"{args.binary} is missing: build first (benchmarks/stabilization_study.sh)")
    selected = [v for v in VARIANTS if v[0] in args.only]
    print(f"== Running {len(selected)} simulations, {args.jobs} at a time", flush=True)
    start = time.time()
    with ThreadPoolExecutor(args.jobs) as pool:
        futures = {key: pool.submit(run_one, key, value, args) for key, value, _, _ in selected}
    for key, future in futures.items():
        if future.exception() is not None:  # a problem of this script, not of the run
            print(f"   {key}: {future.exception()!r}", flush=True)
    print(f"== Simulations took {time.time() - start:.0f} s in total", flush=True)


# ---------------------------------------------------------------- analysis

def read_snapshots(run):
    """[(t, {column: array})] of the run's contact_surface snapshots, in time order."""
    return [(t, bench_common.read_csv(p)) for t, p in run.snapshots()]


def active_zone(snap, pair=0):
    """x and pressure of the active nodes of one pair, ordered by x."""
    if not snap or "active" not in snap:
        return np.array([]), np.array([])
    on = (snap["active"] > 0.5) & (snap["pair"] == pair)
    x, p = snap["x"][on], snap["pressure"][on]
    order = np.argsort(x)
    return x[order], p[order]


def roughness(snap):
    """RMS of the second difference of the nodal pressure along the active zone
    of pair 0 (ordered by x) divided by its mean, in %; NaN below 3 nodes."""
    _, p = active_zone(snap)
    if len(p) < 3 or p.mean() <= 0:
        return math.nan
    return 100 * np.sqrt(np.mean(np.diff(p, 2) ** 2)) / p.mean()


def penetration(snap):
    """Largest penetration (-normalized gap, >= 0) of an active node of any pair; NaN if none."""
    if not snap or "active" not in snap:
        return math.nan
    on = snap["active"] > 0.5
    return max(0.0, float(-snap["gap"][on].min())) if on.any() else math.nan


def drift(snaps, t0):
    """Largest |change of a node's normalized gap| between consecutive snapshots
    at t >= t0 while the node is active in both, with the time of the later
    snapshot and the node; (NaN, NaN, None) without such a pair of snapshots."""
    best = (math.nan, math.nan, None)
    later = [(t, s) for t, s in snaps if t >= t0 - 1e-9]
    for (_, a), (tb, b) in zip(later, later[1:]):
        if not a or not b:
            continue
        held = {(int(p), int(n)): g for p, n, g, on
                in zip(a["pair"], a["node"], a["gap"], a["active"]) if on > 0.5}
        for p, n, g, on in zip(b["pair"], b["node"], b["gap"], b["active"]):
            if on > 0.5 and (int(p), int(n)) in held:
                change = abs(g - held[(int(p), int(n))])
                if not change <= best[0]:  # also replaces NaN
                    best = (change, tb, (int(p), int(n)))
    return best


def nearest(snaps, target, tolerance):
    """(t, snapshot) nearest to target, or None if none is within tolerance."""
    if not snaps:
        return None
    t, s = min(snaps, key=lambda ts: abs(ts[0] - target))
    return (t, s) if abs(t - target) <= tolerance + 1e-9 else None


def value_at(t, y, t0):
    """y interpolated at t0 (NaN outside the run)."""
    if len(t) == 0 or t0 < t[0] - 1e-12 or t0 > t[-1] + 1e-12:
        return math.nan
    return float(np.interp(t0, t, y))


def metrics(run, snaps, args):
    """The table numbers of one run, all from its output files."""
    row = dict(stabilization=run.label, run=run.dir.name, status=run.short, reason=run.status)
    info = run.dir / "run_status.txt"
    if info.is_file():
        for line in info.read_text().splitlines():
            if line.startswith("exit_code"):
                row["exit_code"] = line.split("=", 1)[1].strip()
    if not run.ok:
        if row.get("exit_code") not in (None, "0"):
            row["status"] = f"failed (exit code {row['exit_code']})"
            row["reason"] = run.reason or row["status"]
        return row
    t = run.col("time")
    steps = int(run.col("step")[-1])
    newton = run.col("cumulative_newton_iterations")[-1]
    cw, ew = run.col("contact_work"), run.col("external_work")
    s0 = args.sliding_start
    sliding = run.t_last >= s0
    pens = [penetration(s) for _, s in snaps]
    d, d_t, d_node = drift(snaps, args.drift_start)
    rough = [roughness(s) for ts, s in snaps if ts >= s0 - 1e-9]
    rough = [r for r in rough if math.isfinite(r)]
    row.update(
        steps=steps, t_end=float(run.t_last),
        max_penetration=np.nanmax(pens) if np.isfinite(pens).any() else math.nan,
        drift=d, drift_time=d_t, drift_node="" if d_node is None else f"{d_node[0]}:{d_node[1]}",
        contact_work_sliding=cw[-1] - value_at(t, cw, s0) if sliding else math.nan,
        external_work_sliding=ew[-1] - value_at(t, ew, s0) if sliding else math.nan,
        contact_work_end=float(cw[-1]), external_work_total=float(ew[-1]),
        roughness_median=float(np.median(rough)) if rough else math.nan,
        roughness_snapshots=len(rough),
        newton=int(newton), newton_per_step=newton / max(steps, 1),
        cuts=int(run.col("time_step_cuts")[-1]), wall=float(run.col("wall_time")[-1]))
    for i, target in enumerate(args.instants):
        found = nearest(snaps, target, args.snapshot_tolerance)
        row[f"roughness_{i}"] = roughness(found[1]) if found else math.nan
        row[f"roughness_{i}_time"] = found[0] if found else math.nan
    return row


# ----------------------------------------------------------------- figures

def legend_label(run, note=""):
    """The run's label, its status if it did not complete, and a note."""
    extra = [n for n in (note, "" if run.short == "completed" else run.short) if n]
    return run.label + (f" ({', '.join(extra)})" if extra else "")


def mark_sliding(ax, args, t_max):
    """Shade the sliding phase at full depth (t >= --sliding-start)."""
    if t_max > args.sliding_start:
        ax.axvspan(args.sliding_start, t_max, color="0.9", lw=0, zorder=0,
                   label=f"sliding at full depth (t >= {args.sliding_start:g} s)")


def finish(ax, xlabel, ylabel, title, ncol=2):
    """Axis labels, grid, legend below the axes."""
    ax.set(xlabel=xlabel, ylabel=ylabel, title=title)
    ax.grid(alpha=0.3)
    if not ax.lines:
        ax.text(0.5, 0.5, "no data", transform=ax.transAxes, ha="center", color="0.5")
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=ncol,
              frameon=False)


def t_max_of(runs):
    """Last time of the longest run (for the sliding shade)."""
    return max((r.t_last for r in runs if r.ok), default=0.0)


def penetration_figure(runs, snaps, path, args):
    """(a) normalized gap of the monitored node, (b) largest penetration of an active node."""
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 5))
    t_max = t_max_of(runs)
    point = ""
    for run in runs:
        color, ls = STYLE[run.key]
        path_h = run.dir / "contact_history.csv"
        h = bench_common.read_csv(path_h) if run.ok and path_h.is_file() else {}
        gap = next((n for n in h if n.startswith("gap")), None)
        if gap is not None and len(h[gap]):
            point = gap[len("gap"):]
            a.plot(h["time"], h[gap], color=color, ls=ls, lw=1.3, label=legend_label(run))
        else:
            a.plot([], [], color=color, ls=ls, label=legend_label(run, "no data"))
        ts = [t for t, _ in snaps[run.key]]
        pen = np.array([penetration(s) for _, s in snaps[run.key]], dtype=float)
        ok = np.isfinite(pen)
        # a penetration of exactly 0 cannot be drawn on the log axis: floor at 1e-12
        b.plot(np.array(ts)[ok], np.maximum(pen[ok], 1e-12), color=color, ls=ls, lw=1.3,
               marker="o", ms=2.5, label=legend_label(run))
    for ax in (a, b):
        mark_sliding(ax, args, t_max)
    a.axhline(0, color="k", lw=0.6)
    finish(a, "time (s)", "normalized gap (< 0: penetration)",
           f"(a) lowest node of the tool's arc {point.strip()}")
    b.set_yscale("log")
    finish(b, "time (s)", "largest penetration (-gap; 0 drawn at 1e-12)",
           "(b) largest among the active nodes (snapshots)")
    fig.suptitle("Ironing: penetration of held nodes by stabilization")
    save(fig, path)


def profiles_figure(runs, snaps, path, args):
    """Pressure against x of the active nodes of pair 0, one panel per instant."""
    n = len(args.instants)
    fig, axes = plt.subplots(1, n, figsize=(4.6 * n, 4.8), squeeze=False)
    for ax, target in zip(axes[0], args.instants):
        for run in runs:
            color, ls = STYLE[run.key]
            found = nearest(snaps[run.key], target, args.snapshot_tolerance)
            if found is None:
                ax.plot([], [], color=color, ls=ls, label=legend_label(run, "no snapshot"))
                continue
            x, p = active_zone(found[1])
            note = "" if abs(found[0] - target) < 1e-9 else f"t = {found[0]:g} s"
            ax.plot(x, p, color=color, ls=ls, lw=1.2, marker="o", ms=3,
                    label=legend_label(run, note))
        finish(ax, "x of the active tool nodes (current)", "contact pressure",
               f"t = {target:g} s", ncol=1)
    fig.suptitle("Ironing: nodal contact pressure along the contact zone")
    save(fig, path)


def stats_figure(runs, path, args, column, ylabel, title):
    """A statistics.csv column against time, the sliding phase shaded."""
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    mark_sliding(ax, args, t_max_of(runs))
    for run in runs:
        color, ls = STYLE[run.key]
        if run.ok:
            ax.plot(run.col("time"), run.col(column), color=color, ls=ls, lw=1.3,
                    label=legend_label(run))
        else:
            ax.plot([], [], color=color, ls=ls, label=legend_label(run))
    ax.axhline(0, color="k", lw=0.6)
    finish(ax, "time (s)", ylabel, title)
    save(fig, path)


def roughness_figure(runs, snaps, path, args):
    """Pressure roughness of every snapshot against time."""
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    mark_sliding(ax, args, t_max_of(runs))
    for run in runs:
        color, ls = STYLE[run.key]
        ts = np.array([t for t, _ in snaps[run.key]], dtype=float)
        r = np.array([roughness(s) for _, s in snaps[run.key]], dtype=float)
        ok = np.isfinite(r)
        ax.plot(ts[ok], r[ok], color=color, ls=ls, lw=1.2, marker="o", ms=2.5,
                label=legend_label(run))
    finish(ax, "time (s)", "RMS(second difference of p) / mean p (%)",
           "Ironing: roughness of the nodal pressure along the contact zone")
    save(fig, path)


# ------------------------------------------------------------------ tables

def columns(args):
    """(key, header, format) of the table."""
    cols = [("stabilization", "stabilization", ""), ("status", "status", ""),
            ("steps", "steps", "d"),
            ("max_penetration", "largest penetration, active node", ".3g"),
            ("drift", f"drift of held nodes (t >= {args.drift_start:g} s)", ".3g"),
            ("contact_work_sliding", f"contact work, sliding (t >= {args.sliding_start:g} s)", ".4g"),
            ("external_work_sliding", "external work, sliding", ".4g"),
            ("external_work_total", "external work, total", ".4g")]
    cols += [(f"roughness_{i}", f"roughness at t = {t:g} s (%)", ".3g")
             for i, t in enumerate(args.instants)]
    return cols + [("roughness_median", "roughness, median while sliding (%)", ".3g"),
                   ("newton_per_step", "Newton/step", ".3g"), ("cuts", "step cuts", "d"),
                   ("wall", "wall time (s)", ".4g")]


def markdown(rows, args, runs):
    """The Markdown file: title, where from, the table, footnotes."""
    cols = columns(args)
    prm = next((r.prm for r in runs if r.ok), {})
    setup = (f"end time {prm.get('Time integration/End time', '?')} s, refinement factor "
             f"{prm.get('Scene/Refinement factor', '?')}, time step "
             f"{prm.get('Time integration/Time step', '?')}, VTU interval "
             f"{prm.get('Output/VTU interval', '?')}")
    lines = ["# Ironing: the mortar stabilizations side by side", "",
             f"Generated by `benchmarks/stabilization_study.py` from "
             f"`{shown(args.output_root)}/stabilization_*` ({setup}); figures in "
             f"`{shown(args.figures)}`. Every run is `prm/ironing/mortar.prm` with only "
             f"`{STABILIZATION}` and the output directory changed"
             + ("" if args.end_time is None and args.refinement is None else
                " (and the end time / refinement factor of a shortened test run)")
             + "; the run marked Newmark gamma 0.55 also sets `Time integration/Newmark "
               "gamma = 0.55` and `Newmark beta = 0.275625` (a slightly dissipative "
               "scheme; all others use the trapezoidal rule, beta = 1/4, gamma = 1/2).", "",
             "| " + " | ".join(h for _, h, _ in cols) + " |", "|" + "---|" * len(cols)]
    for row in rows:
        lines.append("| " + " | ".join(fmt(row.get(k), s) for k, _, s in cols) + " |")
    sliding = f"t >= {args.sliding_start:g} s"
    notes = [
        "Gaps are the normalized weighted gaps of contact_surface-NNNNN.csv (written every VTU "
        "interval steps; negative = penetration). Largest penetration = largest -gap of an "
        "active node (any pair) over all snapshots.",
        f"Drift of held nodes = largest |change of a node's gap| between consecutive snapshots "
        f"at t >= {args.drift_start:g} s while the node is active in both (the node and the "
        "later snapshot's time are in the CSV).",
        f"Contact work, sliding = contact_work at the run's last step minus its value at t = "
        f"{args.sliding_start:g} s (statistics.csv, interpolated); external work the same, "
        "and its final value (total). Frictionless contact ideally does no work; compare "
        "with the external work over the same interval.",
        "Roughness = RMS of the second difference of the nodal pressure of the active nodes "
        "of pair 0 (the tool's arc), ordered by x, divided by their mean pressure, in %; at "
        f"the snapshot nearest each instant (within {args.snapshot_tolerance:g} s, else –), "
        f"and the median over every snapshot at {sliding} (with at least 3 active nodes).",
        "Newton/step = cumulative_newton_iterations / steps; step cuts = time_step_cuts; wall "
        "time = statistics.csv wall_time of the last row.",
    ]
    notes += [f"{r['stabilization']}: {r['reason']}." for r in rows
              if r.get("reason") and r["reason"] != r["status"]]
    lines += [""] + [f"{i + 1}. {n}" for i, n in enumerate(notes)] + [""]
    return "\n".join(lines)


def write_csv(rows, path, args):
    """Every number of the table, plus the drift's node and time, as CSV."""
    keys = ["stabilization", "run", "status", "exit_code", "steps", "t_end", "max_penetration",
            "drift", "drift_time", "drift_node", "contact_work_sliding",
            "external_work_sliding", "contact_work_end", "external_work_total"]
    for i in range(len(args.instants)):
        keys += [f"roughness_{i}", f"roughness_{i}_time"]
    keys += ["roughness_median", "roughness_snapshots", "newton", "newton_per_step", "cuts",
             "wall", "reason"]
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, keys, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: "" if isinstance(v, float) and not math.isfinite(v) else v
                             for k, v in row.items()})
    print(f"writing {path}")


# --------------------------------------------------------------------- main

def parse_args():
    """Command line."""
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("-j", "--jobs", type=int, default=1,
                   help="simulations at the same time (default 1; -j 2 on 2 cores)")
    p.add_argument("--end-time", type=float, help="shorten the runs (default: the file's 6 s)")
    p.add_argument("--refinement", type=float,
                   help="Scene/Refinement factor (default: the file's 1)")
    p.add_argument("--only", nargs="+", choices=[v[0] for v in VARIANTS],
                   default=[v[0] for v in VARIANTS], help="run these stabilizations only")
    p.add_argument("--plots-only", action="store_true", help="run nothing, plot what output/ holds")
    p.add_argument("--binary", type=Path, default=REPO / "build/contact-dynamics")
    p.add_argument("--output-root", type=Path, default=REPO / "output")
    p.add_argument("--figures", type=Path, default=REPO / "doc/figures/stabilization")
    p.add_argument("--tables", type=Path, default=REPO / "doc/stabilization-tables.md")
    p.add_argument("--csv", type=Path, default=REPO / "benchmarks/results/stabilization_study.csv")
    p.add_argument("--instants", type=float, nargs="+", default=[1.0, 3.0, 5.0],
                   help="times of the pressure profiles and roughness columns (default 1 3 5)")
    p.add_argument("--snapshot-tolerance", type=float, default=0.1,
                   help="largest distance of the snapshot used for an instant (s)")
    p.add_argument("--sliding-start", type=float, default=2.0,
                   help="start of sliding at full depth (s)")
    p.add_argument("--drift-start", type=float, default=2.5,
                   help="start of the window of the held-node drift (s)")
    args = p.parse_args()
    if args.jobs < 1:
        p.error("-j needs a positive integer")
    args.binary = args.binary.resolve()
    args.output_root = args.output_root.resolve()
    return args


def main():
    """Run (unless --plots-only), then write the figures, the table and the CSV."""
    args = parse_args()
    if not args.plots_only:
        run_all(args)
    print("== Figures and tables")
    args.figures.mkdir(parents=True, exist_ok=True)
    runs = []
    for key, value, _, _ in VARIANTS:
        label = value + (" (Newmark gamma 0.55)" if key in EXTRA else "")
        run = Run(args.output_root, "stabilization", key, label)
        run.prm = run.prm or bench_common.read_prm(run.dir / "run.prm") \
            if (run.dir / "run.prm").is_file() else run.prm
        print(f"{run.dir}: {run.status}")
        runs.append(run)
    snaps = {r.key: read_snapshots(r) if r.ok else [] for r in runs}
    rows = [metrics(r, snaps[r.key], args) for r in runs]

    figs = args.figures
    penetration_figure(runs, snaps, figs / "stabilization_penetration.png", args)
    profiles_figure(runs, snaps, figs / "stabilization_pressure_profiles.png", args)
    stats_figure(runs, figs / "stabilization_contact_work.png", args, "contact_work",
                 "contact work", "Ironing: work of the contact forces")
    roughness_figure(runs, snaps, figs / "stabilization_pressure_roughness.png", args)

    text = markdown(rows, args, runs)
    args.tables.parent.mkdir(parents=True, exist_ok=True)
    args.tables.write_text(text)
    print(f"writing tables {args.tables}\n\n{text}")
    write_csv(rows, args.csv, args)


if __name__ == "__main__":
    main()
