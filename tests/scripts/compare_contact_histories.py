# usage: compare_contact_histories.py REFERENCE_DIR RUN_DIR TOLERANCE
# Two runs of one scene at different resolutions (a uniform mesh and one
# refined near the contact): the contact impulse (trapezoidal integral of
# |contact_force_y|), the peak contact force and its time, the final energy
# (kinetic + elastic) and the numerical dissipation of the alpha schemes.
import csv, sys

ref, run, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])


def measures(d):
    r = list(csv.DictReader(open(d + "/statistics.csv")))
    f = [abs(float(x["contact_force_y"])) for x in r]
    k = max(range(len(f)), key=lambda i: f[i])
    impulse = sum(0.5 * (f[i] + f[i + 1]) * float(r[i + 1]["dt"])
                  for i in range(len(r) - 1))
    energy = float(r[-1]["kinetic_energy"]) + float(r[-1]["elastic_energy"])
    return dict(impulse=impulse, peak=f[k], peak_time=float(r[k]["time"]),
                energy=energy,
                numerical=float(r[-1].get("numerical_dissipation", 0)))


a, b = measures(ref), measures(run)
for key in ("impulse", "peak", "energy"):
    d = abs(b[key] - a[key]) / abs(a[key])
    print(f"{key}: {a[key]:.6g} against {b[key]:.6g}, relative {d:.2e}",
          "within" if d <= tol else "BEYOND", tol)
print("peak at the same time:", "yes" if a["peak_time"] == b["peak_time"] else "NO")
print("numerical dissipation positive in both:",
      "yes" if a["numerical"] > 0 and b["numerical"] > 0 else "NO",
      f"({a['numerical']:.4g}, {b['numerical']:.4g})")
