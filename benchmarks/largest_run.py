#!/usr/bin/env python3
"""The largest run: 3-D contact at research resolution on this machine, and
what 64 and 1024 processes would do, from its measured communication.

Issue 40, item 5. Runs prm/ironing/mortar_3d_million.prm (the 3-D ironing
refined to 1,029,444 unknowns, distributed mesh, AMG) under mpirun
with Open MPI's communication monitoring (`--mca pml_monitoring_enable 2`:
bytes and messages per pair of processes, the application's own
point-to-point messages (E) apart from those of the collectives (I)), once
to its end time and once for its first step only, so that the difference is
the communication of the steps 2 to N; divided by their Newton iterations it
is the volume per Newton iteration. Whole-run time split by TimerOutput
section, peak resident memory of the largest process.

  python3 benchmarks/largest_run.py [--processes 2] [--prm FILE]
      [--end T] [--first-step T] [--table-only]

Writes benchmarks/results/largest_run.csv (one row per run) and
doc/largest-run-table.md (the runs, their split, the communication per
Newton iteration, and the estimate for 64 and 1024 processes).
"""
import argparse
import csv
import math
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_common  # noqa: E402

REPO = Path(__file__).resolve().parent.parent
SECTIONS = ["setup", "initial conditions", "Newton solve", "bulk assembly",
            "contact search", "contact assembly", "linear solve",
            "output", "energies"]
MONITOR = ["--mca", "pml_monitoring_enable", "2",
           "--mca", "pml_monitoring_enable_output", "1"]
# "E 0 1 1012 bytes 30 msgs sent": tag class, sender, receiver
_LINE = re.compile(r"^([EI])\s+(\d+)\s+(\d+)\s+(\d+) bytes\s+(\d+) msgs sent")

# The machine the estimate assumes: an InfiniBand-class network
LATENCY_S = 2e-6          # per message
BANDWIDTH_B_PER_S = 1e10  # per process
NEIGHBOURS_3D = 26        # of a box-shaped subdomain inside the body
LARGE = 2 ** 24           # bytes: the contact node sums, not halos


def communication(log):
    """Bytes and messages sent, summed over all pairs, per tag class; and
    the bytes of the application's messages below LARGE bytes (the halos),
    from the size histogram of each E line (bin k counts messages of
    2^(k-1) to 2^k bytes: taken at 1.5 2^(k-1)). The rest of the E bytes
    are the messages of LARGE bytes and more: on the ironing, the contact
    node sums sent to the nodes' owner (SurfaceContact::exchange_node_sums,
    found with gdb on the sends)."""
    total = {"E bytes": 0, "E msgs": 0, "I bytes": 0, "I msgs": 0,
             "E small bytes": 0.}
    for line in log.splitlines():
        m = _LINE.match(line.strip())
        if not m:
            continue
        total[f"{m.group(1)} bytes"] += int(m.group(4))
        total[f"{m.group(1)} msgs"] += int(m.group(5))
        fields = line.split("\t")
        if m.group(1) == "E" and len(fields) > 4 and "," in fields[-1]:
            counts = [int(c) for c in fields[-1].split(",") if c.strip()]
            small = sum(c * 1.5 * 2 ** (k - 1) for k, c in enumerate(counts)
                        if 0 < k and 2 ** k <= LARGE)
            total["E small bytes"] += min(small, int(m.group(4)))
    total["E large bytes"] = total["E bytes"] - total["E small bytes"]
    return total


def run(args, work, end, name):
    changes = {"Output/Output directory": str(work / name)}
    if end:
        changes["Time integration/End time"] = end
    prm = work / f"{name}.prm"
    bench_common.write_prm(prm, REPO / args.prm, changes)
    command = (["mpirun", "-np", str(args.processes)] + MONITOR
               + [args.exe, str(prm)])
    log, peak = bench_common.run_measured(command)
    (work / f"{name}.log").write_text(log)
    t = bench_common.parse_run_log(log, SECTIONS)
    # (no numpy: the script runs under any python3)
    names, stats = bench_common.read_csv_rows(work / name / "statistics.csv")
    column = names.index("linear_iterations")
    row = {"run": name, "processes": args.processes,
           "unknowns": t.get("unknowns"), "steps": t["steps"],
           "newton": t["newton"],
           "krylov": sum(int(float(r[column])) for r in stats),
           "total s": t["total"], "peak MB": peak / 1024}
    row.update({f"{s} s": t.get(s, 0.) for s in SECTIONS})
    row.update(communication(log))
    row["load"] = open("/proc/loadavg").read().split()[0]
    return row


def estimate(full, first, processes):
    """Per Newton iteration at 2, 64 and 1024 processes, from the measured
    volume of the steps after the first, for the busiest process.
    Halos (the matrix-vector products and the multigrid levels): bytes per
    process scale with a subdomain's surface, (n / P)^(2/3), and a box
    inside the body has 26 neighbours and six faces where each half of the
    2-process run has one. Contact node sums: the patches are computed in
    equal shares by all processes and each patch's sums go to the owner of
    its secondary nodes; today one process owns them all (the tool's cap
    lies in one process's part), so it receives the sums of a fraction
    (P - 1) / P of the patches, and their volume grows as the contact
    surface, N^(2/3). Collectives (dot products, the gathered contact
    surfaces): as many as measured, each log2 P latencies deep; their bytes
    per process are the gathered surface, fixed in strong scaling and
    growing as N^(2/3) in weak scaling."""
    newton = full["newton"] - first["newton"]
    krylov = full["krylov"] - first["krylov"]

    def per_newton(key):
        return (full[key] - first[key]) / newton
    # all sums of one Newton iteration, of which (P - 1) / P were sent
    sums = per_newton("E large bytes") * processes / (processes - 1)
    halo_bytes = per_newton("E small bytes") / processes
    p2p_msgs = per_newton("E msgs") / processes
    coll_bytes = per_newton("I bytes") / processes
    coll_msgs = per_newton("I msgs") / processes
    # wall time per Newton iteration on `processes`
    compute = (full["Newton solve s"] - first["Newton solve s"]) / newton
    n = full["unknowns"]
    rows = []
    for label, unknowns, p in [("measured", n, processes),
                               ("strong", n, 64), ("strong", n, 1024),
                               ("weak", n / processes * 64, 64),
                               ("weak", n / processes * 1024, 1024)]:
        surface = ((unknowns / p) / (n / processes)) ** (2 / 3)
        faces = 1 if p == processes else 6
        halo = halo_bytes * surface * faces
        contact = sums * (unknowns / n) ** (2 / 3) * (p - 1) / p
        m = p2p_msgs * (1 if p == processes else NEIGHBOURS_3D)
        c = coll_msgs * math.log2(p) / math.log2(processes)
        cb = coll_bytes * (unknowns / n) ** (2 / 3)
        t_comp = compute * (unknowns / p) / (n / processes)
        t_comm = ((m + c) * LATENCY_S
                  + (halo + contact + cb) / BANDWIDTH_B_PER_S)
        rows.append({"case": label, "processes": p, "unknowns": unknowns,
                     "per process": unknowns / p, "halo bytes": halo,
                     "contact bytes": contact,
                     "collective bytes": cb, "p2p msgs": m,
                     "collective msgs": c, "compute s": t_comp,
                     "communication s": t_comm,
                     "share": t_comm / (t_comm + t_comp)})
    return newton, krylov, rows


def table(full, first, processes):
    newton, krylov, est = estimate(full, first, processes)
    load = full.get("load", "")
    out = ["<!-- generated by benchmarks/largest_run.py; do not edit -->", "",
           f"One run each (not a median: the full run takes 13 minutes),"
           f" {processes} processes on 2 cores"
           + (f", load average at the end {load}" if load else "") +
           ". Peak memory: resident set of the largest process.", "",
           "| run | unknowns | steps | Newton its | Krylov its | whole run (s)"
           " | setup | initial conditions | bulk assembly | contact search +"
           " assembly | linear solve | output | peak memory per process"
           " (MB) |", "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in (full, first):
        def share(*keys):
            return f"{sum(r[k + ' s'] for k in keys):.0f} s"
        out.append(
            f"| {r['run']} | {r['unknowns']:,} | {r['steps']} | {r['newton']}"
            f" | {r['krylov']} | {r['total s']:.0f} | {share('setup')} |"
            f" {share('initial conditions')} | {share('bulk assembly')} |"
            f" {share('contact search', 'contact assembly')} |"
            f" {share('linear solve')} | {share('output')} |"
            f" {r['peak MB']:.0f} |")
    out += ["", f"Steps 2 to {full['steps']} (the difference of the runs):"
            f" {newton} Newton iterations, {krylov} Krylov iterations"
            f" ({krylov / newton:.1f} per Newton iteration).", "",
            "Per Newton iteration, for the busiest process (the owner of"
            " the secondary nodes, which receives the contact node sums):",
            "",
            "| case | processes | unknowns | per process | halo bytes |"
            " contact node sums received (bytes) | point-to-point messages |"
            " collective bytes |"
            " collective messages | compute (s) | communication (s) |"
            " communication share |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for e in est:
        out.append(
            f"| {e['case']} | {e['processes']} | {e['unknowns']:.3g} |"
            f" {e['per process']:.3g} | {e['halo bytes']:.3g} |"
            f" {e['contact bytes']:.3g} |"
            f" {e['p2p msgs']:.0f} | {e['collective bytes']:.3g} |"
            f" {e['collective msgs']:.0f} |"
            f" {e['compute s']:.3g} | {e['communication s']:.3g} |"
            f" {100 * e['share']:.1f} % |")
    out += ["", f"Estimate: latency {LATENCY_S * 1e6:g} us per message,"
            f" {BANDWIDTH_B_PER_S / 1e9:g} GB/s per process, compute per"
            " Newton iteration proportional to the unknowns per process (the"
            " measured wall time of the Newton solves, which includes the"
            " communication on 2 processes of one machine)."]
    return out


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--processes", type=int, default=2)
    parser.add_argument("--prm", default="prm/ironing/mortar_3d_million.prm")
    parser.add_argument("--end", default="",
                        help="end time (default: the file's)")
    parser.add_argument("--first-step", default="0.02",
                        help="end time of the run for the first step")
    parser.add_argument("--exe", default=str(REPO / "build/contact-dynamics"))
    parser.add_argument("--table-only", action="store_true",
                        help="only rewrite the table from the CSV of a"
                        " previous run")
    args = parser.parse_args(argv)
    results = REPO / "benchmarks/results/largest_run.csv"
    if args.table_only:
        with open(results) as f:
            rows = [{k: (v if k in ("run", "load") else float(v)) for k, v in r.items()}
                    for r in csv.DictReader(f)]
        work = REPO / "benchmarks/results/largest_run"
        for r in rows:
            for k in ("unknowns", "steps", "newton", "krylov"):
                r[k] = int(r[k])
            r.update(communication((work / f"{r['run']}.log").read_text()))
        (REPO / "doc/largest-run-table.md").write_text(
            "\n".join(table(rows[0], rows[1], args.processes)) + "\n")
        return
    work = REPO / "benchmarks/results/largest_run"
    work.mkdir(parents=True, exist_ok=True)
    rows = [run(args, work, args.end, "full")]
    print(rows[-1], flush=True)
    rows.append(run(args, work, args.first_step, "first_step"))
    print(rows[-1], flush=True)
    with open(results, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    (REPO / "doc/largest-run-table.md").write_text(
        "\n".join(table(rows[0], rows[1], args.processes)) + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
