#!/usr/bin/env python3
"""The self-check's signals of gv-em-slam runs beside their scores: one markdown row per run.
  signals.py TABLE.tsv RUNS_DIR   (TABLE.tsv from run_table.sh: name rc loop ate odo_loop odo_ate ...;
  RUNS_DIR/<name>/em/report.json). The last column applies libgridvector/src/em/SelfCheck.h's rules to the
  report's figures (for reports written before the thresholds were set; a report of this version has them
  in self_check.verdict)."""
import json, sys

def verdict(s, dyn):
    chi = s['normalised_chi2']
    why = []
    if chi is not None and chi > 1.0: why.append('chi2')
    if s['rejected_share'] > 0.05: why.append('rejected')
    if s['unlinked_share'] > 0.2: why.append('unlinked')
    if not s['converged'] and s['failed_share'] > 0.75: why.append('unconverged+failed')
    if not s['converged'] and dyn > 0.6: why.append('unconverged+dynamic')
    return 'suspect (' + ', '.join(why) + ')' if why else 'ok'

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
          f"{s['unlinked_share']:.3f} | {s['through_wall_share']:.4f} | {dyn:.3f} | {verdict(s, dyn)} |")
