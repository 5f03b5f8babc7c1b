#!/usr/bin/env python3
"""The raw odometry of a CARMEN log as a trajectory (t x y theta per FLASER scan: the
last ODOM pose at or before the scan), to score the dead reckoning with evaltraj.py
beside gv-em-slam's trajectory.txt.   usage: odomtraj.py LOG > odom.txt"""
import gzip, sys

def main():
    path = sys.argv[1]
    op = gzip.open if path.endswith('.gz') else open
    odom = None
    with op(path, 'rt') as f:
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == 'ODOM':
                odom = (p[1], p[2], p[3])
            elif p[0] == 'FLASER' and odom is not None:
                n = int(p[1])
                print(p[2 + n + 6], *odom)

main()
