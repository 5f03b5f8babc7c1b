#!/usr/bin/env python3
"""Deliberately broken benchmark logs for the self-check (issue 21, item 3).

  breaklog.py splice ODOM_LOG SCAN_LOG OUT.log   the k-th ODOM line of ODOM_LOG with the k-th
      FLASER line of SCAN_LOG, for k below the shorter log's count (mkbench.py logs share one
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
            ts = s[2 + int(s[1]) + 6]
            o.write(' '.join(p[:7] + [ts, 'bench', ts]) + '\n' + sc)

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
