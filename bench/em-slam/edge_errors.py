#!/usr/bin/env python3
"""Diagnosis only (doc/benchmarks.md, EM-SLAM real logs, "per-edge errors"): how far is each
registration edge of an M-step from the reference trajectory?

usage: edge_errors.py EDGES.txt REF.txt [--chi2 C] [--scans A-B[,C-D]] [--all]
  EDGES.txt: gv-em-slam's GV_EM_DEBUG_DIR/edges_<iteration>.txt (scan indices, the information
  the pose graph uses, in the frame of Eq. 21's error), or with --online its
  online_edges_before_finish.txt / online_edges_final.txt (OnlineEmSlam's graph before and after
  finish(), same format); REF.txt: mkbench's .ref.txt (t x y theta,
  one line per scan). For each edge the error of its measurement z against the reference's
  relative pose, e = z^-1 (+) (ref_from^-1 (+) ref_to) (PoseGraph::error), its chi2 e^T I e (what
  the edge claims against what the reference says; 3 dof: 7.8 is the 95 % level, 11.3 the
  99 %), and the translation error split along the information's strongest and weakest
  translation directions (an edge wrong along the direction it constrains is a wrong
  registration; one wrong along its weak direction is a degenerate one that claims nothing there).
  Prints the edges with chi2 above C (default 11.34), worst first, active ones marked, and a
  summary per kind; --scans limits to edges with both ends in the ranges (either order);
  --all prints every edge."""
import math, sys


def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def rel(a, b):
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (c * dx + s * dy, -s * dx + c * dy, wrap(b[2] - a[2]))


def error(z, r):
    """PoseGraph::error(0, r, z): translation difference rotated into z's frame, heading difference."""
    ex, ey = r[0] - z[0], r[1] - z[1]
    c, s = math.cos(z[2]), math.sin(z[2])
    return (c * ex + s * ey, -s * ex + c * ey, wrap(r[2] - z[2]))


def load_ref(p):
    return [tuple(map(float, l.split()[1:4])) for l in open(p) if l.strip() and not l.startswith('#')]


def eig2(a, b, d):
    """Eigen-decomposition of [[a, b], [b, d]]: (small, large, unit vector of the small one)."""
    tr, det = a + d, a * d - b * b
    disc = math.sqrt(max(0.0, tr * tr / 4 - det))
    lo, hi = tr / 2 - disc, tr / 2 + disc
    if abs(b) > 1e-12:
        v = (lo - d, b)
    else:
        v = (1.0, 0.0) if a <= d else (0.0, 1.0)
    n = math.hypot(*v)
    return lo, hi, (v[0] / n, v[1] / n)


def parse_ranges(s):
    out = []
    for part in s.split(','):
        a, b = part.split('-')
        out.append((int(a), int(b)))
    return out


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    edges_path, ref_path = args[0], args[1]
    level, ranges, show_all = 11.34, None, False
    i = 2
    while i < len(args):
        if args[i] == '--chi2':
            level = float(args[i + 1]); i += 2
        elif args[i] == '--scans':
            ranges = parse_ranges(args[i + 1]); i += 2
        elif args[i] == '--all':
            show_all = True; i += 1
        else:
            sys.exit('unknown argument ' + args[i])
    ref = load_ref(ref_path)
    rows = []
    for l in open(edges_path):
        if l.startswith('#') or not l.strip():
            continue
        f = l.split()
        a, b, kind, rej, dof = int(f[0]), int(f[1]), f[2], int(f[3]), int(f[4])
        deg, rms, mlen, ncor = float(f[5]), float(f[6]), float(f[7]), int(f[8])
        z = tuple(map(float, f[9:12]))
        I = list(map(float, f[12:18]))
        if ranges and not any(lo <= a <= hi for lo, hi in ranges) and not any(lo <= b <= hi for lo, hi in ranges):
            continue
        r = rel(ref[a], ref[b])
        e = error(z, r)
        M = [[I[0], I[1], I[2]], [I[1], I[3], I[4]], [I[2], I[4], I[5]]]
        chi2 = sum(e[p] * M[p][q] * e[q] for p in range(3) for q in range(3))
        lo, hi, v = eig2(I[0], I[1], I[3])
        weak = e[0] * v[0] + e[1] * v[1]
        strong = -e[0] * v[1] + e[1] * v[0]
        rows.append(dict(a=a, b=b, kind=kind, rej=rej, dof=dof, deg=deg, rms=rms, mlen=mlen, ncor=ncor,
                         chi2=chi2, et=math.hypot(e[0], e[1]), er=math.degrees(e[2]), strong=strong, weak=weak,
                         sstrong=1 / math.sqrt(hi) if hi > 0 else float('inf'),
                         sweak=1 / math.sqrt(lo) if lo > 0 else float('inf')))
    rows.sort(key=lambda r: -r['chi2'])
    print('| from | to | kind | active | dof | degeneracy | corr | matched [m] | rms [m] | err t [m] | err r [deg] '
          '| along strong [m] (sigma) | along weak [m] (sigma) | chi2 vs ref |')
    print('|---|---|---|---|---|---|---|---|---|---|---|---|---|---|')
    for r in rows:
        if not show_all and r['chi2'] < level:
            continue
        print('| %d | %d | %s | %s | %d | %.2g | %d | %.2f | %.4f | %.3f | %.2f | %+.3f (%.3f) | %+.3f (%.3g) | %.1f |' % (
            r['a'], r['b'], r['kind'], 'no' if r['rej'] else 'yes', r['dof'], r['deg'], r['ncor'], r['mlen'], r['rms'],
            r['et'], r['er'], r['strong'], r['sstrong'], r['weak'], r['sweak'], r['chi2']))
    print()
    for kind in sorted(set(r['kind'] for r in rows)):
        ks = [r for r in rows if r['kind'] == kind]
        act = [r for r in ks if not r['rej']]
        bad = [r for r in act if r['chi2'] >= level]
        print('%s: %d edges, %d active, %d active above chi2 %.2f, active chi2 sum %.0f' % (
            kind, len(ks), len(act), len(bad), level, sum(r['chi2'] for r in act)))


if __name__ == '__main__':
    main()
