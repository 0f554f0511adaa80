# usage: held_gaps.py OUTPUT_DIRECTORY (VTU interval 1: a surface file per step)
# Held gaps across steps: a node active with the same gap (to 1e-9) in
# steps n-2, n-1 and n is held; its gap in step n+1 is compared with step
# n's, separately where the mesh changed between n and n+1. Nodes are
# matched by current position (they move much less than the spacing).
import csv, glob, sys, math
d = sys.argv[1]
files = sorted(glob.glob(d + '/contact_surface-*.csv'))
stats = {int(r['step']): r for r in csv.DictReader(open(d + '/statistics.csv'))}
def load(f):
    return [(float(r['x']), float(r['y']), float(r['gap']), r['active'] == '1')
            for r in csv.DictReader(open(f))]
steps = {int(f[-9:-4]): load(f) for f in files}
def find(rows, x, y):
    q = min(rows, key=lambda q: (q[0] - x) ** 2 + (q[1] - y) ** 2)
    return q if math.hypot(q[0] - x, q[1] - y) < 0.01 else None
across = between = 0
n_across = n_between = 0
for n in sorted(steps):
    if n - 2 not in steps or n + 1 not in steps:
        continue
    for x, y, g, act in steps[n]:
        chain = [find(steps[n - k], x, y) for k in (1, 2)]
        if not act or any(c is None or not c[3] or abs(c[2] - g) > 1e-9 for c in chain):
            continue
        nxt = find(steps[n + 1], x, y)
        if nxt is None or not nxt[3]:
            continue
        change = stats[n + 1]['mesh_changes'] != stats[n]['mesh_changes']
        if change:
            across = max(across, abs(nxt[2] - g)); n_across += 1
        else:
            between = max(between, abs(nxt[2] - g)); n_between += 1
print("held gaps: largest change across mesh changes %.2e (%d), between %.2e (%d)"
      % (across, n_across, between, n_between))
ok = across <= 1e-10 and between <= 1e-10 and n_across >= 10 and n_between >= 10
print("held within 1e-10 over at least 10 comparisons each: %s" % ("yes" if ok else "NO"))
