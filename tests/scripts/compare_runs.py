# usage: compare_runs.py LABEL REFERENCE_DIR RUN_DIR [COLUMN,COLUMN...]
# Two runs of the same scene that should agree to round-off (a restarted
# run against one never stopped, another process count): statistics.csv
# row by row and every contact_surface-*.csv of the reference, column by
# column, relative to each column's largest magnitude in the reference.
import csv, glob, os, sys

label, ref, run = sys.argv[1:4]
# (timings and solver counts; "node" is the surface's internal numbering,
# which a mesh rebuilt from a checkpoint may order differently: the rows
# are in the same order of position)
skip = {"wall_time", "final_residual", "linear_iterations", "node"}
# more columns to leave out (the Newton counts of two linear solvers)
if len(sys.argv) > 4:
    skip |= set(sys.argv[4].split(","))
ENERGIES = {"transfer_energy", "energy_balance_error", "contact_work",
            "obstacle_work", "damping_dissipation", "external_work",
            "numerical_dissipation", "frictional_dissipation",
            "energy_created"}


def table(path):
    rows = list(csv.reader(open(path)))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def worst_difference(path_a, path_b):
    head, a = table(path_a)
    _, b = table(path_b)
    if len(a) != len(b):
        return None
    worst = 0.
    # an energy (a small difference of large ones: transfer_energy is the
    # kinetic energy lost by a projection) against the system's energy
    energy = None
    if "kinetic_energy" in head and "elastic_energy" in head:
        ke, ee = head.index("kinetic_energy"), head.index("elastic_energy")
        energy = max(abs(r[ke]) + abs(r[ee]) for r in a) or None
    # a force component zero by symmetry against the largest one
    forces = [k for k, name in enumerate(head) if name.startswith("contact_force_")]
    force = max((abs(r[k]) for r in a for k in forces), default=0) or None
    for k, name in enumerate(head):
        if name in skip:
            continue
        scale = max(abs(r[k]) for r in a) or 1
        if energy and name in ENERGIES:
            scale = max(scale, energy)
        # (only for a component that is zero up to round-off)
        if force and k in forces and scale < 1e-8 * force:
            scale = force
        for x, y in zip(a, b):
            d = abs(x[k] - y[k]) / scale
            if not d <= worst:  # (a NaN counts as infinitely far)
                worst = d if d == d else float("inf")
    return worst


files = ["statistics.csv"] + sorted(
    os.path.basename(f) for f in glob.glob(ref + "/contact_surface-*.csv"))
worst, differ = 0., []
for f in files:
    d = worst_difference(os.path.join(ref, f), os.path.join(run, f)) \
        if os.path.exists(os.path.join(run, f)) else None
    if d is None:
        differ.append(f)
    else:
        worst = max(worst, d)
print("%s: statistics and %d surface files compared, %s, largest difference %.2e %s" % (
    label, len(files) - 1,
    "rows equal" if not differ else "rows differ in " + ", ".join(differ),
    worst, "within 1e-8" if worst <= 1e-8 else "beyond 1e-8"))
