#!/usr/bin/env python3
"""Deliberately broken benchmark logs for the self-check (issue 21, item 3).

  breaklog.py splice ODOM_LOG SCAN_LOG OUT.log   the k-th ODOM pose of ODOM_LOG with the k-th
      FLASER line of SCAN_LOG (its poses replaced by that odometry), for k below the shorter log's count (mkbench.py logs share one
      timeline, t0 + 0.2 s per scan, so the timestamps stay consistent: the scan's own are kept)
  breaklog.py drop LOG OUT.log                   every other FLASER line dropped (ODOM kept)
Score either against the scans' log's reference (.ref.txt), matched by time."""
import sys

def lines(path, kind):
    with open(path) as f:
        return [l for l in f if l.startswith(kind + ' ')]

def header(path):
    with open(path) as f:
        return [l for l in f if l.startswith('#') or l.startswith('PARAM ')]

def splice(odom_log, scan_log, out):
    odom, scans = lines(odom_log, 'ODOM'), lines(scan_log, 'FLASER')
    with open(out, 'w') as o:
        o.writelines(header(scan_log))
        for od, sc in zip(odom, scans):
            p, s = od.split(), sc.split()
            n = int(s[1])
            ts = s[2 + n + 6]
            s[2 + n:2 + n + 6] = p[1:4] * 2  # FLASER carries the odometry too (both poses, as mkbench.py writes)
            o.write(' '.join(p[:7] + [ts, 'bench', ts]) + '\n' + ' '.join(s) + '\n')

def drop(log, out):
    k = 0
    with open(log) as f, open(out, 'w') as o:
        for l in f:
            if l.startswith('FLASER '):
                k += 1
                if k % 2 == 0:
                    continue
            o.write(l)

if sys.argv[1] == 'splice':
    splice(*sys.argv[2:5])
else:
    drop(*sys.argv[2:4])
