#!/usr/bin/env python3
"""Diagnosis only (doc/benchmarks-history.md, EM-SLAM real logs, "The floor"): how far are two trajectories'
relative poses from the optimum of an independent point-to-line ICP on the raw scans?

usage: ref_consistency.py BENCH.log REF.txt EST.txt [local|loop] [N]
  BENCH.log: the mkbench log (its FLASER ranges); REF.txt, EST.txt: t x y theta per scan, one
  line per FLASER row. Pairs: consecutive scans (local) or a seeded sample of N evaltraj loop
  pairs (< 3 m apart in REF, >= 20 scans apart). ICP (Cauchy-weighted point-to-line, lines
  through neighbouring beams) runs from REF's and from EST's relative pose; pairs where the two
  runs end more than 0.02 m / 0.3 deg apart (no single optimum) are skipped. Prints the mean
  distance of REF and EST to the optimum and a three-cornered-hat split of the mean squares
  (ref, est, icp; valid if the three errors are independent, which EST and ICP are not fully:
  both fit the same points)."""
import math, sys, random, statistics as S
def wrap(a): return math.atan2(math.sin(a), math.cos(a))
def rel(a, b):
    c, s = math.cos(a[2]), math.sin(a[2]); dx, dy = b[0]-a[0], b[1]-a[1]
    return (c*dx+s*dy, -s*dx+c*dy, wrap(b[2]-a[2]))
def load(p): return [tuple(map(float, l.split()[1:4])) for l in open(p) if l.strip() and not l.startswith('#')]
def scans(p):
    out = []
    for l in open(p):
        s = l.split()
        if not s or s[0] != 'FLASER': continue
        n = int(s[1]); r = list(map(float, s[2:2+n])); res = math.pi / n if n in (180, 360) else math.pi/(n-1)
        pts = [(ri*math.cos(-math.pi/2+i*res), ri*math.sin(-math.pi/2+i*res)) if 0.05 < ri < 40 else None for i, ri in enumerate(r)]
        out.append(pts)
    return out
CELL = 0.25
class Model:
    def __init__(self, pts):
        self.lines = []  # (px,py,nx,ny) local line at each point with a valid neighbour
        for i, p in enumerate(pts):
            if p is None: continue
            best = None
            for j in (i-1, i+1):
                if 0 <= j < len(pts) and pts[j] is not None:
                    d = math.hypot(pts[j][0]-p[0], pts[j][1]-p[1])
                    if d < 0.3 and (best is None or d < best[0]): best = (d, pts[j])
            if best is None or best[0] < 1e-6: continue
            dx, dy = best[1][0]-p[0], best[1][1]-p[1]; L = math.hypot(dx, dy)
            self.lines.append((p[0], p[1], -dy/L, dx/L))
        self.grid = {}
        for k, l in enumerate(self.lines):
            self.grid.setdefault((int(math.floor(l[0]/CELL)), int(math.floor(l[1]/CELL))), []).append(k)
    def nearest(self, x, y, maxd):
        cx, cy = int(math.floor(x/CELL)), int(math.floor(y/CELL)); best = None; bd = maxd*maxd
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for k in self.grid.get((cx+dx, cy+dy), ()):
                    l = self.lines[k]; d = (l[0]-x)**2 + (l[1]-y)**2
                    if d < bd: bd, best = d, l
        return best
def icp(model, pts, T, iters=30, maxd=0.25, trim=0.05):
    x, y, th = T
    for it in range(iters):
        c, s = math.cos(th), math.sin(th)
        H = [[0.0]*3 for _ in range(3)]; g = [0.0]*3; n = 0; sr = 0
        for p in pts:
            if p is None: continue
            qx, qy = c*p[0]-s*p[1]+x, s*p[0]+c*p[1]+y
            l = model.nearest(qx, qy, maxd)
            if l is None: continue
            r = l[2]*(qx-l[0]) + l[3]*(qy-l[1])
            w = 1.0/(1.0+(r/trim)**2)
            J = (l[2], l[3], l[2]*(-(s*p[0]+c*p[1])) + l[3]*(c*p[0]-s*p[1]))
            for a in range(3):
                g[a] += w*J[a]*r
                for b in range(3): H[a][b] += w*J[a]*J[b]
            n += 1; sr += w*r*r
        if n < 20: return None
        # solve H d = -g
        A = [H[i][:] + [-g[i]] for i in range(3)]
        for i in range(3):
            piv = max(range(i, 3), key=lambda r: abs(A[r][i])); A[i], A[piv] = A[piv], A[i]
            if abs(A[i][i]) < 1e-12: return None
            for r in range(3):
                if r != i:
                    f = A[r][i]/A[i][i]
                    for cc in range(i, 4): A[r][cc] -= f*A[i][cc]
        d = [A[i][3]/A[i][i] for i in range(3)]
        x += d[0]; y += d[1]; th = wrap(th + d[2])
        if abs(d[0])+abs(d[1]) < 1e-5 and abs(d[2]) < 1e-6: break
    return (x, y, th, n, math.sqrt(sr/max(1, n)))
if __name__ == '__main__':
    log, refp, estp = sys.argv[1:4]; mode = sys.argv[4] if len(sys.argv) > 4 else 'loop'
    N = int(sys.argv[5]) if len(sys.argv) > 5 else 200
    sc = scans(log); ref = load(refp); est = load(estp)
    n = len(ref)
    if mode == 'local': pairs = [(i, i+1) for i in range(n-1)]
    else: pairs = [(i, j) for i in range(n) for j in range(i+20, n) if math.hypot(ref[i][0]-ref[j][0], ref[i][1]-ref[j][1]) < 3.0]
    random.seed(1); pairs = random.sample(pairs, min(N, len(pairs)))
    rows = []; vec = []
    for i, j in pairs:
        m = Model(sc[i]); rr, re = rel(ref[i], ref[j]), rel(est[i], est[j])
        a = icp(m, sc[j], rr); b = icp(m, sc[j], re)
        if a is None or b is None: continue
        if math.hypot(a[0]-b[0], a[1]-b[1]) > 0.02 or abs(wrap(a[2]-b[2])) > 0.005: continue  # ambiguous optimum
        vec.append(((rr[0]-a[0], rr[1]-a[1], wrap(rr[2]-a[2])), (re[0]-a[0], re[1]-a[1], wrap(re[2]-a[2])), (re[0]-rr[0], re[1]-rr[1], wrap(re[2]-rr[2]))))
        rows.append((math.hypot(rr[0]-a[0], rr[1]-a[1]), abs(math.degrees(wrap(rr[2]-a[2]))),
                     math.hypot(re[0]-a[0], re[1]-a[1]), abs(math.degrees(wrap(re[2]-a[2]))),
                     math.hypot(rr[0]-re[0], rr[1]-re[1]), a[4]))
    print(f'{mode}: {len(rows)}/{len(pairs)} pairs with one ICP optimum')
    print('ref->icp  t %.4f (med %.4f) r %.3f deg | est->icp t %.4f (med %.4f) r %.3f deg | est-ref t %.4f | icp rms %.4f' % (
        S.mean(r[0] for r in rows), S.median(r[0] for r in rows), S.mean(r[1] for r in rows),
        S.mean(r[2] for r in rows), S.median(r[2] for r in rows), S.mean(r[3] for r in rows), S.mean(r[4] for r in rows), S.mean(r[5] for r in rows)))

    # three-cornered hat: ms(ref-icp)=vR+vI, ms(est-icp)=vE+vI, ms(est-ref)=vE+vR (independent errors)
    for name, sl in (('t', slice(0, 2)), ('r', slice(2, 3))):
        m = [S.mean(sum(c*c for c in v[k][sl]) for v in vec) for k in range(3)]
        vR = (m[0] + m[2] - m[1]) / 2; vE = (m[1] + m[2] - m[0]) / 2; vI = (m[0] + m[1] - m[2]) / 2
        f = (lambda v: math.copysign(math.sqrt(abs(v)), v)) if name == 't' else (lambda v: math.degrees(math.copysign(math.sqrt(abs(v)), v)))
        print(f'three-cornered hat {name}: rms ref %.4f est %.4f icp %.4f' % (f(vR), f(vE), f(vI)))
