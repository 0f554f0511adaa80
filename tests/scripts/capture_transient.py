# usage: capture_transient.py RATE_DIR POSITION_DIR (VTU interval 1)
# The ironing's tool nodes captured while the tool slides (pair 0): how
# deep an active node lies behind the substrate (impenetrability: a node in
# contact has gap 0 up to the Capture tolerance 1e-5), the largest pressure
# of an active node more than 1e-4 away, and the roughness of the pressure
# along the contact zone (RMS of its second difference over its mean,
# median over t = 0.2 - 0.6) with Capture = rate and Capture = position.
import csv, glob, math, statistics, sys


def snapshots(d):
    return [list(csv.DictReader(open(f)))
            for f in sorted(glob.glob(d + '/contact_surface-*.csv'))]


def measure(d):
    snaps = snapshots(d)
    deepest = far = 0.
    rough = []
    for k, rows in enumerate(snaps):
        on = [r for r in rows if r['pair'] == '0' and r['active'] == '1']
        for r in on:
            gap, p = float(r['gap']), float(r['pressure'])
            deepest = max(deepest, -gap)
            if abs(gap) > 1e-4:
                far = max(far, p)
        p = [float(r['pressure']) for r in sorted(on, key=lambda r: float(r['x']))]
        if 0.2 <= 0.01 * k <= 0.6 and len(p) >= 3 and sum(p) > 0:
            d2 = [p[i] - 2 * p[i + 1] + p[i + 2] for i in range(len(p) - 2)]
            rough.append(math.sqrt(sum(x * x for x in d2) / len(d2)) /
                         (sum(p) / len(p)))
    return deepest, far, statistics.median(rough)


rate, position = measure(sys.argv[1]), measure(sys.argv[2])
for name, m in (('rate', rate), ('position', position)):
    print(f'{name}: deepest active node {m[0]:.3g}, pressure at a distance '
          f'{m[1]:.3g}, roughness {m[2]:.3g}')
print('position holds contact nodes within the capture tolerance:',
      'yes' if position[0] <= 1e-5 and position[1] == 0 else 'NO')
print('rate sinks captured nodes by more than 1e-4:',
      'yes' if rate[0] > 1e-4 else 'NO')
print('position is smoother:', 'yes' if position[2] < 0.9 * rate[2] else 'NO')
