#!/usr/bin/env python3
"""Accuracy versus cost of the contact formulations and their settings.

Runs the simulator over parameter sweeps of five problems with an
independent or a much finer reference solution, measures the errors, the
wall time (median of repeated runs), the peak memory, Newton iterations and
time-step cuts, and writes a CSV, Markdown tables, Pareto plots and
convergence plots. One command:

  python3 benchmarks/accuracy_vs_cost.py [--quick | --full] [--reuse]

(quick: about 8 minutes on 2 cores; full: about 40 minutes, less with
--reuse after a quick run).

Problems, their reference and the swept settings:

  hertz           prm/examples/hertz.prm, quasi-static cylinder on a block;
                  Hertz formulas (half-width a, peak pressure p0, profile)
                  for the measured load. Refinement factor, formulation
                  (mortar, nts, nts with normal smoothing 0.5), Jacobian,
                  mortar segment quadrature points (full mode).
  bar_impact      prm/examples/bar_impact.prm; exact 1-D wave solution
                  (contact duration 2 L/c = 2, contact force rho c v0 h, no
                  energy lost, striker end at u_x = -0.08 at t = 3). Time
                  step, elements along the bar, stabilization, formulation.
  patch_test      prm/examples/patch_test.prm; exact uniform pressure 1000
                  and interface displacement u_y = -5e-4. Formulation,
                  refinement factor.
  bouncing_block  prm/bouncing_block/mortar_stabilized.prm, shortened (1 s
                  quick, 4 s full); a reference run of the same formulation
                  family (mortar with persistency for both mortar variants,
                  NTS for NTS) with the smallest time step / 4 and refinement
                  factor 2. Time step, formulation / stabilization.
  ironing         prm/ironing/{mortar,nts,nts_smoothed}.prm, frictionless,
                  shortened (1 s quick, 2 s full: the tool indents and
                  slides); reference: mortar with twice the refinement factor
                  of the finest compared run and half its time step (quick:
                  factor 0.5 runs against factor 1, dt 0.005; full: factors
                  0.5 and 1 against factor 2, dt 0.005). Formulation,
                  refinement factor, time step (mortar, full mode).

Generalized-alpha (rho_inf = 0.8) without Rayleigh damping: points for the
bar impact (80 elements, every dt, exact reference), the bouncing block
(every dt, against a generalized-alpha reference at factor 2, smallest
dt / 4) and ironing (every factor at dt 0.01, against a generalized-alpha
reference at the finest factor, dt 0.005); run ids contain '_ga_'.

Errors of every run (where the problem defines them): contact pressure
(Hertz profile and peak, patch test, pressure history of a monitored node),
half-width (Hertz), contact duration (bar), energy (bar: energy change;
all: the energy balance error of statistics.csv), a displacement at a
probe point (bar: striker end; patch test: interface; bouncing block: gap
history of the block's bottom centre; ironing: final displacement of the
tool tip) and contact force histories against the reference.

Each run goes to benchmarks/results/accuracy/<run-id>/ (run.prm, run.log,
statistics.csv, contact_history.csv, the first and last contact_surface CSV
where needed, run.json with the timings); VTU files are deleted. The
results are benchmarks/results/accuracy_vs_cost.csv (one row per run, also
accuracy_vs_cost_<mode>.csv), benchmarks/results/accuracy_rates.csv (fitted
convergence rates), the Markdown tables benchmarks/results/
accuracy_vs_cost_tables.md and doc/accuracy-vs-cost-tables.md, and the
figures doc/figures/accuracy/<problem>_pareto.png, convergence_h.png,
convergence_dt.png.

Wall times are those of the whole process (start-up, mesh, output of the
CSVs and of the first and last VTU files where the contact surface is
needed); with --jobs > 1 runs share the cores and the times are not those
of an idle machine; the load average at the end is recorded. Needs numpy
and matplotlib (Debian: apt-get install python3-numpy python3-matplotlib);
`--help` lists every option.
"""
import argparse
import csv
import hashlib
import json
import math
import os
import re
import signal
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from plot_env import np, plt  # noqa: E402  (numpy, matplotlib with Agg; re-exec if missing)
import bench_common  # noqa: E402  (parameter files with changed entries, CSV files by name)

REPO = Path(__file__).resolve().parent.parent
NEVER = 1000000  # a VTU interval that writes only the first and the last step
PROBLEMS = ["hertz", "bar_impact", "patch_test", "bouncing_block", "ironing"]
IRONING_END = {"quick": 1.0, "full": 2.0}
# probe points (reference coordinates, as in the shipped files' Monitored points)
PROBE = {"bouncing_block": (-1.5, 0.0), "ironing": (1.2, 4.02)}
# the part of an ironing history compared with the reference: after the
# first contact has built up (contact starts at t = 0.04, the tool moves
# down by t/2 and sideways by t)
IRONING_FROM = 0.2

# ---------------------------------------------------------------------------
# Runs
# ---------------------------------------------------------------------------

class Run:
    """One simulation: its parameters, what it sweeps, its outcome."""

    def __init__(self, problem, run_id, base, changes, meta, keep_surface=False,
                 reference=False):
        self.problem, self.id, self.base = problem, run_id, base
        self.changes, self.meta = dict(changes), dict(meta)
        self.keep_surface, self.reference = keep_surface, reference
        self.result = {}

    def prm_changes(self, results_dir):
        """The entries this run changes in its base file."""
        self.dir = results_dir / "accuracy" / self.id
        changes = dict(self.changes)
        changes["Output/Output directory"] = str(self.dir)
        if not self.keep_surface:
            changes["Output/VTU interval"] = 0
        return changes

    def prm_text(self, results_dir):
        """run.prm: includes the base file, then sets the changed entries."""
        return bench_common.prm_with_changes(REPO / self.base, self.prm_changes(results_dir))


def variant_label(meta):
    """Legend label of a formulation + settings (what a marker stands for)."""
    f = meta["formulation"]
    label = {"mortar": "mortar", "nts": "NTS", "nts smoothed": "NTS smoothed"}[f]
    parts = []
    if meta.get("stabilization") and meta["stabilization"] != "-":
        parts.append(meta["stabilization"])
    if meta.get("jacobian") == "approximate":
        parts.append("approx. J")
    q = meta.get("quadrature")
    if q not in (None, "", "-") and int(float(q)) != 2:
        parts.append(f"{int(float(q))} qp")
    if meta.get("scheme") not in (None, "", "newmark"):
        parts.append(f"{meta['scheme']}, undamped")
    if str(meta.get("degree", "1")) in ("2", "2.0"):
        parts.append("degree 2")
    if meta.get("problem") == "bouncing_block" and str(meta.get("refinement")) in ("2", "2.0") \
            and meta.get("reference") not in (None, "", "(is a reference)"):
        parts.append("mesh x2")
    return label + (", " + ", ".join(parts) if parts else "")


def formulation_changes(formulation, stabilization=None, jacobian="exact", quadrature=None,
                        c_n=None):
    """Parameter changes selecting a formulation and its settings."""
    ch = {"Contact/Formulation": "nts" if formulation.startswith("nts") else "mortar"}
    sub = "Contact/Mortar/" if formulation == "mortar" else "Contact/Node to segment/"
    ch[sub + "Jacobian"] = jacobian
    if stabilization:
        ch[sub + "Stabilization"] = stabilization
    if formulation.startswith("nts"):
        ch[sub + "Normal smoothing distance"] = 0.5 if formulation == "nts smoothed" else 0
    if quadrature and formulation == "mortar":
        ch[sub + "Segment quadrature points"] = quadrature
    if c_n is not None:
        ch[sub + "c_n"] = c_n
    return ch


# generalized-alpha with rho_inf = 0.8 instead of Newmark, and no Rayleigh
# damping (issue 19): the scheme's label and its parameter changes
GENERALIZED_ALPHA = "gen.-alpha 0.8"


def generalized_alpha_changes(bodies):
    ch = {"Time integration/Scheme": "generalized-alpha",
          "Time integration/Spectral radius at infinity": 0.8}
    for body in bodies:
        ch[f"Body {body}/Rayleigh stiffness coefficient"] = 0
    return ch


def build_runs(mode):
    full = mode == "full"
    runs = []

    # Hertz: 4 load steps; the last contact_surface CSV is needed
    factors = [0.5, 1, 2] if full else [0.5, 1]
    variants = [("mortar", "exact", 2), ("mortar", "approximate", 2),
                ("nts", "exact", None), ("nts smoothed", "exact", None)]
    if full:
        variants += [("mortar", "exact", 4), ("nts", "approximate", None)]
    for f in factors:
        for form, jac, q in variants:
            meta = dict(formulation=form, stabilization="-", jacobian=jac,
                        quadrature=q if q else "-", refinement=f, elements="", dt=0.25)
            ch = formulation_changes(form, jacobian=jac, quadrature=q)
            ch.update({"Scene/Refinement factor": f, "Output/VTU interval": NEVER})
            rid = f"hertz_{form.replace(' ', '_')}_{jac}" + (f"_q{q}" if q else "") + f"_r{f:g}"
            runs.append(Run("hertz", rid, "prm/examples/hertz.prm", ch, meta, keep_surface=True))
    # elements of degree 2 (issue 41) on half the factor: the same nodes
    for f in factors:
        meta = dict(formulation="mortar", stabilization="-", jacobian="exact", quadrature=2,
                    refinement=f / 2, elements="", dt=0.25, degree=2)
        ch = formulation_changes("mortar", quadrature=2)
        ch.update({"Scene/Refinement factor": f / 2, "Output/VTU interval": NEVER,
                   "Finite element/Polynomial degree": 2})
        runs.append(Run("hertz", f"hertz_mortar_exact_q2_r{f / 2:g}_p2", "prm/examples/hertz.prm",
                        ch, meta, keep_surface=True))

    # Bar impact: exact 1-D answer
    dts = [0.025, 0.0125, 0.00625] + ([0.003125] if full else [])
    for form in ["mortar", "nts"]:
        stabilizations = ["persistency", "none"]
        if form == "mortar":  # the paper's condition and the energy-exact option
            stabilizations += ["velocity persistency", "velocity update"]
        for stab in stabilizations:
            for n in [20, 40, 80]:
                for dt in dts:
                    meta = dict(formulation=form, stabilization=stab, jacobian="exact",
                                quadrature="-", refinement="", elements=n, dt=dt)
                    ch = formulation_changes(form, stabilization=stab, c_n=10)
                    ch.update({"Scene/Bar impact/Elements along bar": n,
                               "Time integration/Time step": dt,
                               "Output/VTU interval": NEVER})
                    rid = f"bar_{form}_{stab.replace(' ', '_')}_n{n}_dt{dt:g}"
                    runs.append(Run("bar_impact", rid, "prm/examples/bar_impact.prm", ch, meta,
                                    keep_surface=True))
    # generalized-alpha (the bar has no damping): what its dissipation costs
    for dt in dts:
        meta = dict(formulation="mortar", stabilization="persistency", scheme=GENERALIZED_ALPHA,
                    jacobian="exact", quadrature="-", refinement="", elements=80, dt=dt)
        ch = formulation_changes("mortar", stabilization="persistency", c_n=10)
        ch.update(generalized_alpha_changes([]))
        ch.update({"Scene/Bar impact/Elements along bar": 80, "Time integration/Time step": dt,
                   "Output/VTU interval": NEVER})
        runs.append(Run("bar_impact", f"bar_mortar_persistency_ga_n80_dt{dt:g}",
                        "prm/examples/bar_impact.prm", ch, meta, keep_surface=True))

    # degree 2 (issue 41) with half the elements (the same nodes)
    for n in [10, 20, 40]:
        for dt in dts:
            meta = dict(formulation="mortar", stabilization="persistency", jacobian="exact",
                        quadrature="-", refinement="", elements=n, dt=dt, degree=2)
            ch = formulation_changes("mortar", stabilization="persistency", c_n=10)
            ch.update({"Scene/Bar impact/Elements along bar": n, "Time integration/Time step": dt,
                       "Output/VTU interval": NEVER, "Finite element/Polynomial degree": 2})
            runs.append(Run("bar_impact", f"bar_mortar_persistency_n{n}_dt{dt:g}_p2",
                            "prm/examples/bar_impact.prm", ch, meta, keep_surface=True))

    # Patch test: one quasi-static step
    for form in ["mortar", "nts"]:
        for f in [1, 2, 4]:
            meta = dict(formulation=form, stabilization="-", jacobian="exact", quadrature="-",
                        refinement=f, elements="", dt=1)
            ch = formulation_changes(form)
            # the shipped file leaves the upper block's x translation free
            # (frictionless contact, nu = 0: a rigid-body mode that Newton can
            # follow off the lower block); x = 0 on its top keeps the exact
            # solution (no lateral strain with nu = 0) and removes the mode
            ch.update({"Scene/Refinement factor": f, "Output/VTU interval": NEVER,
                       "Boundary conditions/Dirichlet":
                       "lower_bottom: xy: 0; upper_top: x: 0; upper_top: y: -1e-3*t"})
            runs.append(Run("patch_test", f"patch_{form}_r{f:g}", "prm/examples/patch_test.prm",
                            ch, meta, keep_surface=True))

    # Bouncing block, shortened, against fine references of the same family
    end = 4.0 if full else 1.0
    bb_dts = [0.05, 0.025, 0.0125]
    ref_dt = min(bb_dts) / 4
    families = {("mortar", "persistency"): "mortar", ("mortar", "none"): "mortar",
                ("nts", "none"): "nts"}
    refs = {"mortar": ("mortar", "persistency"), "nts": ("nts", "none")}

    def bb_changes(form, stab, dt, factor):
        ch = formulation_changes(form, stabilization=stab)
        if form == "nts":  # as prm/bouncing_block/nts.prm
            ch.update({"Contact/Node to segment/c_n": "1e6",
                       "Contact/Node to segment/Capture tolerance": "1e-5"})
        ch.update({"Time integration/End time": end, "Time integration/Time step": dt,
                   "Scene/Refinement factor": factor})
        return ch

    for fam, (form, stab) in refs.items():
        meta = dict(formulation=form, stabilization=stab, jacobian="exact", quadrature="-",
                    refinement=2, elements="", dt=ref_dt, end_time=end)
        runs.append(Run("bouncing_block", f"bbref_{form}_{stab}_T{end:g}",
                        "prm/bouncing_block/mortar_stabilized.prm",
                        bb_changes(form, stab, ref_dt, 2), meta, reference=True))
    for (form, stab), fam in families.items():
        for dt in bb_dts:
            meta = dict(formulation=form, stabilization=stab, jacobian="exact", quadrature="-",
                        refinement=1, elements="", dt=dt, end_time=end,
                        reference=f"bbref_{refs[fam][0]}_{refs[fam][1]}_T{end:g}",
                        mortar_reference=f"bbref_mortar_persistency_T{end:g}")
            runs.append(Run("bouncing_block", f"bb_{form}_{stab}_dt{dt:g}_T{end:g}",
                            "prm/bouncing_block/mortar_stabilized.prm",
                            bb_changes(form, stab, dt, 1), meta))
    # the reference mesh with the coarse steps: the time-step error alone
    for dt in bb_dts:
        meta = dict(formulation="mortar", stabilization="persistency", jacobian="exact",
                    quadrature="-", refinement=2, elements="", dt=dt, end_time=end,
                    reference=f"bbref_mortar_persistency_T{end:g}",
                    mortar_reference=f"bbref_mortar_persistency_T{end:g}")
        runs.append(Run("bouncing_block", f"bb_mortar_persistency_r2_dt{dt:g}_T{end:g}",
                        "prm/bouncing_block/mortar_stabilized.prm",
                        bb_changes("mortar", "persistency", dt, 2), meta))
    # degree 2 (issue 41) on half the factor (the same nodes)
    for dt in bb_dts:
        meta = dict(formulation="mortar", stabilization="persistency", jacobian="exact",
                    quadrature="-", refinement=0.5, elements="", dt=dt, end_time=end, degree=2,
                    reference=f"bbref_mortar_persistency_T{end:g}",
                    mortar_reference=f"bbref_mortar_persistency_T{end:g}")
        runs.append(Run("bouncing_block", f"bb_mortar_persistency_dt{dt:g}_T{end:g}_p2",
                        "prm/bouncing_block/mortar_stabilized.prm",
                        dict(bb_changes("mortar", "persistency", dt, 0.5),
                             **{"Finite element/Polynomial degree": 2}), meta))
    # generalized-alpha without Rayleigh damping, against its own fine
    # reference (the undamped model: the numerical damping vanishes with dt)
    ga_ref = f"bbref_mortar_persistency_ga_T{end:g}"
    ga = generalized_alpha_changes(["block", "substrate"])
    meta = dict(formulation="mortar", stabilization="persistency", scheme=GENERALIZED_ALPHA,
                jacobian="exact", quadrature="-", refinement=2, elements="", dt=ref_dt,
                end_time=end)
    runs.append(Run("bouncing_block", ga_ref, "prm/bouncing_block/mortar_stabilized.prm",
                    dict(bb_changes("mortar", "persistency", ref_dt, 2), **ga), meta,
                    reference=True))
    for dt in bb_dts:
        meta = dict(formulation="mortar", stabilization="persistency", scheme=GENERALIZED_ALPHA,
                    jacobian="exact", quadrature="-", refinement=1, elements="", dt=dt,
                    end_time=end, reference=ga_ref, mortar_reference=ga_ref)
        runs.append(Run("bouncing_block", f"bb_mortar_persistency_ga_dt{dt:g}_T{end:g}",
                        "prm/bouncing_block/mortar_stabilized.prm",
                        dict(bb_changes("mortar", "persistency", dt, 1), **ga), meta))

    # Ironing, frictionless, shortened, against a finer mortar reference.
    # The shipped files differ only in the formulation block; their own
    # c_n, capture tolerance, stabilization (mortar: velocity persistency,
    # the paper's condition; NTS: none)
    # and minimum time step are kept.
    end = IRONING_END[mode]
    factors = [0.5, 1] if full else [0.5]
    ref_factor, ref_dt = 2 * max(factors), 0.005
    files = {"mortar": "prm/ironing/mortar.prm", "nts": "prm/ironing/nts.prm",
             "nts smoothed": "prm/ironing/nts_smoothed.prm"}
    ref_id = f"ironref_mortar_r{ref_factor:g}_dt{ref_dt:g}_T{end:g}"

    def iron_changes(dt, factor):
        return {"Time integration/End time": end, "Time integration/Time step": dt,
                "Scene/Refinement factor": factor, "Output/VTU interval": NEVER}
    meta = dict(formulation="mortar", stabilization="velocity persistency", jacobian="exact",
                quadrature="-", refinement=ref_factor, elements="", dt=ref_dt, end_time=end)
    runs.append(Run("ironing", ref_id, files["mortar"], iron_changes(ref_dt, ref_factor), meta,
                    keep_surface=True, reference=True))
    cases = [(form, f, 0.01) for f in factors for form in files]
    if full:
        cases.append(("mortar", 1, 0.02))
    for form, f, dt in cases:
        meta = dict(formulation=form,
                    stabilization="velocity persistency" if form == "mortar" else "none",
                    jacobian="exact", quadrature="-", refinement=f, elements="", dt=dt,
                    end_time=end, reference=ref_id)
        rid = f"iron_{form.replace(' ', '_')}_r{f:g}_dt{dt:g}_T{end:g}"
        runs.append(Run("ironing", rid, files[form], iron_changes(dt, f), meta,
                        keep_surface=True))
    # degree 2 (issue 41) on half the factor (the same nodes)
    for f in factors:
        meta = dict(formulation="mortar", stabilization="velocity persistency", jacobian="exact",
                    quadrature="-", refinement=f / 2, elements="", dt=0.01, end_time=end,
                    reference=ref_id, degree=2)
        runs.append(Run("ironing", f"iron_mortar_r{f / 2:g}_dt0.01_T{end:g}_p2", files["mortar"],
                        dict(iron_changes(0.01, f / 2), **{"Finite element/Polynomial degree": 2}),
                        meta, keep_surface=True))
    # generalized-alpha without Rayleigh damping, against its own reference
    # (the undamped model, the finest compared mesh, dt 0.005)
    ga = generalized_alpha_changes(["tool", "substrate"])
    ga_ref = f"ironref_mortar_ga_r{max(factors):g}_dt{ref_dt:g}_T{end:g}"
    meta = dict(formulation="mortar", stabilization="velocity persistency",
                scheme=GENERALIZED_ALPHA, jacobian="exact", quadrature="-",
                refinement=max(factors), elements="", dt=ref_dt, end_time=end)
    runs.append(Run("ironing", ga_ref, files["mortar"],
                    dict(iron_changes(ref_dt, max(factors)), **ga), meta, keep_surface=True,
                    reference=True))
    for f in factors:
        meta = dict(formulation="mortar", stabilization="velocity persistency",
                    scheme=GENERALIZED_ALPHA, jacobian="exact", quadrature="-", refinement=f,
                    elements="", dt=0.01, end_time=end, reference=ga_ref)
        runs.append(Run("ironing", f"iron_mortar_ga_r{f:g}_dt0.01_T{end:g}", files["mortar"],
                        dict(iron_changes(0.01, f), **ga), meta, keep_surface=True))
    return runs


_active = {}
_active_lock = threading.Lock()


def run_process(cmd, cwd, log_path, timeout):
    """Run cmd; wall time, peak resident memory (kB) of the child, exit code, timed out."""
    with open(log_path, "w") as log:
        start = time.perf_counter()
        p = subprocess.Popen(cmd, cwd=cwd, stdout=log, stderr=subprocess.STDOUT)
        with _active_lock:
            _active[p.pid] = p
        timed_out = []

        def kill():
            timed_out.append(True)
            try:
                os.kill(p.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        timer = threading.Timer(timeout, kill) if timeout else None
        if timer:
            timer.start()
        try:
            _, status, usage = os.wait4(p.pid, 0)
        finally:
            if timer:
                timer.cancel()
            with _active_lock:
                _active.pop(p.pid, None)
        wall = time.perf_counter() - start
        p.returncode = os.waitstatus_to_exitcode(status)  # so that Popen does not wait again
    return wall, usage.ru_maxrss, p.returncode, bool(timed_out)


def kill_active():
    with _active_lock:
        for pid in list(_active):
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass


def clean_output(directory, keep_surface):
    for p in directory.glob("solution*.vtu"):
        p.unlink()
    for p in directory.glob("solution*.pvd"):
        p.unlink()
    surfaces = sorted(directory.glob("contact_surface-*.csv"))
    # only the first (reference positions) and the last contact_surface CSV are used
    for p in (surfaces[1:-1] if keep_surface else surfaces):
        p.unlink()


def execute(run, args, exe, counter):
    """Run a simulation (repeatedly if it is cheap), record timing in run.json."""
    text = run.prm_text(args.results)
    digest = hashlib.sha1((text + (REPO / run.base).read_text()
                           + str(exe.stat().st_mtime)).encode()).hexdigest()
    info_path = run.dir / "run.json"
    if args.reuse and info_path.is_file():
        info = json.loads(info_path.read_text())
        if info.get("digest") == digest:
            run.timing = info
            counter(run, reused=True)
            return
    run.dir.mkdir(parents=True, exist_ok=True)
    # outputs of an earlier run must not pass for this run's (a run that
    # stops before writing them would otherwise be scored on old files)
    for pattern in ("contact_surface-*.csv", "statistics.csv", "contact_history.csv",
                    "solution*.vtu", "solution*.pvd", "run.json"):
        for p in run.dir.glob(pattern):
            p.unlink()
    (run.dir / "run.prm").write_text(text)
    walls, rss = [], []
    repeats = 1
    while len(walls) < repeats:
        wall, maxrss, rc, timed_out = run_process([str(exe), "run.prm"], run.dir,
                                                  run.dir / "run.log", args.timeout)
        walls.append(wall)
        rss.append(maxrss)
        if rc != 0 or timed_out:
            break
        if len(walls) == 1 and wall < args.cheap_seconds and not run.reference:
            repeats = args.repeats
    clean_output(run.dir, run.keep_surface)
    log = (run.dir / "run.log").read_text(errors="replace").strip().splitlines()
    message = ""
    if rc != 0 or timed_out:
        message = "timeout after %g s" % args.timeout if timed_out else \
            next((l.strip() for l in reversed(log) if l.strip() and not l.startswith(("+", "|"))),
                 f"exit code {rc}")
    run.timing = dict(digest=digest, walls=walls, maxrss_kb=rss, returncode=rc,
                      timed_out=timed_out, message=message[:300])
    info_path.write_text(json.dumps(run.timing, indent=1))
    counter(run, reused=False)


# ---------------------------------------------------------------------------
# Reading outputs and errors
# ---------------------------------------------------------------------------

def read_csv(path):
    """{column: array} of a numeric CSV file (skips malformed lines)."""
    return bench_common.read_csv(path, units=False)


def surface_files(directory):
    return sorted(directory.glob("contact_surface-*.csv"))


def last_surface(directory, stats):
    """The contact_surface CSV of the last step, if the run wrote one (a run
    that stopped early has only that of step 0, which must not be scored)."""
    files = surface_files(directory)
    if not files or not len(stats.get("step", [])):
        return None, None
    if int(files[-1].stem.split("-")[-1]) != int(stats["step"][-1]):
        return None, None
    return read_csv(files[-1]), files[-1].name


def surface_displacement(directory, stats):
    """(x, y of step 0, u_x, u_y at the last step) of the secondary nodes of
    pair 0, or None (the CSVs list the nodes in the same order)."""
    last, _ = last_surface(directory, stats)
    files = surface_files(directory)
    if last is None or len(files) < 2:
        return None
    first = read_csv(files[0])
    a, b = first["pair"] == 0, last["pair"] == 0
    if a.sum() != b.sum() or not np.array_equal(first["node"][a], last["node"][b]):
        return None
    return (first["x"][a], first["y"][a], last["x"][b] - first["x"][a],
            last["y"][b] - first["y"][a])


def read_history(path, point):
    """time, pressure and gap of the monitored node nearest to `point` from
    contact_history.csv (columns 'pressure(x y)', 'gap(x y)'), or None."""
    if not path.is_file():
        return None
    columns = bench_common.read_csv(path)
    probes = []
    for n in columns:
        m = re.match(r"pressure(\(([-+0-9.eE]+) ([-+0-9.eE]+)\))", n)
        if m:
            probes.append((math.hypot(float(m.group(2)) - point[0],
                                      float(m.group(3)) - point[1]), m.group(1)))
    if not probes or not len(columns["time"]):
        return None
    where = min(probes)[1]
    return dict(time=columns["time"], pressure=columns["pressure" + where],
                gap=columns["gap" + where])


def energy_balance_error(stats):
    """max |energy balance error| over the run relative to max (kinetic + elastic)."""
    e = stats.get("energy_balance_error")
    if e is None or not len(e):
        return math.nan
    scale = np.max(np.abs(stats["kinetic_energy"] + stats["elastic_energy"]))
    return float(np.max(np.abs(e)) / scale) if scale > 0 else math.nan


def tributary_lengths(x, degree=1):
    """integral N_j along x (x sorted): half the distance to the neighbours,
    with degree 2 1/6, 4/6, 1/6 of each 3-node face (vertex, mid, vertex)."""
    w = np.zeros_like(x)
    if degree == 2:
        for i in range(0, len(x) - 2, 2):
            w[i:i + 3] += (x[i + 2] - x[i]) * np.array([1 / 6, 4 / 6, 1 / 6])
        return w
    if len(x) > 1:
        d = np.diff(x)
        w[:-1] += d / 2
        w[1:] += d / 2
    return w


def hertz_errors(directory, stats, degree=1):
    """Half-width, peak pressure and profile L2 errors against Hertz (as tests/hertz_cylinder.cc)."""
    s, name = last_surface(directory, stats)
    out = {}
    if s is None:
        return out
    pair0 = s["pair"] == 0
    order = np.argsort(s["x"][pair0])
    x, p = s["x"][pair0][order], s["pressure"][pair0][order]
    w = tributary_lengths(x, degree)
    P = abs(stats["contact_force_y"][-1])
    E, nu, R = 1000.0, 0.3, 1.0
    E_star = E / (2 * (1 - nu * nu))
    a = math.sqrt(4 * P * R / (math.pi * E_star))
    p0 = 2 * P / (math.pi * a)
    m0, m1, m2 = (np.sum(w * p * x ** k) for k in range(3))
    if m0 <= 0:
        return out
    centre = m1 / m0
    a_h = math.sqrt(max(0.0, 4 * (m2 / m0 - centre ** 2)))
    r = (x - centre) / a
    exact = p0 * np.sqrt(np.clip(1 - r * r, 0, None))
    active = s["active"][pair0][order] > 0
    out.update(err_half_width=a_h / a - 1, err_peak_pressure=p.max() / p0 - 1,
               err_profile_l2=math.sqrt(np.sum(w * (p - exact) ** 2) / np.sum(w * exact ** 2)),
               h=float(np.median(np.diff(x[active]))) if active.sum() > 1 else math.nan,
               load_P=P, hertz_a=a, force_balance=m0 / P - 1, active_nodes=int(active.sum()),
               surface_csv=name)
    return out


BAR = dict(L=1.0, c=1.0, v0=0.1, h=0.1, gap=0.01, rho=1.0)


def bar_end_displacement(T):
    """Exact u_x of the striker's contact end at time T: free flight, at rest
    at the wall for 2 L / c, then rebound with -v0 (stress-free)."""
    t0 = BAR["gap"] / BAR["v0"]
    t1 = t0 + 2 * BAR["L"] / BAR["c"]
    if T <= t0:
        return BAR["v0"] * T
    if T <= t1:
        return BAR["gap"]
    return BAR["gap"] - BAR["v0"] * (T - t1)


def bar_errors(directory, stats, dt):
    t, act = stats["time"], stats["active_contact_nodes"] > 0
    out = {}
    ke0 = stats["kinetic_energy"][0]
    out["energy_change"] = (stats["kinetic_energy"][-1] + stats["elastic_energy"][-1] - ke0) / ke0
    out["err_energy"] = abs(out["energy_change"])
    if act.any():
        # contact starts within the step to the first active row and ends
        # within the step after the last: duration with resolution dt
        first, last = t[act][0], t[act][-1]
        duration = last - first + dt
        out["duration"] = duration
        out["err_duration"] = abs(duration - 2 * BAR["L"] / BAR["c"]) / (2 * BAR["L"] / BAR["c"])
        flicker = np.count_nonzero(np.diff(act[(t >= first) & (t <= last)].astype(int)) != 0)
        out["contact_spans"] = 1 + flicker // 2
    else:
        out["err_duration"] = math.nan
    # contact force history against the exact step function rho c v0 h on (t0, t0 + 2 L/c)
    t0 = BAR["gap"] / BAR["v0"]
    F0 = BAR["rho"] * BAR["c"] * BAR["v0"] * BAR["h"]
    w = stats["dt"][1:]
    tt = t[1:]
    exact = np.where((tt > t0 + 1e-12) & (tt < t0 + 2 * BAR["L"] / BAR["c"] - 1e-12), F0, 0.0)
    force = -stats["contact_force_x"][1:]
    out["err_force_l2"] = math.sqrt(np.sum(w * (force - exact) ** 2) / np.sum(w * exact ** 2))
    # the same after averaging each pair of consecutive steps: without the
    # step-to-step alternation of the force
    avg, ex2, w2 = (force[1:] + force[:-1]) / 2, (exact[1:] + exact[:-1]) / 2, (w[1:] + w[:-1]) / 2
    out["err_force_avg2"] = math.sqrt(np.sum(w2 * (avg - ex2) ** 2) / np.sum(w2 * ex2 ** 2))
    out["impulse_change"] = np.sum(w * force) / (2 * BAR["rho"] * BAR["L"] * BAR["h"] * BAR["v0"]) - 1
    u = surface_displacement(directory, stats)
    if u is not None:
        exact = bar_end_displacement(t[-1])
        out["err_probe_displacement"] = abs(float(np.mean(u[2])) - exact) / abs(exact)
    return out


def patch_errors(directory, stats):
    s, name = last_surface(directory, stats)
    if s is None:
        return {}
    act = s["active"] > 0
    if not act.any():
        return dict(err_pressure_max=math.nan, active_nodes=0)
    x = np.sort(s["x"][act])
    out = dict(err_pressure_max=float(np.max(np.abs(s["pressure"][act] - 1000)) / 1000),
               h=float(np.median(np.diff(x))) if len(x) > 1 else math.nan,
               active_nodes=int(act.sum()), surface_csv=name)
    # the interface (secondary: bottom of the upper block) moves down by
    # half the applied 1e-3: both blocks are 0.5 high, equal E, nu = 0
    u = surface_displacement(directory, stats)
    if u is not None:
        out["err_probe_displacement"] = float(np.max(np.abs(u[3] + 5e-4)) / 5e-4)
    return out


def ironing_probe_displacement(directory, stats):
    """Displacement of the secondary node nearest the probe point at the last step."""
    u = surface_displacement(directory, stats)
    if u is None:
        return None
    x0, y0, ux, uy = u
    j = int(np.argmin(np.hypot(x0 - PROBE["ironing"][0], y0 - PROBE["ironing"][1])))
    return np.array([ux[j], uy[j]])


def relative_l2(t, y, tr, yr, t_from=-math.inf):
    """Relative L2-in-time error of y(t) against yr(tr) interpolated onto t,
    over t >= t_from (step lengths as weights; a run that stopped early is
    compared over the part it computed)."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    w = np.diff(t, prepend=t[0] if len(t) else 0.0)
    keep = t >= t_from
    if keep.sum() < 2:
        return math.nan
    yi = np.interp(t[keep], tr, yr)
    den = np.sum(w[keep] * yi ** 2)
    return math.sqrt(np.sum(w[keep] * (y[keep] - yi) ** 2) / den) if den > 0 else math.nan


def history_error(stats, ref, column, t_from=-math.inf):
    """Relative L2-in-time error of a statistics column against the reference
    interpolated onto the run's times (step 0 left out)."""
    return relative_l2(stats["time"][1:], stats[column][1:], ref["time"], ref[column], t_from)


def history_error_avg2(stats, ref, column):
    """As history_error, after averaging each pair of consecutive steps (run and reference).

    The mean of two consecutive values, placed at the middle time, removes the
    step-to-step alternation that the trapezoidal rule leaves in a multiplier
    (a Lagrange multiplier of a velocity-level constraint is not convergent
    pointwise, the average of consecutive values is)."""
    def mid(st):
        t, y = st["time"][1:], st[column][1:]
        return (t[1:] + t[:-1]) / 2, (y[1:] + y[:-1]) / 2, (st["dt"][2:] + st["dt"][1:-1]) / 2
    t, y, w = mid(stats)
    tr, yr_, _ = mid(ref)
    yr = np.interp(t, tr, yr_)
    den = np.sum(w * yr ** 2)
    return math.sqrt(np.sum(w * (y - yr) ** 2) / den) if den > 0 else math.nan


# ---------------------------------------------------------------------------
# Collecting results
# ---------------------------------------------------------------------------

COLUMNS = ["run_id", "problem", "formulation", "stabilization", "scheme", "jacobian",
           "quadrature", "degree",
           "refinement", "elements", "dt", "end_time", "h",
           "err_half_width", "err_peak_pressure", "err_profile_l2",
           "err_duration", "err_energy", "err_force_l2", "err_force_avg2", "energy_change",
           "impulse_change", "contact_spans",
           "err_pressure_max",
           "err_force_history", "err_force_history_avg2", "err_kinetic_energy_history",
           "err_force_vs_mortar_ref", "err_kinetic_energy_vs_mortar_ref",
           "err_force_x_history", "err_probe_pressure_history", "err_probe_gap_history",
           "err_probe_displacement", "err_energy_balance", "load_P", "hertz_a", "reference",
           "steps", "newton", "newton_per_step", "cuts", "wall_median_s", "wall_min_s", "repeats",
           "peak_memory_mb", "status", "message"]


def collect(runs):
    stats_of, history_of = {}, {}
    for run in runs:
        path = run.dir / "statistics.csv"
        stats_of[run.id] = read_csv(path) if path.is_file() else {}
        if run.problem in PROBE:
            history_of[run.id] = read_history(run.dir / "contact_history.csv", PROBE[run.problem])
    for run in runs:
        st, tm = stats_of[run.id], run.timing
        r = dict(run_id=run.id, problem=run.problem, **run.meta)
        r["end_time"] = run.meta.get("end_time", float(bench_common.prm_values(
            REPO / run.base, run.prm_changes(ARGS.results)).get("Time integration/End time", "nan")))
        walls = tm["walls"]
        ok_walls = walls if tm["returncode"] == 0 else walls[:1]
        r.update(wall_median_s=float(np.median(ok_walls)), wall_min_s=float(np.min(ok_walls)),
                 repeats=len(walls), peak_memory_mb=max(tm["maxrss_kb"]) / 1024.0,
                 message=tm.get("message", ""))
        if st and len(st.get("time", [])):
            r["steps"] = int(st["step"][-1])
            r["newton"] = int(st["cumulative_newton_iterations"][-1])
            r["newton_per_step"] = r["newton"] / max(1, r["steps"])
            r["cuts"] = int(st["time_step_cuts"][-1])
            done = st["time"][-1] >= r["end_time"] - 1e-9 * max(1.0, r["end_time"])
            r["status"] = "completed" if done and tm["returncode"] == 0 else \
                f"stopped at t={st['time'][-1]:g}"
        else:
            r["status"] = "failed"
        if st and len(st.get("time", [])) > 1:
            r["err_energy_balance"] = energy_balance_error(st)
            if run.problem == "hertz":
                r.update(hertz_errors(run.dir, st, int(float(run.meta.get("degree", 1)))))
            elif run.problem == "bar_impact":
                r.update(bar_errors(run.dir, st, run.meta["dt"]))
            elif run.problem == "patch_test":
                r.update(patch_errors(run.dir, st))
            elif run.problem == "ironing" and not run.reference:
                ref = stats_of.get(run.meta["reference"], {})
                if ref and len(ref.get("time", [])) > 1:
                    r["err_force_history"] = history_error(st, ref, "contact_force_y", IRONING_FROM)
                    r["err_force_x_history"] = history_error(st, ref, "contact_force_x",
                                                             IRONING_FROM)
                h, hr = history_of.get(run.id), history_of.get(run.meta["reference"])
                if h is not None and hr is not None:
                    r["err_probe_pressure_history"] = relative_l2(
                        h["time"], h["pressure"], hr["time"], hr["pressure"], IRONING_FROM)
                ref_run = next((x for x in runs if x.id == run.meta["reference"]), None)
                u = ironing_probe_displacement(run.dir, st)
                ur = ironing_probe_displacement(ref_run.dir, ref) if ref_run and ref else None
                if u is not None and ur is not None:
                    T = float(st["time"][-1])
                    # relative to the tool's deformation at the probe (the
                    # top is moved by (T, -T/2), the rigid part is exact)
                    deformation = ur - np.array([T, -min(T, 2.0) / 2])
                    r["err_probe_displacement"] = float(np.linalg.norm(u - ur)
                                                        / np.linalg.norm(deformation))
            elif run.problem == "bouncing_block" and not run.reference:
                ref = stats_of.get(run.meta["reference"], {})
                mref = stats_of.get(run.meta["mortar_reference"], {})
                if ref and len(ref.get("time", [])) > 1:
                    r["err_force_history"] = history_error(st, ref, "contact_force_y")
                    r["err_kinetic_energy_history"] = history_error(st, ref, "kinetic_energy")
                # one yardstick for all formulations: the stabilized mortar reference
                if mref and len(mref.get("time", [])) > 1:
                    r["err_force_vs_mortar_ref"] = history_error(st, mref, "contact_force_y")
                    r["err_force_history_avg2"] = history_error_avg2(st, mref, "contact_force_y")
                    r["err_kinetic_energy_vs_mortar_ref"] = history_error(st, mref, "kinetic_energy")
                h, hr = history_of.get(run.id), history_of.get(run.meta["mortar_reference"])
                if h is not None and hr is not None:
                    r["err_probe_pressure_history"] = relative_l2(h["time"], h["pressure"],
                                                                  hr["time"], hr["pressure"])
                    r["err_probe_gap_history"] = relative_l2(h["time"], h["gap"],
                                                             hr["time"], hr["gap"])
        if run.problem == "bar_impact":
            r["h"] = BAR["L"] / run.meta["elements"]
        if run.reference:
            r["reference"] = "(is a reference)"
        r["label"] = variant_label(r)
        run.result = r
    return [run.result for run in runs]


def fmt(v, digits=3):
    if v is None or v == "":
        return ""
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if v == 0:
            return "0"
        if abs(v) >= 1e4 or abs(v) < 1e-3:
            return f"{v:.{digits - 1}e}"
        return f"{v:.{digits}g}"
    return str(v)


def write_csv(rows, path):
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for r in rows:
            w.writerow([r.get(c, "") if not isinstance(r.get(c), float) else f"{r[c]:.6g}"
                        for c in COLUMNS])


def read_results_csv(path):
    rows = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            for k, v in list(r.items()):
                if k in ("run_id", "problem", "formulation", "stabilization", "scheme",
                         "jacobian", "status", "message", "reference"):
                    continue
                try:
                    r[k] = float(v) if v != "" else ""
                except ValueError:
                    pass
            r["label"] = variant_label(r)
            rows.append(r)
    return rows


def md_table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(fmt(x) for x in row) + " |" for row in rows]
    return "\n".join(out)


def pct(v):
    if v == "" or v is None or (isinstance(v, float) and math.isnan(v)):
        return "–"
    a = abs(v) * 100
    if a == 0:
        return "0"
    if a < 0.01:
        return f"{abs(v):.1e}"
    return f"{a:.3g} %"


def spct(v):
    """Signed percentage."""
    if v == "" or v is None or (isinstance(v, float) and math.isnan(v)):
        return "–"
    return ("+" if v > 0 else "-" if v < 0 else "") + pct(abs(v))


def tables(rows):
    """Markdown tables of all runs, by problem."""
    out = []

    def common(r):
        return [fmt(r.get("newton")), fmt(r.get("cuts")), fmt(r.get("wall_median_s")),
                fmt(r.get("peak_memory_mb"), 3), r.get("status", "")]
    by = lambda p: [r for r in rows if r["problem"] == p]  # noqa: E731
    hz = by("hertz")
    if hz:
        out.append("### Hertz (errors against the Hertz formulas for the measured load)\n")
        out.append("Signed errors (+: too large). Hertz half-width a_Hertz and load P per unit "
                   "length in the last columns but four.\n")
        out.append(md_table(["variant", "factor", "h", "a", "p0", "profile L2", "a_Hertz", "P",
                             "Newton", "cuts", "wall (s)", "MB", "status"],
                            [[r["label"], fmt(r["refinement"]), fmt(r.get("h")),
                              spct(r.get("err_half_width")), spct(r.get("err_peak_pressure")),
                              pct(r.get("err_profile_l2")), fmt(r.get("hertz_a")),
                              fmt(r.get("load_P"))] + common(r) for r in hz]))
    bar = by("bar_impact")
    if bar:
        out.append("\n### Bar impact (errors against the exact 1-D solution)\n")
        out.append(md_table(["variant", "elements", "dt", "c dt/h", "duration", "energy change",
                             "energy balance", "force L2", "force L2, 2-step avg",
                             "impulse change", "end u_x", "spans",
                             "Newton", "cuts", "wall (s)", "MB", "status"],
                            [[r["label"], fmt(r["elements"]), fmt(r["dt"]),
                              fmt(r["dt"] * r["elements"]),
                              pct(r.get("err_duration")), spct(r.get("energy_change")),
                              pct(r.get("err_energy_balance")),
                              pct(r.get("err_force_l2")), pct(r.get("err_force_avg2")),
                              spct(r.get("impulse_change")), pct(r.get("err_probe_displacement")),
                              fmt(r.get("contact_spans"))]
                             + common(r) for r in bar]))
    pt = by("patch_test")
    if pt:
        out.append("\n### Patch test (max relative pressure error over active nodes)\n")
        out.append(md_table(["variant", "factor", "h", "max |p - 1000| / 1000",
                             "max interface u_y error", "Newton", "cuts",
                             "wall (s)", "MB", "status"],
                            [[r["label"], fmt(r["refinement"]), fmt(r.get("h")),
                              pct(r.get("err_pressure_max")), pct(r.get("err_probe_displacement"))]
                             + common(r) for r in pt]))
    bb = by("bouncing_block")
    if bb:
        out.append("\n### Bouncing block (relative L2-in-time errors against the fine reference)\n")
        out.append("F_y, KE: against the reference of the same family (mortar with persistency "
                   "for both mortar variants, NTS for NTS); all other errors against the "
                   "mortar reference (mortar, persistency, factor 2, smallest dt / 4). Probe: "
                   "the monitored node at the block's bottom centre (-1.5, 0); its gap is the "
                   "block's height above the substrate (negative: penetration). Energy "
                   "balance: max |balance error| / max (kinetic + elastic energy) of the run "
                   "itself. The gen.-alpha runs (no Rayleigh damping) are compared with a "
                   "reference of their own (gen.-alpha, undamped, factor 2, smallest dt / 4) "
                   "in every column.\n")
        out.append(md_table(["variant", "dt", "factor", "F_y (family)", "KE (family)",
                             "F_y", "F_y 2-step avg",
                             "KE", "probe p", "probe gap", "energy balance",
                             "reference", "Newton", "cuts", "wall (s)", "MB",
                             "status"],
                            [[r["label"], fmt(r["dt"]), fmt(r["refinement"]),
                              pct(r.get("err_force_history")),
                              pct(r.get("err_kinetic_energy_history")),
                              pct(r.get("err_force_vs_mortar_ref")),
                              pct(r.get("err_force_history_avg2")),
                              pct(r.get("err_kinetic_energy_vs_mortar_ref")),
                              pct(r.get("err_probe_pressure_history")),
                              pct(r.get("err_probe_gap_history")),
                              pct(r.get("err_energy_balance")),
                              r.get("reference", "")] + common(r) for r in bb]))
    ir = by("ironing")
    if ir:
        out.append("\n### Ironing (relative L2-in-time errors for t >= %g against the fine "
                   "mortar reference)\n" % IRONING_FROM)
        out.append("F_y, F_x: total contact force on the tool; probe p: contact pressure of the "
                   "tool-tip node (1.2, 4.02); probe u: its displacement at the end relative to "
                   "the tool's deformation there (displacement minus the prescribed motion of "
                   "the top); energy balance: max |balance error| / max (kinetic + elastic). "
                   "The gen.-alpha runs (no Rayleigh damping) are compared with a reference of "
                   "their own (gen.-alpha, undamped, the finest compared factor, dt 0.005).\n")
        out.append(md_table(["variant", "factor", "dt", "F_y", "F_x", "probe p", "probe u",
                             "energy balance", "Newton", "cuts", "wall (s)", "MB", "status"],
                            [[r["label"] + (" (reference)" if r.get("reference") ==
                                            "(is a reference)" else ""),
                              fmt(r["refinement"]), fmt(r["dt"]),
                              pct(r.get("err_force_history")),
                              pct(r.get("err_force_x_history")),
                              pct(r.get("err_probe_pressure_history")),
                              pct(r.get("err_probe_displacement")),
                              pct(r.get("err_energy_balance"))] + common(r) for r in ir]))
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------------------
# Convergence rates
# ---------------------------------------------------------------------------

def fit_slope(x, y):
    x, y = np.asarray(x, float), np.abs(np.asarray(y, float))
    ok = np.isfinite(x) & np.isfinite(y) & (x > 0) & (y > 0)
    if ok.sum() < 2:
        return math.nan, 0
    return float(np.polyfit(np.log(x[ok]), np.log(y[ok]), 1)[0]), int(ok.sum())


def num(v):
    return v if isinstance(v, (int, float)) and v != "" else math.nan


def convergence_series(rows):
    """(kind, problem, error, label, xs, ys) of every series for rate fits."""
    series = []
    done = [r for r in rows if str(r.get("status", "")).startswith("completed")]
    hz = [r for r in done if r["problem"] == "hertz"]
    for lab in sorted({r["label"] for r in hz}):
        rs = sorted([r for r in hz if r["label"] == lab], key=lambda r: num(r.get("h")))
        for e in ["err_profile_l2", "err_half_width", "err_peak_pressure"]:
            series.append(("h", "hertz", e, lab, [num(r.get("h")) for r in rs],
                           [num(r.get(e)) for r in rs]))
    bar = [r for r in done if r["problem"] == "bar_impact"]
    if bar:
        dt_min = min(r["dt"] for r in bar)
        n_max = max(r["elements"] for r in bar)
        for lab in sorted({r["label"] for r in bar}):
            rs = sorted([r for r in bar if r["label"] == lab and r["dt"] == dt_min],
                        key=lambda r: r["h"])
            for e in ["err_energy", "err_duration", "err_force_l2", "err_force_avg2"]:
                series.append(("h", "bar_impact", e, f"{lab} (dt = {dt_min:g})",
                               [r["h"] for r in rs], [num(r.get(e)) for r in rs]))
            rs = sorted([r for r in bar if r["label"] == lab and r["elements"] == n_max],
                        key=lambda r: r["dt"])
            for e in ["err_energy", "err_duration", "err_force_l2", "err_force_avg2"]:
                series.append(("dt", "bar_impact", e, f"{lab} ({n_max:g} elements)",
                               [r["dt"] for r in rs], [num(r.get(e)) for r in rs]))
            # h and dt together at a fixed Courant number c dt / h = 0.5
            rs = sorted([r for r in bar if r["label"] == lab
                         and abs(r["dt"] * r["elements"] - 0.5) < 1e-9], key=lambda r: r["h"])
            for e in ["err_energy", "err_duration", "err_force_l2", "err_force_avg2"]:
                series.append(("h", "bar_impact", e, f"{lab} (c dt/h = 0.5)",
                               [r["h"] for r in rs], [num(r.get(e)) for r in rs]))
    pt = [r for r in done if r["problem"] == "patch_test"]
    for lab in sorted({r["label"] for r in pt}):
        rs = sorted([r for r in pt if r["label"] == lab], key=lambda r: num(r.get("h")))
        for e in ["err_pressure_max", "err_probe_displacement"]:
            series.append(("h", "patch_test", e, lab, [num(r.get("h")) for r in rs],
                           [num(r.get(e)) for r in rs]))
    bb = [r for r in done if r["problem"] == "bouncing_block" and r.get("reference")
          and r.get("reference") != "(is a reference)"]
    for lab in sorted({r["label"] for r in bb}):
        rs = sorted([r for r in bb if r["label"] == lab], key=lambda r: r["dt"])
        for e in ["err_force_vs_mortar_ref", "err_force_history_avg2",
                  "err_kinetic_energy_vs_mortar_ref", "err_probe_gap_history"]:
            series.append(("dt", "bouncing_block", e, lab, [r["dt"] for r in rs],
                           [num(r.get(e)) for r in rs]))
    ir = [r for r in done if r["problem"] == "ironing" and r.get("reference")
          and r.get("reference") != "(is a reference)"]
    for lab in sorted({r["label"] for r in ir}):
        rs = sorted([r for r in ir if r["label"] == lab and r["dt"] == 0.01],
                    key=lambda r: r["refinement"], reverse=True)
        if len(rs) > 1:  # h of the substrate's top: 12 / (200 factor)
            for e in ["err_force_history", "err_force_x_history", "err_probe_pressure_history",
                      "err_probe_displacement"]:
                series.append(("h", "ironing", e, lab, [0.06 / r["refinement"] for r in rs],
                               [num(r.get(e)) for r in rs]))
        rs = sorted([r for r in ir if r["label"] == lab and r["refinement"] == 1],
                    key=lambda r: r["dt"])
        if len(rs) > 1:
            for e in ["err_force_history", "err_probe_pressure_history"]:
                series.append(("dt", "ironing", e, lab, [r["dt"] for r in rs],
                               [num(r.get(e)) for r in rs]))
    return series


def monotone(ys):
    """'yes' if |error| decreases with every refinement (xs ascending: |ys| ascending)."""
    a = np.abs(np.asarray(ys, float))
    a = a[np.isfinite(a)]
    if len(a) < 2:
        return "–"
    return "yes" if np.all(np.diff(a) > 0) else "no"


def rates(rows):
    out = []
    for kind, problem, err, lab, xs, ys in convergence_series(rows):
        slope, n = fit_slope(xs, ys)
        out.append(dict(kind=kind, problem=problem, error=err, variant=lab, slope=slope, points=n,
                        monotone=monotone(ys),
                        x=" ".join(fmt(x) for x in xs), err=" ".join(fmt(y) for y in ys)))
    return out


# ---------------------------------------------------------------------------
# Figures
# ---------------------------------------------------------------------------

PALETTE = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown",
           "tab:pink", "tab:gray", "tab:olive", "tab:cyan"]
MARKERS = ["o", "s", "^", "D", "v", "P", "X", "<", ">", "*"]
ERROR_NAMES = {"err_profile_l2": "Hertz: profile L2 error", "err_half_width": "Hertz: |half-width error|",
               "err_peak_pressure": "Hertz: |peak pressure error|",
               "err_duration": "bar: |contact duration error|", "err_energy": "bar: energy error",
               "err_force_l2": "bar: contact force L2 error",
               "err_force_avg2": "bar: force L2 error, 2-step average",
               "err_force_history_avg2": "block: F_y history error, 2-step average",
               "err_force_vs_mortar_ref": "block: F_y history error",
               "err_kinetic_energy_vs_mortar_ref": "block: kinetic energy history error",
               "err_pressure_max": "patch test: max pressure error",
               "err_force_history": "block: F_y history error (L2 in time)",
               "err_kinetic_energy_history": "block: kinetic energy history error",
               "err_probe_gap_history": "block: probe gap (height) history error",
               "err_force_x_history": "ironing: F_x history error",
               "err_probe_pressure_history": "ironing: tool-tip pressure history error",
               "err_probe_displacement": "probe displacement error"}
PARETO = {"hertz": ["err_profile_l2", "err_half_width", "err_peak_pressure"],
          "bar_impact": ["err_energy", "err_duration", "err_force_avg2", "err_probe_displacement"],
          "patch_test": ["err_pressure_max", "err_probe_displacement"],
          "bouncing_block": ["err_force_vs_mortar_ref", "err_force_history_avg2",
                             "err_kinetic_energy_vs_mortar_ref", "err_probe_gap_history"],
          "ironing": ["err_force_history", "err_force_x_history", "err_probe_pressure_history",
                      "err_probe_displacement"]}
# the same error key means something else per problem
TITLES = {("ironing", "err_force_history"): "ironing: F_y history error (t >= %g)" % IRONING_FROM,
          ("ironing", "err_probe_displacement"): "ironing: tool-tip displacement error (end)",
          ("bar_impact", "err_probe_displacement"): "bar: striker end u_x error (t = 3)",
          ("patch_test", "err_probe_displacement"): "patch test: max interface u_y error"}


def error_name(problem, err):
    return TITLES.get((problem, err), ERROR_NAMES[err])
FLOOR = 1e-16


def style_map(labels):
    return {lab: (PALETTE[i % len(PALETTE)], MARKERS[i % len(MARKERS)])
            for i, lab in enumerate(sorted(labels))}


def pareto_front(points):
    """Indices of the points (cost, error) that no other point beats in both."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], math.inf
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def plot_pareto(rows, problem, path):
    rs = [r for r in rows if r["problem"] == problem and r.get("reference") != "(is a reference)"]
    errs = [e for e in PARETO[problem] if any(isinstance(r.get(e), float) for r in rs)]
    if not rs or not errs:
        return
    styles = style_map({r["label"] for r in rs})
    ncol = 2 if len(errs) == 4 else len(errs)
    nrow = (len(errs) + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(5.6 * ncol, 4.4 * nrow), squeeze=False)
    for ax, e in zip(axes.flat, errs):
        vals = [abs(r[e]) for r in rs if isinstance(r.get(e), float) and math.isfinite(r[e])]
        positive = [v for v in vals if v > 0]
        # an error of exactly 0 (exact to the output's precision, or to the
        # time-step resolution of the contact duration) sits on a floor line
        floor = min(positive) / 5 if positive else FLOOR
        pts = [(r["wall_median_s"], abs(r[e]) if abs(r[e]) > 0 else floor, r) for r in rs
               if isinstance(r.get(e), float) and math.isfinite(r[e])]
        if len(positive) < len(vals):
            ax.axhline(floor, color="gray", lw=0.8, ls=":")
            ax.annotate("error 0 (to output precision / step resolution)", (0.98, floor),
                        xycoords=("axes fraction", "data"), textcoords="offset points",
                        xytext=(0, -9), fontsize=7, color="gray", ha="right")
        for lab, (col, mk) in styles.items():
            sel = [p for p in pts if p[2]["label"] == lab]
            done = [p for p in sel if str(p[2]["status"]).startswith("completed")]
            stop = [p for p in sel if not str(p[2]["status"]).startswith("completed")]
            if done:
                ax.scatter([p[0] for p in done], [p[1] for p in done], color=col, marker=mk,
                           s=36, label=lab, alpha=0.85, zorder=3)
            if stop:
                ax.scatter([p[0] for p in stop], [p[1] for p in stop], facecolors="none",
                           edgecolors=col, marker=mk, s=36, zorder=3,
                           label=None if done else lab + " (stopped)")
        complete = [p for p in pts if str(p[2]["status"]).startswith("completed")]
        front = [complete[i] for i in pareto_front([(p[0], p[1]) for p in complete])]
        if front:
            fx, fy = [p[0] for p in front], [p[1] for p in front]
            ax.step(fx + [max(p[0] for p in pts) * 1.3], fy + [fy[-1]], where="post",
                    color="k", lw=1, ls="--", zorder=2, label="Pareto front")
            ax.scatter(fx, fy, s=110, facecolors="none", edgecolors="k", lw=1.2, zorder=4)
            if problem == "bar_impact":  # name the front's points (many runs)
                for p in front:
                    ax.annotate(f"n{p[2]['elements']:g}, dt {p[2]['dt']:g}", (p[0], p[1]),
                                textcoords="offset points", xytext=(4, 4), fontsize=6)
            elif problem in ("hertz", "patch_test"):
                for p in front:
                    ax.annotate(f"x{p[2]['refinement']:g}", (p[0], p[1]),
                                textcoords="offset points", xytext=(4, 4), fontsize=7)
            elif problem == "bouncing_block":
                for p in front:
                    ax.annotate(f"dt {p[2]['dt']:g}", (p[0], p[1]),
                                textcoords="offset points", xytext=(4, 4), fontsize=7)
        if problem == "ironing":  # few runs: name them all
            for p in pts:
                ax.annotate(f"x{p[2]['refinement']:g}, dt {p[2]['dt']:g}", (p[0], p[1]),
                            textcoords="offset points", xytext=(4, -9), fontsize=6)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time of the run (s, median)")
        ax.set_ylabel(error_name(problem, e) + " (relative)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=7, loc="best")
    info_path = ARGS.results / f"accuracy_run_info_{ARGS.mode}.json"
    jobs = json.loads(info_path.read_text())["jobs"] if info_path.is_file() else 1
    fig.suptitle(f"{problem.replace('_', ' ')}: accuracy versus cost (2 cores, "
                 + ("one run at a time)" if jobs == 1 else f"{jobs} runs at a time)"),
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_convergence(rows, kind, path):
    series = [s for s in convergence_series(rows) if s[0] == kind and s[1] != "patch_test"]
    panels = []
    for s in series:
        key = (s[1], s[2])
        if key not in panels:
            panels.append(key)
    if kind == "h":  # keep the figure readable: the most telling errors
        panels = [p for p in panels if p in [("hertz", "err_profile_l2"), ("hertz", "err_half_width"),
                                             ("hertz", "err_peak_pressure"),
                                             ("bar_impact", "err_energy"),
                                             ("bar_impact", "err_force_avg2"),
                                             ("ironing", "err_force_history"),
                                             ("ironing", "err_probe_pressure_history")]]
    if not panels:
        return
    ncol = min(3, len(panels))
    nrow = (len(panels) + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(5.2 * ncol, 4.2 * nrow), squeeze=False)
    styles = style_map({s[3].split(" (")[0] for s in series})

    def same(a, b):
        a, b = np.abs(np.array(a, float)), np.abs(np.array(b, float))
        return a.shape == b.shape and np.allclose(a, b, rtol=1e-3, equal_nan=True)
    for ax, (problem, err) in zip(axes.flat, panels):
        mine = [s for s in series if (s[1], s[2]) == (problem, err)]
        for _, prob, e, lab, xs, ys in mine:
            # a series equal to another one's (NTS and mortar on the bar's
            # matching meshes) is named in that one's label, not drawn again
            twin = [s for s in mine if s[3] != lab and s[3].replace("mortar", "NTS") == lab
                    and same(s[5], ys)]
            if twin:
                continue
            doubles = [s for s in mine if s[3] != lab and lab.replace("mortar", "NTS") == s[3]
                       and same(s[5], ys)]
            if doubles:
                lab = lab.replace("mortar", "mortar = NTS")
            xs, ys = np.array(xs, float), np.abs(np.array(ys, float))
            ok = np.isfinite(xs) & np.isfinite(ys) & (ys > 0)
            if ok.sum() < 1:
                continue
            slope, n = fit_slope(xs, ys)
            if monotone(ys[ok]) == "no":  # a sign change or a floor: no rate
                lab += " [not monotone]"
            col, mk = styles[lab.replace("mortar = NTS", "mortar").split(" (")[0]
                             .split(" [")[0]]
            ax.loglog(xs[ok], ys[ok], marker=mk, color=col, lw=1,
                      ls="--" if "c dt/h" in lab else "-",
                      label=f"{lab}: slope {slope:.2f}" if n >= 2 else lab)
        ax.set_xlabel("element size h along the contact" if kind == "h" else "time step dt")
        ax.set_ylabel("relative error")
        ax.set_title(error_name(problem, err), fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6)
    for ax in list(axes.flat)[len(panels):]:
        ax.axis("off")
    fig.suptitle("convergence in " + ("mesh size" if kind == "h" else "time step") +
                 " (slopes: least-squares fit of log error against log " + kind + ")", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


# ---------------------------------------------------------------------------

def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="Quick mode takes about 8 minutes on 2 cores; full mode "
                                        "about 40 (see doc/accuracy-vs-cost.md). The module "
                                        "docstring (top of the file) describes problems, "
                                        "references and outputs.")
    mode = ap.add_mutually_exclusive_group()
    mode.add_argument("--quick", dest="mode", action="store_const", const="quick",
                      help="the smaller sweep (default)")
    mode.add_argument("--full", dest="mode", action="store_const", const="full",
                      help="the larger sweep (finer meshes and steps, 4 s bouncing block)")
    ap.set_defaults(mode="quick")
    ap.add_argument("--repeats", type=int, default=3,
                    help="runs of a cheap case, the median wall time is kept (default 3)")
    ap.add_argument("--cheap-seconds", type=float, default=5.0,
                    help="a case whose first run takes less than this is cheap and repeated "
                         "(default 5 s); expensive cases and references run once")
    ap.add_argument("--jobs", type=int, default=1,
                    help="simulations at the same time (default 1; more spoils the timings)")
    ap.add_argument("--only", default="",
                    help="comma-separated problems: " + ", ".join(PROBLEMS))
    ap.add_argument("--match", default="",
                    help="with --only: only the runs whose id matches this regular expression "
                         "and the references they are compared with (e.g. '_ga_': the "
                         "generalized-alpha points)")
    ap.add_argument("--reuse", action="store_true",
                    help="keep the results of runs whose parameters and executable are unchanged")
    ap.add_argument("--plots-only", action="store_true",
                    help="run nothing: tables and figures from the results CSV")
    ap.add_argument("--csv", type=Path, default=None,
                    help="with --plots-only: the results CSV to plot (default "
                         "<results>/accuracy_vs_cost.csv; e.g. accuracy_vs_cost_quick.csv)")
    ap.add_argument("--dry-run", action="store_true",
                    help="write the parameter files and check them with --validate, run nothing")
    ap.add_argument("--self-test", action="store_true",
                    help="test the parameter-file override (benchmarks/bench_common.py)")
    ap.add_argument("--timeout", type=float, default=3600,
                    help="kill a run after this many seconds (default 3600)")
    ap.add_argument("--exe", type=Path, default=REPO / "build" / "contact-dynamics",
                    help="the simulator (default %(default)s)")
    ap.add_argument("--results", type=Path, default=REPO / "benchmarks" / "results",
                    help="run directories, CSVs and tables (default %(default)s)")
    ap.add_argument("--figures", type=Path, default=REPO / "doc" / "figures" / "accuracy",
                    help="the PNG figures (default %(default)s)")
    ap.add_argument("--doc-tables", type=Path, default=REPO / "doc" / "accuracy-vs-cost-tables.md",
                    help="a copy of the tables for the documentation, written after a run of "
                         "every problem and with --plots-only (default %(default)s)")
    args = ap.parse_args()
    if args.repeats < 1 or args.jobs < 1:
        ap.error("--repeats and --jobs need a positive integer")
    if args.match and not args.only:
        ap.error("--match needs --only (the tables of a complete run need every run)")
    return args


def main():
    global ARGS
    args = ARGS = parse_args()
    if args.self_test:
        bench_common.self_test()
        return
    csv_path = args.results / "accuracy_vs_cost.csv"
    if args.plots_only:
        rows = read_results_csv(args.csv or csv_path)
    else:
        if not args.exe.is_file():
            sys.exit(f"{args.exe} is missing: build it first (./run.sh build)")
        runs = build_runs(args.mode)
        if args.only:
            keep = set(args.only.split(","))
            unknown = keep - {r.problem for r in runs}
            if unknown:
                sys.exit(f"--only: unknown problem(s) {', '.join(sorted(unknown))}")
            runs = [r for r in runs if r.problem in keep]
        if args.match:
            # with the references the matched runs are compared with
            chosen = {r.id for r in runs if re.search(args.match, r.id)}
            chosen |= {r.meta[k] for r in runs if r.id in chosen
                       for k in ("reference", "mortar_reference") if r.meta.get(k)}
            runs = [r for r in runs if r.id in chosen]
        if args.dry_run:
            bad = 0
            for run in runs:
                text = run.prm_text(args.results)
                run.dir.mkdir(parents=True, exist_ok=True)
                (run.dir / "run.prm").write_text(text)
                p = subprocess.run([str(args.exe), "--validate", "run.prm"], cwd=run.dir,
                                   capture_output=True, text=True)
                # the values the simulator reads
                used = subprocess.run([str(args.exe), "--print-parameters", "run.prm"],
                                      cwd=run.dir, capture_output=True, text=True)
                values = bench_common.parse_prm(used.stdout)
                wrong = [k for k, v in run.prm_changes(args.results).items()
                         if values.get(k) != str(v)]
                status = "OK" if p.returncode == 0 and not wrong else \
                    f"FAILED {wrong} {p.stdout[-300:]}{p.stderr[-300:]}"
                bad += status != "OK"
                print(f"{run.id}: {status}")
            print(f"{len(runs)} parameter files, {bad} failed")
            sys.exit(1 if bad else 0)
        # references first, expensive first: parallel runs then end together
        runs.sort(key=lambda r: (not r.reference,))
        total, done, reused_count = len(runs), [0], [0]
        lock = threading.Lock()
        start = time.perf_counter()

        def counter(run, reused):
            with lock:
                done[0] += 1
                reused_count[0] += reused
                t = run.timing
                state = "reused" if reused else \
                    ("ok" if t["returncode"] == 0 else f"exit {t['returncode']}")
                print(f"[{done[0]:3d}/{total}] {run.id:48s} {np.median(t['walls']):8.2f} s "
                      f"(x{len(t['walls'])}) {max(t['maxrss_kb']) / 1024:6.0f} MB "
                      f"{state} {t.get('message', '')[:80]}  [{time.perf_counter() - start:6.0f} s]",
                      flush=True)
        print(f"{args.mode} mode: {total} runs, {args.jobs} at a time, results in "
              f"{args.results / 'accuracy'}", flush=True)
        try:
            if args.jobs == 1:
                for run in runs:
                    execute(run, args, args.exe, counter)
            else:
                with ThreadPoolExecutor(args.jobs) as pool:
                    for f in [pool.submit(execute, run, args, args.exe, counter) for run in runs]:
                        f.result()
        except KeyboardInterrupt:
            kill_active()
            sys.exit("interrupted")
        elapsed = time.perf_counter() - start
        print(f"all runs: {elapsed:.0f} s ({elapsed / 60:.1f} min)", flush=True)
        # the table in a fixed order: by problem, then as built
        order = {p: i for i, p in enumerate(PROBLEMS)}
        runs.sort(key=lambda r: order[r.problem])
        rows = collect(runs)
        if args.only and csv_path.is_file():  # keep the other problems' rows
            mine = {r["run_id"] for r in rows}
            # (with --match the other runs of the same problems stay too)
            old = [r for r in read_results_csv(csv_path)
                   if r["run_id"] not in mine and
                   (args.match or r["problem"] not in set(args.only.split(",")))]
            rows = sorted(old + rows, key=lambda r: order[r["problem"]])
        write_csv(rows, csv_path)
        if not args.only:  # a copy per mode, so that quick and full results coexist
            write_csv(rows, args.results / f"accuracy_vs_cost_{args.mode}.csv")
        info_file = args.results / f"accuracy_run_info_{args.mode}.json"
        if reused_count[0] == total and not args.only and info_file.is_file():
            print(f"every run reused: {info_file.name} (timing of the runs) kept")
        else:
            info_file.write_text(json.dumps(
                dict(mode=args.mode, jobs=args.jobs, repeats=args.repeats, seconds=elapsed,
                     runs=total, reused=reused_count[0], only=args.only,
                     date=time.strftime("%Y-%m-%d %H:%M:%S"),
                     load_average_at_end=os.getloadavg()), indent=1))
        rows = read_results_csv(csv_path)  # the same numbers as the CSV
    text = tables(rows)
    rate_rows = rates(rows)
    args.results.mkdir(parents=True, exist_ok=True)
    with open(args.results / "accuracy_rates.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["kind", "problem", "error", "variant", "slope", "points",
                                          "monotone", "x", "err"])
        w.writeheader()
        for r in rate_rows:
            w.writerow({**r, "slope": f"{r['slope']:.3f}"})
    text += "\n### Fitted convergence rates (slope of log error against log h or log dt)\n\n"
    text += ("Least-squares slope of log |error| against log h or log dt. 'monotone': the "
             "|error| falls at every refinement; where it does not (a sign change, an error "
             "floor) the slope is no convergence rate.\n\n")
    text += md_table(["in", "problem", "error", "variant", "slope", "points", "monotone", "x",
                      "errors"],
                     [[r["kind"], r["problem"], r["error"], r["variant"],
                       f"{r['slope']:.2f}" if math.isfinite(r["slope"]) else "–", r["points"],
                       r["monotone"], r["x"], r["err"]] for r in rate_rows]) + "\n"
    (args.results / "accuracy_vs_cost_tables.md").write_text(text)
    if not args.plots_only and not args.only:
        (args.results / f"accuracy_vs_cost_tables_{args.mode}.md").write_text(text)
    if not args.only:
        info_path = args.results / f"accuracy_run_info_{args.mode}.json"
        source = args.csv or csv_path
        header = ["# Accuracy versus cost: generated tables", "",
                  "Written by `benchmarks/accuracy_vs_cost.py` from `%s`; do not edit. "
                  "Explanations: [accuracy-vs-cost.md](accuracy-vs-cost.md)." % source.name, ""]
        # the run information belongs to these rows after a run, or with
        # --plots-only to the per-mode CSV of the mode given
        if info_path.is_file() and (not args.plots_only
                                    or source.name == f"accuracy_vs_cost_{args.mode}.csv"):
            info = json.loads(info_path.read_text())
            header += ["Mode `%s`, %d runs (%d reused from an earlier run with the same "
                       "parameters and binary), %.0f s of runs, %s (jobs = %d), "
                       "finished %s, load average at the end %s." % (
                           info["mode"], info["runs"], info["reused"], info["seconds"],
                           "one at a time" if info["jobs"] == 1 else
                           "%d at a time" % info["jobs"], info["jobs"], info["date"],
                           " ".join("%.2f" % x for x in info["load_average_at_end"])), ""]
        args.doc_tables.parent.mkdir(parents=True, exist_ok=True)
        args.doc_tables.write_text("\n".join(header) + text)
    print(text)
    if args.match:
        print("--match: the figures are not redrawn (they need every run; "
              "--plots-only draws them from the CSV)")
        return
    args.figures.mkdir(parents=True, exist_ok=True)
    for problem in PARETO:
        plot_pareto(rows, problem, args.figures / f"{problem}_pareto.png")
    plot_convergence(rows, "h", args.figures / "convergence_h.png")
    plot_convergence(rows, "dt", args.figures / "convergence_dt.png")
    print(f"wrote {'' if args.plots_only else str(csv_path) + ', '}"
          f"{args.results / 'accuracy_rates.csv'}, "
          f"{args.results / 'accuracy_vs_cost_tables.md'} and the figures in {args.figures}")


ARGS = None

if __name__ == "__main__":
    main()
