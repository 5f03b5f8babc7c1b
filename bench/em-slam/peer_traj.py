#!/usr/bin/env python3
"""Turn MRPT 2.5 icp-slam / rbpf-slam output into `t x y theta` trajectories (one row per scan).

usage: peer_traj.py icp      BENCH.log MRPT_OUT_DIR OUT.txt
       peer_traj.py rbpf     BENCH.log MRPT_OUT_DIR OUT.txt   (filtered estimate)
       peer_traj.py rbpf-ml  BENCH.log MRPT_OUT_DIR OUT.txt   (best particle's path)

Scan timestamps come from the benchmark CARMEN log (FLASER lines, in order), the same
ones gv-carmen2rawlog puts into the rawlog. Layouts read from MRPT 2.5.8's output:
- icp-slam `log_estimated_path.txt`: `step x y yaw`, one row per rawlog entry; with the
  observation-only rawlog of gv-carmen2rawlog the entries are ODOMETRY, FLASER per scan,
  so the laser rows are steps 1, 3, 5, ... (the pose after that scan was processed).
- rbpf-slam `log_estimated_path.txt`: `step x y z yaw pitch roll timestamp`, one row per
  action/sensory-frame pair (the particles' mean plus odometry since the last update).
- rbpf-slam `most_likely_path.txt`: `x y yaw` of the best particle, the start pose and
  then one pose per filter update; the updated steps are those with `frame_inserted? = 1`
  in `log_times.txt` (localise and insert thresholds are equal in rbpf_os_*.ini). Scans
  between updates get the best pose at the last update composed with the odometry since
  it (`log_odometry_path.txt`), as MRPT's own per-scan estimate does, so every system is
  scored on every scan.
Exits 1 with one line on stderr when the files do not have the expected shape."""
import math
import os
import sys


def fail(msg):
    sys.stderr.write(msg + '\n')
    sys.exit(1)


def scan_times(log):
    ts = []
    for line in open(log):
        p = line.split()
        if p and p[0] == 'FLASER':
            n = int(p[1])
            ts.append(p[2 + n + 6])  # ranges, then x y th odom_x odom_y odom_th ts host lts
    return ts


def rows(path, min_cols):
    if not os.path.exists(path):
        fail(f'{os.path.basename(path)} missing')
    out = []
    for line in open(path):
        s = line.split()
        if not s or s[0].startswith('%') or s[0].startswith('#'):
            continue
        if len(s) < min_cols:
            fail(f'{os.path.basename(path)}: {len(s)} columns, expected {min_cols}')
        out.append([float(v) for v in s])
    return out


def compose(a, b):
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], a[2] + b[2])


def between(a, b):
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (c * dx + s * dy, -s * dx + c * dy, math.atan2(math.sin(b[2] - a[2]), math.cos(b[2] - a[2])))


def icp_poses(d, n):
    r = rows(os.path.join(d, 'log_estimated_path.txt'), 4)
    if len(r) != 2 * n:
        fail(f'log_estimated_path.txt has {len(r)} rows, expected {2 * n} (odometry + laser per scan)')
    return [(q[1], q[2], q[3]) for q in r[1::2]]


def rbpf_poses(d, n):
    r = rows(os.path.join(d, 'log_estimated_path.txt'), 5)
    if len(r) != n:
        fail(f'log_estimated_path.txt has {len(r)} rows, expected {n}')
    return [(q[1], q[2], q[4]) for q in r]


def rbpf_ml_poses(d, n):
    best = rows(os.path.join(d, 'most_likely_path.txt'), 3)
    times = rows(os.path.join(d, 'log_times.txt'), 4)
    odo = rows(os.path.join(d, 'log_odometry_path.txt'), 5)
    if len(times) != n or len(odo) != n:
        fail(f'log_times.txt/log_odometry_path.txt have {len(times)}/{len(odo)} rows, expected {n}')
    updated = [int(q[0]) for q in times if q[3] == 1]
    if not updated or updated[0] != 0 or len(best) != len(updated) + 1:
        fail(f'most_likely_path.txt has {len(best)} poses for {len(updated)} filter updates')
    out, k = [], -1
    for i in range(n):
        if k + 1 < len(updated) and updated[k + 1] == i:
            k += 1
        kf = updated[k]
        base = (best[k + 1][0], best[k + 1][1], best[k + 1][2])
        o_kf, o_i = (odo[kf][1], odo[kf][2], odo[kf][4]), (odo[i][1], odo[i][2], odo[i][4])
        out.append(compose(base, between(o_kf, o_i)))
    return out


def main():
    if len(sys.argv) != 5 or sys.argv[1] not in ('icp', 'rbpf', 'rbpf-ml'):
        fail(__doc__.split('\n\n')[1])
    kind, log, d, out = sys.argv[1:]
    ts = scan_times(log)
    if not ts:
        fail(f'{log}: no FLASER lines')
    poses = {'icp': icp_poses, 'rbpf': rbpf_poses, 'rbpf-ml': rbpf_ml_poses}[kind](d, len(ts))
    with open(out, 'w') as f:
        for t, p in zip(ts, poses):
            f.write(f'{t} {p[0]:.6f} {p[1]:.6f} {p[2]:.6f}\n')


if __name__ == '__main__':
    main()
