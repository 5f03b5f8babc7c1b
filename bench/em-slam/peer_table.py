#!/usr/bin/env python3
"""Markdown tables of gv-em-slam against the MRPT peers, from the result files of
run_benchmarks.sh (RESULT_DIR/<log>_s<seed>/<column>.txt, one line each: the evaltraj.py
line plus `time_s=` and `scans=`, or `failed: <reason>`).

usage: peer_table.py RESULT_DIR "LOGS" "SEEDS"
One table per seed (rows: log x {loop-relation t, ATE, time, scans/s}; columns: systems),
then, for several seeds, the mean loop-relation error over the seeds."""
import os
import re
import sys

COLUMNS = [('gv', 'gv-em-slam'), ('gv-rawlog', 'gv-em-slam, peers\' rawlog'), ('icp-classic', 'icp classic'), ('icp-grid', 'icp grid'),
           ('rbpf-filtered', 'rbpf filtered'), ('rbpf-best', 'rbpf best')]
METRICS = [('rel_loop_t_m', 'loop t [m]', '%.4f'), ('ate_rmse_m', 'ATE [m]', '%.4f'),
           ('time_s', 'time [s]', '%.1f'), ('scans_per_s', 'scans/s', '%.0f')]


def load(path):
    """dict of figures, {'failed': reason}, or None when the system was not run."""
    if not os.path.exists(path):
        return None
    line = open(path).read().strip()
    if line.startswith('failed:'):
        return {'failed': line[len('failed:'):].strip()}
    d = {k: float(v) for k, v in re.findall(r'(\w+)=([-0-9.naif]+)', line)}
    if d.get('time_s', 0) > 0 and 'scans' in d:
        d['scans_per_s'] = d['scans'] / d['time_s']
    return d


def cell(r, key, fmt):
    if r is None:
        return 'not run'
    if 'failed' in r:
        return 'failed: ' + r['failed'].replace('|', '/')
    return fmt % r[key] if key in r else '-'


def main():
    res, logs, seeds = sys.argv[1], sys.argv[2].split(), sys.argv[3].split()
    head = '| log | figure | ' + ' | '.join(c[1] for c in COLUMNS) + ' |'
    rule = '|---|---|' + '---|' * len(COLUMNS)
    loops = {}
    for seed in seeds:
        print(f'\nSeed {seed}:\n\n{head}\n{rule}')
        for log in logs:
            rs = [load(os.path.join(res, f'{log}_s{seed}', c[0] + '.txt')) for c in COLUMNS]
            for key, name, fmt in METRICS:
                print(f'| {log} | {name} | ' + ' | '.join(cell(r, key, fmt) for r in rs) + ' |')
            for c, r in zip(COLUMNS, rs):
                loops.setdefault((log, c[0]), []).append(r.get('rel_loop_t_m') if r and 'failed' not in r else None)
    if len(seeds) < 2:
        return
    print(f'\nLoop-relation translational error [m], mean over seeds {", ".join(seeds)} '
          '(a failed or missing run leaves the cell as the count of runs that did score):\n')
    print('| log | ' + ' | '.join(c[1] for c in COLUMNS) + ' |\n|---|' + '---|' * len(COLUMNS))
    for log in logs:
        out = []
        for c in COLUMNS:
            v = [x for x in loops[(log, c[0])] if x is not None]
            out.append('%.4f' % (sum(v) / len(v)) if len(v) == len(seeds) else f'{len(v)}/{len(seeds)} scored')
        print(f'| {log} | ' + ' | '.join(out) + ' |')


if __name__ == '__main__':
    main()
