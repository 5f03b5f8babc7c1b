#!/usr/bin/env python3
"""What the scans saw of each door's states (doc/benchmarks.md, "Doors on the real logs"). For
every door of a gv-em-slam run (door_states.txt: hinge, leaf length, every state's direction, the
wall as detected) and every scan within 15 m of the hinge, at its final pose, each state's leaf
(points every 5 cm from 0.15 m off the hinge to 0.05 m short of the tip) is looked at along the
beams: a beam through a point that ends within TOL of it saw it occupied, one ending beyond it saw
through it, one ending short of it was occluded. A state is *present* in a scan when >= 3 of its
points were observed and at least half of them occupied, *absent* when >= 3 were observed and at
least 80 % seen through.

Per door (one line per door; with --summary the figures below, then their range per class):
  toggle    the largest, over the states, of min(#scans present, #scans absent)
  awo       absent-with-other: the most scans, over the states, in which the state is absent
            while another state is present (its place seen empty while the leaf stood elsewhere)
  swap      state pairs (s, t) seen both ways round: s present while t absent in some scan, and
            t present while s absent in another; swapmin the larger over the pairs of the fewer
  through   scans with a beam crossing the opening (hinge to latch along the wall's line, on the
            side away from the wall's centre) and ending >= 0.3 m beyond it
  fill      per state, over the scans it is present, the mean share of its observed points occupied
  jamb      (with --vectors) the distance from the hinge, along the opening, at which a static
            vector on the wall's line (both ends within 0.2 m of it, >= 0.2 m long) starts beyond
            0.3 m: a door frame's latch side lies a leaf's length away; '-' none
  profile   per state, n_occupied / n_observed of each point over all scans (the cells' n_occupy /
            n_visit along the leaf, from the scans): its minimum, and *share*, the part of the
            points at >= 0.1 (--summary: the smallest share over the states)

usage: door_evidence.py LOG TRAJECTORY DOOR_STATES [--labels "0:P 1:U ..."] [--tol 0.1] [--summary]
                        [--vectors VECTORS.txt]
  LOG: the CARMEN log the run read (FLASER, the laser at the robot's pose: benchmark and simulated
  logs); TRAJECTORY: its trajectory.txt; DOOR_STATES: its door_states.txt, one door a line,
  'hx hy length amin amax n | W x1 y1 x2 y2 | leaves | A deg deg ...'; --labels: a class per door
  index (by-eye classes in doc/benchmarks.md)."""
import argparse, math


def read_scans(path):
    """FLASER ranges and beam layout of a CARMEN log (laser at the robot's pose, as the benchmark
    and simulated logs are)."""
    res, fov, rmax, scans = None, math.pi, 81.0, []
    for line in open(path):
        t = line.split()
        if not t: continue
        if t[0] == 'PARAM':
            if t[1] == 'laser_front_laser_resolution': res = math.radians(float(t[2]))
            elif t[1] == 'laser_front_laser_fov':
                v = float(t[2]); fov = v if v <= 2 * math.pi + 0.01 else math.radians(v)
            elif t[1] == 'robot_front_laser_max': rmax = float(t[2])
        elif t[0] == 'FLASER':
            n = int(t[1]); scans.append([float(x) for x in t[2:2 + n]])
    n = len(scans[0])
    if res is None: res = fov / (n - 1)
    return scans, -fov / 2, res, rmax


def read_poses(path):
    return [tuple(map(float, l.split()[1:4])) for l in open(path) if l.strip() and not l.startswith('#')]


def read_doors(path):
    out = []
    for l in open(path):
        if l.startswith('#') or not l.strip(): continue
        a, w, _, an = l.split('|')
        h = list(map(float, a.split()))
        out.append(dict(hinge=(h[0], h[1]), length=h[2], angles=[math.radians(float(x)) for x in an.split()[1:]],
                        wall=list(map(float, w.split()[1:]))))
    return out


class Looker:
    def __init__(self, scans, start, res, rmax, poses, tol):
        self.scans, self.start, self.res, self.rmax, self.poses, self.tol = scans, start, res, rmax, poses, tol

    def observe(self, k, p):
        """'o' occupied, 'f' seen through, None not observed, for point p in scan k."""
        x, y, th = self.poses[k]
        dx, dy = p[0] - x, p[1] - y
        r = math.hypot(dx, dy)
        b = math.atan2(dy, dx) - th
        b = (b + math.pi) % (2 * math.pi) - math.pi
        i = round((b - self.start) / self.res)
        if i < 0 or i >= len(self.scans[k]) or r > 0.9 * self.rmax: return None
        if r * abs(b - (self.start + i * self.res)) > 0.03: return None  # between beams
        z = self.scans[k][i]
        if z <= 0 or z >= self.rmax: return 'f' if r < 0.9 * self.rmax else None
        if abs(z - r) <= self.tol: return 'o'
        return 'f' if z > r + self.tol else None

    def crosses(self, k, a, b, beyond):
        """Beams of scan k crossing segment a-b and ending >= `beyond` past it."""
        x, y, th = self.poses[k]
        n = 0
        for i, z in enumerate(self.scans[k]):
            if z <= 0: continue
            zz = min(z, 0.9 * self.rmax)
            ang = th + self.start + i * self.res
            ex, ey = x + zz * math.cos(ang), y + zz * math.sin(ang)
            t = seg_intersect((x, y), (ex, ey), a, b)
            if t is not None and (1 - t) * zz >= beyond: n += 1
        return n


def seg_intersect(p, q, a, b):
    """Parameter t along p-q where it crosses a-b, or None."""
    rx, ry, sx, sy = q[0] - p[0], q[1] - p[1], b[0] - a[0], b[1] - a[1]
    den = rx * sy - ry * sx
    if abs(den) < 1e-12: return None
    t = ((a[0] - p[0]) * sy - (a[1] - p[1]) * sx) / den
    u = ((a[0] - p[0]) * ry - (a[1] - p[1]) * rx) / den
    return t if 0 <= t <= 1 and 0 <= u <= 1 else None


def leaf_points(d, a):
    hx, hy = d['hinge']
    pts, s = [], 0.15
    while s <= d['length'] - 0.05 + 1e-9:
        pts.append((hx + s * math.cos(a), hy + s * math.sin(a))); s += 0.05
    return pts


def state_outcomes(look, d, near):
    """Per state, per scan: 'P' present, 'A' absent or None; and the fill of present scans."""
    out, fills, profiles = [], [], []
    for a in d['angles']:
        pts = leaf_points(d, a)
        row, fill = [], []
        occ, seen = [0] * len(pts), [0] * len(pts)
        for k in near:
            obs = [look.observe(k, p) for p in pts]
            for i, ob in enumerate(obs):
                if ob: seen[i] += 1; occ[i] += ob == 'o'
            no, nf = obs.count('o'), obs.count('f')
            if no + nf < 3: row.append(None)
            elif no >= 0.5 * (no + nf): row.append('P'); fill.append(no / (no + nf))
            elif nf >= 0.8 * (no + nf): row.append('A')
            else: row.append(None)
        out.append(row)
        fills.append(sum(fill) / len(fill) if fill else float('nan'))
        ratios = [o / n for o, n in zip(occ, seen) if n >= 3]
        profiles.append((min(ratios) if ratios else float('nan'),
                         sum(r >= 0.1 for r in ratios) / len(ratios) if ratios else float('nan')))
    return out, fills, profiles


def opening(d):
    """Hinge to latch along the wall's line, away from the wall's centre."""
    w = d['wall']; hx, hy = d['hinge']
    ux, uy = w[2] - w[0], w[3] - w[1]
    L = math.hypot(ux, uy); ux, uy = ux / L, uy / L
    cx, cy = (w[0] + w[2]) / 2, (w[1] + w[3]) / 2
    if (hx - cx) * ux + (hy - cy) * uy < 0: ux, uy = -ux, -uy
    s = 0.1
    return (hx + s * ux, hy + s * uy), (hx + d['length'] * ux, hy + d['length'] * uy)


def jamb(d, vectors):
    """Where a static vector on the wall's line starts beyond the opening (None: nowhere)."""
    (hx, hy), (ex, ey) = d['hinge'], opening(d)[1]
    ux, uy = (ex - hx) / d['length'], (ey - hy) / d['length']
    best = None
    for x1, y1, x2, y2 in vectors:
        t = [((x - hx) * ux + (y - hy) * uy, abs((x - hx) * uy - (y - hy) * ux)) for x, y in ((x1, y1), (x2, y2))]
        lo, hi = min(t[0][0], t[1][0]), max(t[0][0], t[1][0])
        if max(o for _, o in t) <= 0.2 and hi - lo >= 0.2 and lo >= 0.3 and (best is None or lo < best): best = lo
    return best


def evidence(look, d):
    hx, hy = d['hinge']
    near = [k for k, (x, y, _) in enumerate(look.poses) if math.hypot(x - hx, y - hy) < 15]
    st, fills, prof = state_outcomes(look, d, near)
    n = len(st)
    awo = []
    for s in range(n):
        awo.append(sum(1 for j in range(len(near)) if st[s][j] == 'A' and any(st[t][j] == 'P' for t in range(n) if t != s)))
    swaps, swapmin = 0, 0
    for s in range(n):
        for t in range(s + 1, n):
            one = sum(1 for j in range(len(near)) if st[s][j] == 'P' and st[t][j] == 'A')
            two = sum(1 for j in range(len(near)) if st[t][j] == 'P' and st[s][j] == 'A')
            if one and two: swaps += 1
            swapmin = max(swapmin, min(one, two))
    a, b = opening(d)
    through = sum(1 for k in near if look.crosses(k, a, b, 0.3) > 0)
    pres = [r.count('P') for r in st]
    absn = [r.count('A') for r in st]
    return dict(length=d['length'], swap=swaps, swapmin=swapmin, awo=awo, pres=pres, absn=absn, through=through, fills=fills, prof=prof,
                near=len(near))


def summary_line(k, cls, e, byclass):
    toggle = max(min(p, a) for p, a in zip(e['pres'], e['absn']))
    share = min((b for _, b in e['prof'] if not math.isnan(b)), default=float('nan'))
    row = dict(toggle=toggle, awo=max(e['awo']), swap=e['swap'], through=e['through'], share=share)
    byclass.setdefault(cls, []).append(row)
    jb = '' if 'jamb' not in e else ' jamb ' + ('-' if e['jamb'] is None else f"{e['jamb']:.2f} L {e['length']:.2f}")
    print(f"{k} {cls} " + ' '.join(f"{n} {v:.2f}" if n == 'share' else f"{n} {v}" for n, v in row.items()) + jb, flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('log'); ap.add_argument('traj'); ap.add_argument('doors')
    ap.add_argument('--labels', default='')
    ap.add_argument('--tol', type=float, default=0.1)
    ap.add_argument('--summary', action='store_true', help='toggle, awo, swap, through, share per door; ranges per class')
    ap.add_argument('--vectors', help="the run's vectors.txt: the latch-side jamb per door (--summary)")
    o = ap.parse_args()
    scans, start, res, rmax = read_scans(o.log)
    poses = read_poses(o.traj)
    assert len(poses) == len(scans), (len(poses), len(scans))
    look = Looker(scans, start, res, rmax, poses, o.tol)
    lab = dict(x.split(':') for x in o.labels.split())
    byclass = {}
    statics = [tuple(map(float, l.split()[:4])) for l in open(o.vectors)
               if not l.startswith('#') and l.split()[5] == 'static'] if o.vectors else []
    print('# door class hinge L states | swap swapmin | present/absent/absent-with-other per state | through near | fill per state | profile min ratio / share >= 0.1 per state')
    for k, d in enumerate(read_doors(o.doors)):
        e = evidence(look, d)
        if o.summary:
            if o.vectors: e['jamb'] = jamb(d, statics)
            summary_line(k, lab.get(str(k), '-').upper(), e, byclass)
            continue
        per = ' '.join(f"{p}/{a}/{w}" for p, a, w in zip(e['pres'], e['absn'], e['awo']))
        fill = ' '.join('-' if math.isnan(f) else f'{f:.2f}' for f in e['fills'])
        prof = ' '.join('-' if math.isnan(a) else f'{a:.2f}/{b:.2f}' for a, b in e['prof'])
        print(f"{k} {lab.get(str(k), '-')} ({d['hinge'][0]:.2f},{d['hinge'][1]:.2f}) {d['length']:.2f} {len(d['angles'])} | "
              f"{e['swap']} {e['swapmin']} | {per} | {e['through']} {e['near']} | {fill} | {prof}", flush=True)
    for cls, rows in sorted(byclass.items()):  # --summary: each property's range per class
        rng = lambda n, f='{}': '-'.join(f.format(x) for x in (min(r[n] for r in rows), max(r[n] for r in rows)))
        print(f"# class {cls}: {len(rows)} doors, toggle {rng('toggle')}, awo {rng('awo')}, swap {rng('swap')}, "
              f"through {rng('through')}, share {rng('share', '{:.2f}')}")


if __name__ == '__main__':
    main()
