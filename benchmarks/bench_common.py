#!/usr/bin/env python3
"""What the benchmark scripts share: one way to run a shipped parameter file
with some entries changed, and one CSV reader.

    from bench_common import write_prm, read_prm, read_csv, run_measured

Changed entries are never edited into the text of a parameter file: a
wrapper file includes the original (deal.II's `include` directive) and then
sets the entries, and deal.II keeps the last value it reads. Entries are
named 'Section/Subsection/Entry' ('Entry' at the top level); a name without
'/' that the original file sets stands for every section that sets it.

CSV files (statistics.csv, contact_history.csv, contact_surface-N.csv) are
read by column name, never by position. numpy is needed only by read_csv.

The shell scripts use the same functions from the command line:

    bench_common.py prm BASE.prm OUT.prm [Section/Entry=value ...]
        write OUT.prm: BASE.prm with the entries changed
    bench_common.py get FILE.prm Section/Entry
        print the value of an entry (following include)
    bench_common.py last FILE.csv NAME [NAME ...]
        print the named columns of the last complete row, comma-separated
"""
import csv
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

_SUBSECTION = re.compile(r"^subsection\s+(.*?)\s*$")
_SET = re.compile(r"^set\s+(.*?)\s*=(.*)$")
_INCLUDE = re.compile(r"^include\s+(.*?)\s*$")


def _norm(name):
    return " ".join(name.split())


def _join_continuations(lines):
    """deal.II joins a line ending in a backslash with the next one."""
    out, pending = [], None
    for line in lines:
        if pending is not None:
            line = pending + " " + line.lstrip()
            pending = None
        if line.rstrip().endswith("\\"):
            pending = line.rstrip()[:-1].rstrip()
            continue
        out.append(line)
    if pending is not None:
        out.append(pending)
    return out


def parse_prm(text, values=None, section=()):
    """Entries of parameter-file text as {'Section/Entry': value} (the last
    one wins); `include FILE` lines are followed (relative to the working
    directory, as deal.II does)."""
    values = {} if values is None else values
    section = list(section)
    for line in _join_continuations(text.splitlines()):
        line = line.split("#", 1)[0].strip()
        m = _SUBSECTION.match(line)
        if m:
            section.append(_norm(m.group(1)))
            continue
        if line == "end" and section:
            section.pop()
            continue
        m = _INCLUDE.match(line)
        if m:
            parse_prm(Path(m.group(1)).read_text(), values, section)
            continue
        m = _SET.match(line)
        if m:
            values["/".join(section + [_norm(m.group(1))])] = m.group(2).strip()
    return values


def read_prm(path):
    """Entries of a parameter file as {'Section/Entry': value}."""
    return parse_prm(Path(path).read_text())


def _resolve(base, changes):
    """changes as {'Section/Entry': str(value)}, bare names resolved in `base`."""
    known = read_prm(base)
    resolved = {}
    for key, value in changes.items():
        key = "/".join(_norm(p) for p in key.split("/"))
        paths = [k for k in known if k.split("/")[-1] == key] if "/" not in key else []
        for path in paths or [key]:
            resolved[path] = str(value)
    return resolved


def prm_values(base, changes):
    """The entries a run of `base` with `changes` reads (as far as the files
    set them: defaults are not listed)."""
    return {**read_prm(base), **_resolve(base, changes)}


def prm_with_changes(base, changes):
    """Text of a parameter file that includes `base` (a path) and then sets
    `changes` ({'Section/Entry': value})."""
    tree = {}
    for key, value in _resolve(base, changes).items():
        *sections, entry = key.split("/")
        node = tree
        for s in sections:
            node = node.setdefault(("subsection", s), {})
        node[("set", entry)] = value
    lines = [f"include {Path(base).resolve()}"]

    def emit(node, depth):
        for (kind, name), value in node.items():
            if kind == "set":
                lines.append("  " * depth + f"set {name} = {value}")
            else:
                lines.append("  " * depth + f"subsection {name}")
                emit(value, depth + 1)
                lines.append("  " * depth + "end")
    emit(tree, 0)
    return "\n".join(lines) + "\n"


def write_prm(path, base, changes):
    """Write prm_with_changes(base, changes) to `path`; returns the text."""
    text = prm_with_changes(base, changes)
    Path(path).write_text(text)
    return text


def read_csv_rows(path):
    """Column names (as in the header) and the rows whose every field is a
    number, as text (skips a line half written by a running simulation)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return [], []
    names = [n.strip() for n in rows[0]]
    good = []
    for row in rows[1:]:
        try:
            if len(row) == len(names):
                [float(x) for x in row]
                good.append([x.strip() for x in row])
        except ValueError:
            pass
    return names, good


def read_csv(path, units=True):
    """{column name: numpy array} of a numeric CSV file, in the order of its
    columns. With units=False a name loses what follows '(' (older
    statistics.csv files wrote 'wall_time(cumulative s)')."""
    from plot_env import np
    names, rows = read_csv_rows(path)
    if not names:
        return {}
    if not units:
        names = [n.split("(")[0].strip() for n in names]
    data = np.array([[float(x) for x in row] for row in rows],
                    dtype=float).reshape(-1, len(names))
    return {n: data[:, i] for i, n in enumerate(names)}


def parse_run_log(log, sections):
    """From a run's screen output: seconds per TimerOutput section of
    `sections` (and its number of calls, "<section> calls"), "total" (the TimerOutput's wall time), "unknowns" (of the
    first mesh), "steps" and "newton" (from the final line)."""
    result = {}
    for line in log.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) >= 4 and cells[1] in sections:
            result[cells[1]] = float(cells[3].rstrip("s"))
            result[cells[1] + " calls"] = int(cells[2])
        m = re.search(r"Total wallclock time elapsed since start\s*\|\s*([0-9.e+-]+)s", line)
        if m:
            result["total"] = float(m.group(1))
        m = re.search(r"(\d+) unknowns", line)
        if m and "unknowns" not in result:
            result["unknowns"] = int(m.group(1))
        m = re.search(r"after (\d+) steps \((\d+) Newton iterations", line)
        if m:
            result["steps"] = int(m.group(1))
            result["newton"] = int(m.group(2))
    return result


def run_measured(command):
    """The screen output and the peak resident set (kB) of the largest
    process of the run (wait4: the child and the descendants it waited
    for, that is mpirun's ranks)."""
    with tempfile.TemporaryFile("w+") as log:
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
        child = subprocess.Popen(command, stdout=log, env=env,
                                 stderr=subprocess.STDOUT, text=True)
        _, status, usage = os.wait4(child.pid, 0)
        child.returncode = os.waitstatus_to_exitcode(status)
        log.seek(0)
        text = log.read()
    if child.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed:\n{text[-2000:]}")
    return text, usage.ru_maxrss


def self_test():
    """Checks of the parameter-file override on a small file."""
    import tempfile
    base_text = """# comment with subsection and end and set X = 1
set Dimension = 2
subsection Contact   # trailing comment
  set Formulation = mortar   # comment
  subsection Mortar
    set Jacobian = exact
  end
  subsection Node to segment
    set Jacobian = exact
  end
end
subsection Scene
  set Scene = bar impact
  subsection Bar impact
    set Elements along bar = \\
        40
  end
end
"""
    with tempfile.TemporaryDirectory() as d:
        base = Path(d) / "base.prm"
        base.write_text(base_text)
        changes = {"Contact/Formulation": "nts", "Contact/Mortar/c_n": 20,
                   "Scene/Bar impact/Elements along bar": 80, "Jacobian": "approximate",
                   "Scene/Refinement factor": 2, "Output/VTU interval": 0}
        text = write_prm(Path(d) / "run.prm", base, changes)
        values = read_prm(Path(d) / "run.prm")
        expect = {"Contact/Formulation": "nts", "Contact/Mortar/c_n": "20",
                  "Contact/Mortar/Jacobian": "approximate",
                  "Contact/Node to segment/Jacobian": "approximate",
                  "Scene/Bar impact/Elements along bar": "80", "Scene/Refinement factor": "2",
                  "Output/VTU interval": "0", "Dimension": "2", "Scene/Scene": "bar impact"}
        for key, value in expect.items():
            assert values.get(key) == value, (key, values.get(key), text)
        assert prm_values(base, changes) == values, (prm_values(base, changes), values)
        assert "mortar" not in text and text.count("subsection Contact") == 1, text
    print("bench_common self-test: OK")


def main(argv):
    usage = "usage:\n" + __doc__[__doc__.index("    bench_common.py prm"):]
    command, args = (argv[0], argv[1:]) if argv else ("", [])
    if command in ("-h", "--help"):
        print(__doc__)
        return
    if command == "prm" and len(args) >= 2:
        changes = dict(a.split("=", 1) for a in args[2:] if "=" in a)
        if len(changes) != len(args) - 2 or not all(changes):
            sys.exit(f"prm: changes are Section/Entry=value\n{usage}")
        write_prm(args[1], args[0], changes)
    elif command == "get" and len(args) == 2:
        values = read_prm(args[0])
        if args[1] not in values:
            sys.exit(f"{args[0]} sets no '{args[1]}'")
        print(values[args[1]])
    elif command == "last" and len(args) >= 2:
        if not Path(args[0]).is_file():
            sys.exit(f"{args[0]} is missing")
        names, rows = read_csv_rows(args[0])
        missing = [n for n in args[1:] if n not in names]
        if missing:
            sys.exit(f"{args[0]} has no column {', '.join(missing)}")
        if rows:
            print(",".join(rows[-1][names.index(n)] for n in args[1:]))
    elif command == "self-test" and not args:
        self_test()
    else:
        sys.exit(usage)


if __name__ == "__main__":
    main(sys.argv[1:])
