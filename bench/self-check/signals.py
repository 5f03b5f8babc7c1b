#!/usr/bin/env python3
"""The self-check's signals of gv-em-slam runs beside their scores: one markdown row per run.
  signals.py TABLE.tsv RUNS_DIR   (TABLE.tsv from run_table.sh: name rc loop ate odo_loop odo_ate ...;
  RUNS_DIR/<name>/em/report.json)"""
import json, sys

rows = [l.rstrip('\n').split('\t') for l in open(sys.argv[1]) if l.strip()]
print('| run | exit | loop [m] | ATE [m] | odometry loop / ATE [m] | converged (iterations) | failed registrations | '
      'rejected edges | normalised chi2 | keyframes without a sequential edge | beams through occupied static cells | '
      'dynamic share of map length | verdict |')
print('|---|---|---|---|---|---|---|---|---|---|---|---|---|')
for r in rows:
    name, rc, loop, ate, oloop, oate = r[:6]
    rep = json.load(open(f'{sys.argv[2]}/{name}/em/report.json'))
    s, m = rep['self_check'], rep['final_map']
    dyn = m['dynamic_length_m'] / max(1e-9, m['static_length_m'] + m['dynamic_length_m'])
    chi = s['normalised_chi2']
    print(f"| {name} | {rc} | {loop} | {ate} | {oloop} / {oate} | {'yes' if s['converged'] else 'no'} ({s['iterations']}) | "
          f"{s['failed_share']:.3f} | {s['rejected_share']:.4f} | {'n/a' if chi is None else '%.2f' % chi} | "
          f"{s['unlinked_share']:.3f} | {s['through_wall_share']:.4f} | {dyn:.3f} | {s['verdict']} |")
