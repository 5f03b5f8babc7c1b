#!/usr/bin/env python3
"""Why a simulated row misses doors (doc/benchmarks.md, "Held-out simulator seeds"): the map
around every true door, and the detected hinges that match no true door.

usage: door_misses.py ROW_DIR [--all] [--radius 0.45] [--tolerance 0.3]
  ROW_DIR: one simulated row of run_benchmarks.sh (sim/ from gv-sim, em/ from gv-em-slam,
  map_eval.txt from gv-eval map --breakdown).
Everything is put in the truth frame by the SE(2) alignment of em/trajectory.txt to
sim/truth_trajectory.txt (door_stability.py's Umeyama without scale over poses matched by timestamp).
Per true door seen in two states and matched by no detected hinge within TOLERANCE (every true
door with --all): its map_eval.txt line (passes: leaf angle and scans per pass), the nearest
detected hinge, and the map's vectors (state, p_static, length, ends, direction) passing within
RADIUS of the true hinge or of the tip of the true leaf closed or open; and, per leaf angle the
passes list (and closed), what the scans saw of the true leaf at that angle from the true poses
(door_evidence.py's test along the beams): the scans in which it was present and those that saw
through its place, as time spans [s]. Then every detected hinge farther than TOLERANCE from each
true door (a false door), with its state directions."""
import argparse, math, os, re, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import door_evidence  # noqa: E402
import door_stability  # noqa: E402


def rows(path):
    return [l.split() for l in open(path) if l.strip() and not l.startswith('#')]


def alignment(est_path, truth_path):
    """door_stability's SE(2) fit of the estimated trajectory onto the truth, and its rotation."""
    f = door_stability.se2_fit(door_stability.matched_positions(door_stability.load(est_path, 4),
                                                                door_stability.load(truth_path, 4)))
    (x0, y0), (x1, y1) = f(0.0, 0.0), f(1.0, 0.0)
    return math.atan2(y1 - y0, x1 - x0), f


def dist(p, q):
    return math.hypot(p[0] - q[0], p[1] - q[1])


def seg_dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    ll = dx * dx + dy * dy
    u = 0.0 if ll == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / ll))
    return dist((a[0] + u * dx, a[1] + u * dy), p)


def load_map(d, to_truth):
    vectors = [(to_truth(float(f[0]), float(f[1])), to_truth(float(f[2]), float(f[3])), float(f[4]), f[5])
               for f in rows(d + '/em/vectors.txt')]
    hinges = []
    for line in open(d + '/em/door_states.txt'):
        if line.startswith('#') or not line.strip():
            continue
        parts = line.split('|')
        h = parts[0].split()
        hinges.append((to_truth(float(h[0]), float(h[1])), float(h[2]), parts[-1].split()[1:]))
    return vectors, hinges


def door_lines(d):
    out = {}
    for line in open(d + '/map_eval.txt'):
        m = re.match(r'door (\d+):', line)
        if m:
            out[int(m.group(1))] = line.strip()
    return out


def spans(ts):
    out = []
    for t in ts:
        if out and t - out[-1][1] < 2.5:
            out[-1][1] = t
        else:
            out.append([t, t])
    return ' '.join('%.0f-%.0f' % tuple(s) for s in out) or '-'


class Scans:
    """The row's scans at the true poses, looked at along the beams (door_evidence.Looker)."""
    def __init__(self, d):
        scans, start, res, rmax = door_evidence.read_scans(d + '/sim/sim.log')
        truth = rows(d + '/sim/truth_trajectory.txt')
        self.times = [float(f[0]) - float(truth[0][0]) for f in truth]
        self.poses = [tuple(map(float, f[1:4])) for f in truth]
        self.look = door_evidence.Looker(scans, start, res, rmax, self.poses, 0.1)

    def show_leaf(self, door, line):
        hx, hy, length, closed, opened = map(float, door[:5])
        angles = sorted({0.0} | {float(x) for x in re.findall(r'(\d+) deg\]', line or '')}
                        | {float(x) for x in re.findall(r'(\d+)-\d+ deg\]', line or '')})
        sign = 1 if opened > closed else -1
        near = [k for k, p in enumerate(self.poses) if math.hypot(p[0] - hx, p[1] - hy) < 15]
        d = dict(hinge=(hx, hy), length=length, angles=[closed + sign * math.radians(a) for a in angles])
        for a, row in zip(angles, door_evidence.state_outcomes(self.look, d, near)[0]):
            present = [self.times[k] for k, r in zip(near, row) if r == 'P']
            through = [self.times[k] for k, r in zip(near, row) if r == 'A']
            print('  leaf at %2.0f deg: present in %d scans (%s), seen through in %d (%s)'
                  % (a, len(present), spans(present), len(through), spans(through)))


def show_door(i, door, line, vectors, hinges, th, radius):
    hx, hy, length, closed, opened = map(float, door[:5])
    hinge = (hx, hy)
    tips = [(hx + length * math.cos(a), hy + length * math.sin(a)) for a in (closed, opened)]
    print(line or 'door %d' % i)
    print('  true hinge (%.2f, %.2f), leaf %.2f m, closed %.0f deg, open %.0f deg'
          % (hx, hy, length, math.degrees(closed), math.degrees(opened)))
    if hinges:
        g = min(hinges, key=lambda g: dist(g[0], hinge))
        print('  nearest detected hinge %.2f m off: (%.2f, %.2f), leaf %.2f m, states %s deg'
              % (dist(g[0], hinge), g[0][0], g[0][1], g[1],
                 ' '.join('%.0f' % (float(a) + math.degrees(th)) for a in g[2])))
    for a, b, p, state in vectors:
        if min(seg_dist(q, a, b) for q in [hinge] + tips) <= radius:
            print('    %-7s p=%.2f %.2f m (%.2f, %.2f)-(%.2f, %.2f) dir %4.0f deg, %.2f m from the hinge'
                  % (state, p, dist(a, b), a[0], a[1], b[0], b[1],
                     math.degrees(math.atan2(b[1] - a[1], b[0] - a[0])), seg_dist(hinge, a, b)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('row_dir')
    ap.add_argument('--all', action='store_true')
    ap.add_argument('--radius', type=float, default=0.45)
    ap.add_argument('--tolerance', type=float, default=0.3)
    a = ap.parse_args()
    d = a.row_dir
    th, to_truth = alignment(d + '/em/trajectory.txt', d + '/sim/truth_trajectory.txt')
    vectors, hinges = load_map(d, to_truth)
    lines = door_lines(d)
    truth = rows(d + '/sim/truth_doors.txt')
    scans = Scans(d)
    for i, door in enumerate(truth):
        found = any(dist(g[0], (float(door[0]), float(door[1]))) <= a.tolerance for g in hinges)
        if a.all or (not found and 'seen in two states' in lines.get(i, '')):
            show_door(i, door, lines.get(i), vectors, hinges, th, a.radius)
            scans.show_leaf(door, lines.get(i))
    for g in hinges:
        off = min(dist(g[0], (float(t[0]), float(t[1]))) for t in truth)
        if off > a.tolerance:
            print('false door: hinge (%.2f, %.2f), leaf %.2f m, states %s deg, %.2f m from the nearest true door'
                  % (g[0][0], g[0][1], g[1], ' '.join('%.0f' % (float(x) + math.degrees(th)) for x in g[2]), off))


if __name__ == '__main__':
    main()
