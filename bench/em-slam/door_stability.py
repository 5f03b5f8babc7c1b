#!/usr/bin/env python3
"""Door hinges of gv-em-slam runs on one log, in the reference frame, matched across runs
(doc/benchmarks.md, "Doors on the real logs").

usage: door_stability.py [--radius 0.3] [--rows] LABEL:RUN_DIR:REF.txt ...
  RUN_DIR holds doors.txt and trajectory.txt; REF.txt is the benchmark's .ref.txt. Runs labelled
  'perf' (e.g. a benchmark made with zero odometry noise) are matched against the others but
  not counted among them.
Each run's hinges go to the reference frame by the SE(2) alignment of its trajectory to the
reference (Umeyama without scale over poses matched by timestamp within 0.05 s, as evaltraj.py),
either of the whole trajectory ('global') or of the poses within 5 m of the hinge (at least
the nearest 20: 'local', against the trajectory's drift far from the hinge). A hinge is found
on another run when one of that run's hinges lies within the radius. Prints, per run: doors,
doors found on >= 2 runs (itself and another); with --rows, each door with the runs finding it
(n/N), whether the perf run finds it, and the distance to the nearest hinge of another run."""
import argparse, bisect, math


def load(path, ncol):
    out = []
    for line in open(path):
        s = line.split()
        if s and not s[0].startswith('#'):
            out.append([float(v) for v in s[:ncol]])
    return out


def matched_positions(est, ref):
    """(estimated xy, reference xy) of the poses matched by timestamp within 0.05 s."""
    times = [e[0] for e in est]
    out = []
    for g in ref:
        i = bisect.bisect_left(times, g[0])
        near = [j for j in (i - 1, i) if 0 <= j < len(est) and abs(est[j][0] - g[0]) < 0.05]
        if near:
            j = min(near, key=lambda j: abs(est[j][0] - g[0]))
            out.append((est[j][1:3], g[1:3]))
    return out


def se2_fit(pairs):
    """Umeyama without scale: the rigid motion taking the estimated points onto the reference."""
    n = len(pairs)
    mx, my = sum(p[0][0] for p in pairs) / n, sum(p[0][1] for p in pairs) / n
    gx, gy = sum(p[1][0] for p in pairs) / n, sum(p[1][1] for p in pairs) / n
    sxx = sum((p[0][0] - mx) * (p[1][0] - gx) + (p[0][1] - my) * (p[1][1] - gy) for p in pairs)
    sxy = sum((p[0][0] - mx) * (p[1][1] - gy) - (p[0][1] - my) * (p[1][0] - gx) for p in pairs)
    th = math.atan2(sxy, sxx)
    c, s = math.cos(th), math.sin(th)
    return lambda x, y: (c * (x - mx) - s * (y - my) + gx, s * (x - mx) + c * (y - my) + gy)


def hinges_in_ref(run_dir, ref_path):
    doors = load(run_dir + '/doors.txt', 6)
    pairs = matched_positions(load(run_dir + '/trajectory.txt', 4), load(ref_path, 4))
    whole = se2_fit(pairs)
    glob, loc = [], []
    for d in doors:
        glob.append(whole(d[0], d[1]))
        near = sorted(pairs, key=lambda p: math.hypot(p[0][0] - d[0], p[0][1] - d[1]))
        within = [p for p in near if math.hypot(p[0][0] - d[0], p[0][1] - d[1]) < 5.0]
        loc.append(se2_fit(within if len(within) >= 20 else near[:20])(d[0], d[1]))
    return doors, {'global': glob, 'local': loc}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--radius', type=float, default=0.3)
    ap.add_argument('--rows', action='store_true')
    ap.add_argument('runs', nargs='+')
    a = ap.parse_args()
    runs = []
    for spec in a.runs:
        label, run_dir, ref = spec.split(':')
        runs.append((label,) + hinges_in_ref(run_dir, ref))
    counted = [r for r in runs if r[0] != 'perf']
    perf = [r for r in runs if r[0] == 'perf']
    hit = lambda x, y, r, mode: any(math.hypot(x - u, y - v) <= a.radius for (u, v) in r[2][mode])
    for mode in ('global', 'local'):
        print(f'# {mode} alignment, radius {a.radius} m')
        for label, doors, hs in counted:
            stable, rows = 0, []
            for i, (x, y) in enumerate(hs[mode]):
                others = [r for r in counted if r[0] != label]
                n = 1 + sum(hit(x, y, r, mode) for r in others)
                stable += n >= 2
                nearest = min((math.hypot(x - u, y - v) for r in others for (u, v) in r[2][mode]), default=float('inf'))
                in_perf = any(hit(x, y, r, mode) for r in perf)
                rows.append(f'  {label} door {i}: est ({doors[i][0]:.2f}, {doors[i][1]:.2f}) ref ({x:.2f}, {y:.2f}) '
                            f'length {doors[i][2]:.2f} states {int(doors[i][5])} runs {n}/{len(counted)} '
                            f'{"+" if in_perf else "-"}perf nearest other {nearest:.2f} m')
            print(f'{label}: doors {len(doors)}, on >= 2 runs {stable}')
            if a.rows:
                print('\n'.join(rows))
        for label, doors, hs in perf:
            found = sum(any(hit(x, y, r, mode) for r in counted) for (x, y) in hs[mode])
            print(f'{label}: doors {len(doors)}, found on >= 1 other run {found}')


if __name__ == '__main__':
    main()
