#!/usr/bin/env python3
"""Express a gv-em-slam map in a simulator's truth frame.

usage: align_vectors.py VECTORS.txt EST_TRAJ.txt TRUTH_TRAJ.txt OUT_VECTORS.txt
       [DOORS.txt OUT_DOORS.txt]

SLAM estimates live in the frame of the first odometry pose; the truth files
of gv-sim live in the world frame. The SE(2) transform that best aligns the
estimated trajectory with the true one (least squares, as evaltraj.py's ATE)
is applied to every vector (and door hinge/angles), so gv-eval map can score
the map against the true walls."""
import bisect, math, sys

def load(p):
    out = []
    for line in open(p):
        s = line.split()
        if s and not s[0].startswith('#'):
            out.append(tuple(float(v) for v in s[:4]))
    return out

def align(est, ref):
    et = [e[0] for e in est]
    pairs = []
    for g in ref:
        i = bisect.bisect_left(et, g[0])
        for j in (i - 1, i):
            if 0 <= j < len(est) and abs(est[j][0] - g[0]) < 0.05:
                pairs.append((est[j][1:3], g[1:3]))
                break
    n = len(pairs)
    mx = sum(p[0][0] for p in pairs) / n; my = sum(p[0][1] for p in pairs) / n
    gx = sum(p[1][0] for p in pairs) / n; gy = sum(p[1][1] for p in pairs) / n
    sxx = sum((p[0][0] - mx) * (p[1][0] - gx) + (p[0][1] - my) * (p[1][1] - gy) for p in pairs)
    sxy = sum((p[0][0] - mx) * (p[1][1] - gy) - (p[0][1] - my) * (p[1][0] - gx) for p in pairs)
    th = math.atan2(sxy, sxx)
    c, s = math.cos(th), math.sin(th)
    return lambda x, y: (c * (x - mx) - s * (y - my) + gx, s * (x - mx) + c * (y - my) + gy), th

def main():
    vec, est, ref, out = sys.argv[1:5]
    tf, th = align(load(est), load(ref))
    with open(out, 'w') as o:
        for line in open(vec):
            s = line.split()
            if not s or s[0].startswith('#'):
                o.write(line); continue
            a = tf(float(s[0]), float(s[1])); b = tf(float(s[2]), float(s[3]))
            o.write('%.4f %.4f %.4f %.4f %s\n' % (a[0], a[1], b[0], b[1], ' '.join(s[4:])))
    if len(sys.argv) > 6:
        with open(sys.argv[6], 'w') as o:
            for line in open(sys.argv[5]):
                s = line.split()
                if not s or s[0].startswith('#'):
                    o.write(line); continue
                h = tf(float(s[0]), float(s[1]))
                rest = [s[2]] + ['%.4f' % (float(a) + th) for a in s[3:5]] + s[5:]
                o.write('%.4f %.4f %s\n' % (h[0], h[1], ' '.join(rest)))

if __name__ == '__main__':
    main()
