#!/usr/bin/env python3
"""Figures and tables of the paper's two benchmarks (bouncing block, ironing).

Reads the simulator's output directories <output-root>/<benchmark>_<variant>/
(statistics.csv, contact_history.csv, contact_surface-NNNNN.csv, solution.pvd,
parameters.prm, optional run_status.txt) and writes PNG figures, a Markdown
file of tables (also printed) and a CSV of the same numbers. A variant that
is missing or stopped early is marked so. Run from anywhere, e.g.

  python3 benchmarks/paper_benchmarks.py [--output-root output]
      [--figures doc/figures/benchmarks] [--tables doc/benchmarks-tables.md]

Defaults are relative to the repository root; `--help` lists every option.
Needs numpy and matplotlib (Debian: apt-get install python3-numpy python3-matplotlib).
"""
import argparse
import csv
import math
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from plot_env import np, plt  # noqa: E402  (numpy, matplotlib with Agg; re-exec if missing)
from matplotlib.patches import Patch  # noqa: E402
import bench_common  # noqa: E402  (CSV files by column name, parameter files)

REPO = Path(__file__).resolve().parent.parent
# benchmark -> [(variant key, legend label)]; the first one is the reference.
VARIANTS = {
    "bouncing_block": [("mortar_stabilized", "stabilized mortar"),
                       ("mortar_static", "static mortar"),
                       ("nts", "NTS"),
                       ("mortar_undamped", "stabilized mortar, undamped"),
                       ("mortar_generalized_alpha", "stabilized mortar, gen.-alpha 0.8, undamped"),
                       ("mortar_stabilized_degree2", "stabilized mortar, degree 2")],
    "ironing": [("mortar", "mortar"),
                ("nts", "NTS"),
                ("nts_smoothed", "NTS, smoothed normals"),
                ("mortar_friction", "mortar, mu = 0.25"),
                ("nts_smoothed_friction", "NTS smoothed, mu = 0.25"),
                ("mortar_undamped", "mortar, undamped"),
                ("mortar_generalized_alpha", "mortar, gen.-alpha 0.8, undamped"),
                ("mortar_degree2", "mortar, degree 2")],
}
STYLE = {"mortar_stabilized": ("tab:blue", "-"), "mortar_static": ("tab:orange", "--"),
         "nts": ("tab:red", ":"), "mortar": ("tab:blue", "-"),
         "nts_smoothed": ("tab:orange", "--"), "mortar_friction": ("tab:green", "-."),
         "nts_smoothed_friction": ("tab:purple", (0, (5, 1, 1, 1))),
         "mortar_undamped": ("tab:gray", (0, (1, 1))),
         "mortar_generalized_alpha": ("tab:cyan", (0, (3, 1))),
         "mortar_stabilized_degree2": ("tab:brown", (0, (5, 2))),
         "mortar_degree2": ("tab:brown", (0, (5, 2)))}
FRICTIONLESS = ["mortar", "nts", "nts_smoothed", "mortar_undamped", "mortar_generalized_alpha",
                "mortar_degree2"]
FRICTION = ["mortar_friction", "nts_smoothed_friction"]


def read_prm(path):
    """Entries of a deal.II parameter file as {'Section/Entry': value} ({} if missing)."""
    return bench_common.read_prm(path) if path.is_file() else {}


def read_key_values(path):
    """'key = value' lines of a file (run_status.txt) as a dict."""
    if not path.is_file():
        return {}
    pairs = (line.split("=", 1) for line in path.read_text().splitlines() if "=" in line)
    return {k.strip(): v.strip() for k, v in pairs}


class Run:
    """One simulator output directory and its status."""

    def __init__(self, root, benchmark, key, label):
        self.key, self.label = key, label
        self.dir = Path(root) / f"{benchmark}_{key}"
        info = read_key_values(self.dir / "run_status.txt")
        self.stats, self.reason = {}, info.get("reason", "")
        if (self.dir / "statistics.csv").is_file() and info.get("status") != "missing":
            # 'wall_time(cumulative s)' and 'wall_time' both become 'wall_time'
            self.stats = bench_common.read_csv(self.dir / "statistics.csv", units=False)
        self.ok = len(self.stats.get("time", [])) > 0
        # parameters.prm of a run that was stopped can be empty: use the input file
        self.prm = read_prm(self.dir / "parameters.prm") or \
            read_prm(REPO / "prm" / benchmark / f"{key}.prm")
        self.end_time = float(self.prm.get("Time integration/End time", 8))
        if not self.ok:
            self.status, self.short = "missing", "missing"
            return
        self.t_last = self.stats["time"][-1]
        status = info.get("status") or \
            ("completed" if self.t_last >= self.end_time - 1e-9 else "stopped")
        self.short = "completed" if status == "completed" else f"stopped at t={self.t_last:g}"
        self.status = self.short + (f", {self.reason}" if self.reason and status != "completed" else "")
        dt = self.stats["dt"][1:]
        self.base_dt = float(self.prm.get("Time integration/Time step", dt.max() if len(dt) else 1))
        self.wall = float(info["wall_time_s"]) if "wall_time_s" in info else self.stats["wall_time"][-1]

    def col(self, name):
        """A column of statistics.csv (NaN if the run lacks it)."""
        return self.stats.get(name, np.full(len(self.stats["time"]), np.nan))

    def history(self):
        """Time and pressure of the first monitored point in contact_history.csv (cached)."""
        path = self.dir / "contact_history.csv"
        if not hasattr(self, "_history"):
            self._history, self.point = None, ""
            columns = bench_common.read_csv(path) if path.is_file() else {}
            p = next((n for n in columns if n.startswith("pressure")), None)
            if p is not None and len(columns[p]):
                self._history, self.point = (columns["time"], columns[p]), p[len("pressure"):]
        return self._history

    def snapshots(self):
        """(time, path) of the contact_surface CSVs of this run, from solution.pvd or the step numbers."""
        pvd, found = self.dir / "solution.pvd", {}
        if pvd.is_file():  # lists only this run's outputs, not stale files of older runs
            for t, n in re.findall(r'timestep="([^"]+)"[^>]*file="solution-(\d+)\.vtu"', pvd.read_text()):
                found[n] = float(t)
        else:
            step_time = dict(zip(self.col("step").astype(int), self.col("time")))
            for p in self.dir.glob("contact_surface-*.csv"):
                n = p.stem.split("-")[1]
                if int(n) in step_time:  # file number = time step number
                    found[n] = step_time[int(n)]
        paths = ((t, self.dir / f"contact_surface-{n}.csv") for n, t in found.items())
        return sorted((t, p) for t, p in paths if p.is_file())


def contact_spans(run, merge_gap):
    """Merged (start, end) times of rows with active contact nodes, and the raw span count."""
    t, on = run.col("time"), np.nan_to_num(run.col("active_contact_nodes")) > 0
    edges = np.flatnonzero(np.diff(np.r_[0, on.astype(int), 0]))
    raw = [(t[s], t[e - 1]) for s, e in zip(edges[::2], edges[1::2])]
    merged = []
    for s, e in raw:
        if merged and s - merged[-1][1] <= merge_gap + 1e-12:
            merged[-1] = (merged[-1][0], e)
        else:
            merged.append((s, e))
    return merged, len(raw)


def signal_analysis(t, y, t0, t1, args, dt, f_mark=None):
    """Mean, dominant frequency, its amplitude and RMS deviation from trend of y on [t0, t1].

    y is resampled linearly onto a uniform grid of step dt, a linear trend is
    removed, a Hann window applied (unless --no-hann) and the single-sided
    amplitude spectrum 2|FFT|/sum(window) taken. The dominant frequency is the
    largest amplitude at f >= --min-frequency; the spectrum only if the window
    is at least --min-window long. The trend for the RMS deviation is a centred
    moving average over --trend-window. With f_mark, amp_mark is the largest
    amplitude within 0.6 Hz of f_mark, in % of the mean. alternation: the RMS
    of the second difference of the resampled signal divided by 4 (the
    amplitude of a step-to-step alternation, the Nyquist frequency), in % of
    the mean."""
    out = dict(mean=math.nan, f_dom=math.nan, amp_rel=math.nan, rms_rel=math.nan, spectrum=None)
    t1 = min(t1, t[-1]) if len(t) else t0
    n = int(math.floor((t1 - t0) / dt + 1e-9)) + 1
    if len(t) < 2 or n < 3:
        return out
    grid = t0 + dt * np.arange(n)
    yg = np.interp(grid, t, y)
    out["mean"] = mean = yg.mean()
    out["alternation"] = 100 * np.sqrt(np.mean(np.diff(yg, 2) ** 2)) / 4 / abs(mean)
    m = int(round(args.trend_window / dt)) // 2 * 2 + 1
    if n >= 2 * m:
        smooth = np.convolve(yg, np.ones(m) / m, mode="valid")
        out["rms_rel"] = 100 * np.sqrt(np.mean((yg[m // 2:n - m // 2] - smooth) ** 2)) / abs(mean)
    if t1 - t0 < args.min_window - 1e-9:
        return out
    detrended = yg - np.polyval(np.polyfit(grid, yg, 1), grid)
    w = np.ones(n) if args.no_hann else np.hanning(n)
    amp = 2 * np.abs(np.fft.rfft(detrended * w)) / w.sum()
    amp[0] /= 2
    if n % 2 == 0:
        amp[-1] /= 2
    f = np.fft.rfftfreq(n, dt)
    valid = np.flatnonzero(f >= args.min_frequency)
    if len(valid):
        k = valid[np.argmax(amp[valid])]
        out.update(f_dom=f[k], amp_rel=100 * amp[k] / abs(mean))
    if f_mark:
        near = np.abs(f - f_mark) <= 0.6
        if near.any():
            out["amp_mark"] = 100 * amp[near].max() / abs(mean)
    out["spectrum"] = (f, amp)
    return out


def save(fig, path):
    """Write a figure and close it."""
    print(f"writing figure {path}")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def overlay(runs, path, series, ylabel, title, xlabel="time (s)", spans=(),
            xlim=None, logy=False, vlines=(), marker=None):
    """One curve per run, contact spans shaded.

    series(run) returns (x, y[, note]), or None or a note when there is no curve."""
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for s, e in spans:
        ax.axvspan(s, e, color="0.88", lw=0, zorder=0)
    visible = []
    for i, run in enumerate(runs):
        color, ls = STYLE[run.key]
        data = series(run) if run.ok else None
        if data is None or isinstance(data, str) or len(data[0]) == 0:
            why = data if isinstance(data, str) else run.short
            ax.plot([], [], color=color, ls=ls, label=f"{run.label} ({why})")
            continue
        x, y = np.asarray(data[0]), np.asarray(data[1])
        note = data[2] if len(data) > 2 else ("" if run.short == "completed" else run.short)
        ax.plot(x, y, color=color, ls=ls, lw=1.3, marker=marker, ms=3, zorder=3 + len(runs) - i,
                label=run.label + (f" ({note})" if note else ""))
        visible.append(y[(x >= xlim[0]) & (x <= xlim[1])] if xlim else y)
    for x, label in vlines:
        ax.axvline(x, color="k", ls="--", lw=1, label=label)
    if xlim:
        ax.set_xlim(*xlim)
        values = np.concatenate([v[np.isfinite(v)] for v in visible]) if visible else []
        if len(values) and not logy:
            lo, hi = values.min(), values.max()
            pad = 0.05 * (hi - lo) or 1
            ax.set_ylim(lo - pad, hi + pad)
    if not visible:
        ax.text(0.5, 0.5, "no data", transform=ax.transAxes, ha="center", color="0.5")
    elif logy:
        ax.set_yscale("log")
    ax.set(xlabel=xlabel, ylabel=ylabel, title=title)
    ax.grid(alpha=0.3)
    handles = ax.get_legend_handles_labels()[0]
    if spans:
        handles.append(Patch(color="0.88", label="contact (stabilized mortar)"))
    ax.legend(handles=handles, fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.14),
              ncol=4 if len(handles) <= 4 else 3, frameon=False)
    save(fig, path)


def stats_series(name):
    """series() for overlay: a statistics.csv column against time."""
    return lambda run: (run.col("time"), run.col(name))


def dissipation_series(run):
    """series() for overlay: Rayleigh damping plus numerical dissipation against time."""
    numerical = run.col("numerical_dissipation")
    numerical = np.where(np.isnan(numerical), 0.0, numerical)
    return run.col("time"), run.col("damping_dissipation") + numerical


def bouncing_block_figures(runs, figs, args, spans):
    """The bouncing block figures (energies, Newton iterations, pressure snapshot, balance)."""
    for name, label in [("elastic_energy", "elastic energy (J/m)"),
                        ("kinetic_energy", "kinetic energy (J/m)")]:
        overlay(runs, figs / f"bouncing_block_{name}.png", stats_series(name), label,
                f"Bouncing block: {label.split(' (')[0]}", spans=spans)
    overlay(runs, figs / "bouncing_block_cumulative_newton.png",
            stats_series("cumulative_newton_iterations"), "cumulative Newton iterations",
            "Bouncing block: cumulative Newton iterations", spans=spans)
    overlay(runs, figs / "bouncing_block_dissipation.png", dissipation_series,
            "dissipated energy (J/m)",
            "Bouncing block: Rayleigh damping + numerical dissipation", spans=spans, logy=True)
    overlay(runs, figs / "bouncing_block_energy_balance_error.png",
            stats_series("energy_balance_error"), "energy balance error (J/m)",
            "Bouncing block: energy balance error", spans=spans)
    target = args.snapshot_time
    if target is None:
        target = 0.5 * (spans[0][0] + spans[0][1]) if spans else 1.0

    def snapshot(run):
        shots = run.snapshots()
        if not shots:
            return None
        t, path = min(shots, key=lambda s: abs(s[0] - target))
        c = bench_common.read_csv(path)
        first_pair = c["pair"] == 0
        x, pressure = c["x"][first_pair], c["pressure"][first_pair]
        order = np.argsort(x)
        return x[order], pressure[order], f"t = {t:g} s"

    overlay(runs, figs / "bouncing_block_pressure_snapshot.png", snapshot,
            "contact pressure (Pa)", f"Bouncing block: contact pressure near t = {target:.3g} s",
            xlabel="x of the block's bottom nodes (m)", marker="o")


def ironing_figures(runs, figs, args, analyses, f_pass):
    """The ironing figures (node pressure, close-up, spectrum, balance, Newton)."""
    for prefix, keys, what in [("ironing", FRICTIONLESS, "frictionless"),
                               ("ironing_friction", FRICTION, "mu = 0.25")]:
        group = [r for r in runs if r.key in keys]
        point = next((r.point for r in group if r.ok and r.history()), "")
        label = f"contact pressure of the tool node {point}"
        overlay(group, figs / f"{prefix}_node_pressure.png", Run.history, label,
                f"Ironing ({what}): nodal contact pressure")
        overlay(group, figs / f"{prefix}_node_pressure_closeup.png", Run.history, label,
                f"Ironing ({what}): nodal contact pressure, close-up", xlim=args.closeup)
        window = "Hann window" if not args.no_hann else "no window"
        overlay(group, figs / f"{prefix}_pressure_spectrum.png",
                lambda r: analyses[r.key].get("spectrum") or f"window < {args.min_window:g} s",
                "amplitude of the pressure",
                f"Ironing ({what}): pressure spectrum, t >= {args.window_start:g} s, {window}",
                xlabel="frequency (Hz)", logy=True, xlim=(0, 0.5 / spectrum_dt(runs, args)),
                vlines=[(f_pass, f"element passage {f_pass:.3g} Hz")])
    overlay(runs, figs / "ironing_dissipation.png", dissipation_series, "dissipated energy",
            "Ironing: Rayleigh damping + numerical dissipation", logy=True)
    overlay(runs, figs / "ironing_energy_balance_error.png", stats_series("energy_balance_error"),
            "energy balance error", "Ironing: energy balance error")
    overlay(runs, figs / "ironing_cumulative_newton.png",
            stats_series("cumulative_newton_iterations"), "cumulative Newton iterations",
            "Ironing: cumulative Newton iterations")


def spectrum_dt(runs, args):
    """Sampling step of the spectra: --spectrum-dt or the reference run's base time step."""
    if args.spectrum_dt:
        return args.spectrum_dt
    return next((r.base_dt for r in runs if r.ok), 0.01)


def default_element_length(runs):
    """Primary (substrate top) element length of the built-in ironing scene.

    source/scenes/ironing.cc builds the substrate with scaled(200, f) = max(1, round(200 f))
    uniform elements along its top x in [0, 12] (f: Scene/Refinement factor)."""
    prm = next((r.prm for r in runs if r.prm), {})
    if prm.get("Scene/Mesh file"):
        print("warning: ironing uses a mesh file; pass --element-length")
    f = float(prm.get("Scene/Refinement factor", 1))
    return 12.0 / max(1, round(200 * f))


def metrics(run, spans_merge_gap, signal):
    """The table numbers of one run; signal(run, spans) -> signal_analysis() dict or None."""
    row = dict(variant=run.label, run=run.dir.name, status=run.short, reason=run.status)
    if not run.ok:
        return row
    t, ke = run.col("time"), run.col("kinetic_energy")
    spans, raw = contact_spans(run, spans_merge_gap)
    steps = int(run.col("step")[-1])
    newton = run.col("cumulative_newton_iterations")[-1]
    in_contact = np.zeros(len(t), bool)
    for s, e in spans:
        in_contact |= (t >= s) & (t <= e)
    eb = np.abs(run.col("energy_balance_error"))
    total = np.max(ke + run.col("elastic_energy"))
    row.update(steps=steps, first_contact=spans[0][0] if spans else math.nan,
               second_contact=spans[1][0] if len(spans) > 1 else math.nan, contact_spans=raw,
               ke_before=np.max(ke[t < spans[0][0]]) if spans else np.max(ke),
               ke_contact=np.max(ke[in_contact]) if in_contact.any() else math.nan,
               eb_max=eb.max(), eb_rel=100 * eb.max() / total if total > 0 else math.nan,
               contact_work_max=np.nanmax(run.col("contact_work")),
               damping_end=run.col("damping_dissipation")[-1],
               numerical_end=run.col("numerical_dissipation")[-1],
               newton=int(newton), newton_per_step=newton / max(steps, 1),
               cuts=int(run.col("time_step_cuts")[-1]), wall=run.wall)
    row.update(signal(run, spans) or {})
    return row


def stop_notes(rows):
    """A footnote per stopped variant with the simulator's reason."""
    return [f"{r['variant']}: {r['reason']}." for r in rows
            if r.get("reason") and r["reason"] != r["status"]]


def fmt(value, spec):
    """A table cell: '–' for missing numbers."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "–"
    return format(value, spec) if spec else str(value)


def table(rows, columns, title, notes):
    """A Markdown table with a title and footnotes."""
    lines = [f"## {title}", "", "| " + " | ".join(h for _, h, _ in columns) + " |",
             "|" + "---|" * len(columns)]
    for row in rows:
        lines.append("| " + " | ".join(fmt(row.get(k), s) for k, _, s in columns) + " |")
    return "\n".join(lines + [""] + [f"{i + 1}. {n}" for i, n in enumerate(notes)] + [""])


def columns(unit, bouncing):
    """(key, header, format) of the table columns of one benchmark."""
    cols = [("variant", "variant", ""), ("status", "status", ""), ("steps", "steps", "d"),
            ("first_contact", "first contact (s)", ".4g")]
    if bouncing:
        cols += [("second_contact", "second contact (s)", ".4g"),
                 ("contact_spans", "contact spans (raw)", "d")]
    cols += [("ke_before", f"peak KE before contact{unit}", ".4g"),
             ("ke_contact", f"peak KE in contact{unit}", ".4g"),
             ("eb_max", f"max abs energy balance error{unit}", ".4g"),
             ("eb_rel", "same, % of max(KE+EE)", ".3g"),
             ("damping_end", f"Rayleigh damping dissipation at the end{unit}", ".4g"),
             ("numerical_end", f"numerical dissipation at the end{unit}", ".4g")]
    if bouncing:
        cols.append(("contact_work_max", f"max contact work{unit}", ".4g"))
    signal = "F_y" if bouncing else "p"
    return cols + [("newton", "Newton iterations", "d"), ("newton_per_step", "Newton/step", ".3g"),
                   ("cuts", "step cuts", "d"), ("wall", "wall time (s)", ".4g"),
                   ("mean", f"mean {signal}", ".4g"), ("f_dom", "dominant f (Hz)", ".4g"),
                   ("amp_rel", "amplitude (% of mean)", ".3g")] + \
        ([] if bouncing else [("amp_mark", "amplitude at element passage (% of mean)", ".3g")]) + \
        [("rms_rel", "RMS dev. from trend (% of mean)", ".3g"),
         ("alternation", "step-to-step alternation (% of mean)", ".3g")]


def common_notes(args):
    """Footnotes shared by both tables."""
    window = "a Hann window" if not args.no_hann else "no window (rectangular)"
    return ["Contact times are those of the first statistics row with active contact nodes "
            "(end of the step in which contact is detected).",
            "Energy balance error = KE + EE + dissipation - external work - initial energy; "
            "relative to the run's largest KE + EE (kinetic plus elastic energy). The "
            "dissipation is the Rayleigh damping's, friction's and, with generalized-alpha, "
            "the time integrator's (numerical dissipation: what the bulk lost beyond its "
            "physical account), so the error is the work of the contact forces that friction "
            "does not explain.",
            f"Signal analysis: the signal is interpolated linearly onto a uniform grid (step "
            f"below), a linear trend removed, {window} applied; dominant f = largest "
            f"single-sided amplitude (2|FFT|/sum(window)) at f >= {args.min_frequency:g} Hz, "
            f"only for windows of at least {args.min_window:g} s. RMS dev. from trend = RMS of "
            f"the signal minus its centred {args.trend_window:g} s moving average, in % of the mean. "
            "Step-to-step alternation = RMS of the resampled signal's second difference / 4 (the "
            "amplitude of an alternation at the Nyquist frequency; a resolved oscillation of "
            "amplitude A and angular frequency w contributes sin^2(w dt / 2) A / sqrt(2)), in % "
            "of the mean."]


def shown(path):
    """A path relative to the repository if it is inside it."""
    path = Path(path).resolve()
    return path.relative_to(REPO) if path.is_relative_to(REPO) else path


def parse_args():
    """Command line."""
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--output-root", default=REPO / "output", type=Path)
    p.add_argument("--figures", default=REPO / "doc/figures/benchmarks", type=Path)
    p.add_argument("--tables", default=REPO / "doc/benchmarks-tables.md", type=Path)
    p.add_argument("--csv", default=REPO / "benchmarks/results/paper_benchmarks.csv", type=Path)
    p.add_argument("--element-length", type=float,
                   help="ironing primary element length (default: from the scene, 12/200 at refinement 1)")
    p.add_argument("--sliding-speed", type=float, default=1.0, help="ironing tool speed (default 1)")
    p.add_argument("--window-start", type=float, default=2.5, help="ironing steady-sliding window start (s)")
    p.add_argument("--min-window", type=float, default=1.0, help="shortest window for a spectrum (s)")
    p.add_argument("--min-frequency", type=float, default=2.0, help="lowest dominant frequency (Hz)")
    p.add_argument("--trend-window", type=float, default=0.2, help="moving-average trend width (s)")
    p.add_argument("--spectrum-dt", type=float,
                   help="ironing resampling step (default: the base time step)")
    p.add_argument("--no-hann", action="store_true", help="no Hann window before the FFT")
    p.add_argument("--closeup", type=float, nargs=2, default=(4.0, 5.0), help="ironing close-up (s)")
    p.add_argument("--snapshot-time", type=float,
                   help="bouncing block pressure snapshot time (default: middle of the first contact)")
    p.add_argument("--merge-gap", type=float, default=0.25, help="merge contact spans this close (s)")
    return p.parse_args()


def main():
    """Read the runs, write the figures, the tables and the CSV."""
    args = parse_args()
    args.figures.mkdir(parents=True, exist_ok=True)
    runs = {b: [Run(args.output_root, b, k, label) for k, label in v] for b, v in VARIANTS.items()}
    for r in runs["bouncing_block"] + runs["ironing"]:
        print(f"{r.dir}: {r.status}")

    # Bouncing block: the signal is the total contact force in the run's first contact span.
    def bb_signal(run, spans):
        return spans and signal_analysis(run.col("time"), run.col("contact_force_y"),
                                         spans[0][0], spans[0][1], args, run.base_dt)

    # Ironing: the signal is the monitored node's pressure from --window-start on.
    def ir_signal(run, spans):
        history = run.history()
        return history and signal_analysis(*history, args.window_start, math.inf, args, dt,
                                           f_pass)

    bb = runs["bouncing_block"]
    bb_rows = [metrics(r, args.merge_gap, bb_signal) for r in bb]
    ref_spans = contact_spans(bb[0], args.merge_gap)[0] if bb[0].ok else []
    # a benchmark without any run keeps its figures (e.g. after --only)
    if any(r.ok for r in bb):
        bouncing_block_figures(bb, args.figures, args, ref_spans)

    ir = runs["ironing"]
    dt = spectrum_dt(ir, args)
    h = args.element_length or default_element_length(ir)
    f_pass = args.sliding_speed / h
    ir_rows = [metrics(r, args.merge_gap, ir_signal) for r in ir]
    if any(r.ok for r in ir):
        ironing_figures(ir, args.figures, args, dict(zip([r.key for r in ir], ir_rows)), f_pass)

    notes = common_notes(args)
    text = "\n".join([
        "# Paper benchmarks: measured figures", "",
        f"Generated by `benchmarks/paper_benchmarks.py` from `{shown(args.output_root)}`; "
        f"figures in `{shown(args.figures)}`.", "",
        table(bb_rows, columns(" (J/m)", True), "Bouncing block (paper section 5.1)", notes + [
            f"Contact spans separated by at most {args.merge_gap:g} s are merged (first and "
            "second contact are merged spans); 'raw' counts them unmerged.",
            "Signal: total contact force F_y (N/m) in the run's first (merged) contact span, "
            "resampled at the base step 0.025 s (Nyquist 20 Hz).",
            "Max contact work > 0: energy created by the contact forces."] + stop_notes(bb_rows)),
        table(ir_rows, columns("", False), "Ironing (paper section 5.2)", notes + [
            f"Signal: contact pressure of the monitored tool node (contact_history.csv) from "
            f"t = {args.window_start:g} s to the end of the run; resampled at dt = {dt:g} "
            f"(Nyquist {0.5 / dt:g} Hz). Element-passage frequency = sliding speed "
            f"{args.sliding_speed:g} / primary element length {h:.4g} = {f_pass:.4g} Hz.",
            "Energies are in the problem's consistent (non-dimensional) units."]
            + stop_notes(ir_rows))])
    args.tables.parent.mkdir(parents=True, exist_ok=True)
    args.tables.write_text(text)
    print(f"writing tables {args.tables}\n\n{text}")

    keys = ["benchmark", "run"] + [k for k, _, _ in columns("", True)] + ["element_passage_hz"]
    args.csv.parent.mkdir(parents=True, exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, keys, extrasaction="ignore")
        writer.writeheader()
        for bench, rows in [("bouncing_block", bb_rows), ("ironing", ir_rows)]:
            for row in rows:
                row = dict(row, benchmark=bench, element_passage_hz=f_pass if bench == "ironing" else "")
                writer.writerow({k: "" if isinstance(v, float) and not math.isfinite(v) else v
                                 for k, v in row.items()})
    print(f"writing {args.csv}")


if __name__ == "__main__":
    main()
