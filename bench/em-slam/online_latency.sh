#!/usr/bin/env bash
# Per-scan time of gv-em-slam --online beside tuned icp-slam's, in the same run (doc/benchmarks.md,
# "Online EM-SLAM", "session 16 measurements"; issue 24).
#
#   bench/em-slam/online_latency.sh BIN_DIR OUT_DIR [LOG...]   (LOG: e.g. intel_s1; default: the 8 logs, seed 1)
#
# Per log, one process at a time, both pinned to the same core (CORE, default 0):
#  1. BIN_DIR/gv-carmen2rawlog --format obs --max-range auto (as peer_run.sh), then MRPT's icp-slam with
#     ../shared/bench/peers/icp_classic_tuned.ini under /usr/bin/time. Its per-scan time is the laser rows
#     of OUT/log_times.txt (icp-slam writes one row per rawlog entry, ODOMETRY and FLASER alternate: the
#     first column is the wall time [ms] of CMetricMapBuilderICP::processObservation for that entry).
#  2. BIN_DIR/gv-em-slam --online under /usr/bin/time; per-scan CPU / wall from report.json `online`
#     (`cpu_ms`, `latency_ms`: extraction + addScan, without the due optimisation; `synchronous_ms`:
#     with it, as the replay runs it in the scan's thread).
# Both trajectories scored by evaltraj.py (ours: trajectory.txt and trajectory_online.txt).
# Prints one markdown row per log (columns: see the header below); outputs stay in OUT_DIR/LOG.
set -uo pipefail
[ $# -ge 2 ] || { sed -n '2,16p' "$0" >&2; exit 2; }
BIN=$1 OUT=$2; shift 2
logs=("$@")
[ ${#logs[@]} -gt 0 ] || logs=(acapulco_s1 aces_s1 csail_s1 freiburg-079_s1 freiburg-101_s1 infinite-corridor_s1 intel_s1 seattle_s1)
HERE=$(cd "$(dirname "$0")" && pwd)
SHARED=${GV_SHARED_DIR:-$HERE/../../../shared}
BENCH=${GV_BENCH_DIR:-/work/benchlogs}
CORE=${CORE:-0}
ICP=${MRPT_ICP_SLAM:-icp-slam}
mkdir -p "$OUT"
cpu() { python3 -c "import re,sys; t=open(sys.argv[1]).read(); u=float(re.search(r'User time \(seconds\): ([0-9.]+)', t).group(1)); s=float(re.search(r'System time \(seconds\): ([0-9.]+)', t).group(1)); r=int(re.search(r'Maximum resident set size \(kbytes\): ([0-9]+)', t).group(1)); print('%.2f %d' % (u + s, r))" "$1"; }
loop() { python3 "$SHARED/bench/evaltraj.py" "$1" "$2" 2>/dev/null | sed -n 's/.*rel_loop_t_m=\([0-9.na]*\).*/\1/p'; }

echo "| log | scans | icp-slam CPU [s] / per scan [ms] | icp-slam per scan p50 / p99 / max [ms] | gv online CPU [s] / per scan [ms] | gv online CPU per scan p50 / p99 / max [ms] | gv wall p50 / p99 [ms] | gv with optimisation p50 / p99 [ms] | loop [m] icp / gv final / gv causal | peak RSS icp / gv [MB] |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for l in "${logs[@]}"; do
  b=$BENCH/$l w=$OUT/$l
  rm -rf "$w"; mkdir -p "$w"
  scans=$(wc -l < "$b.ref.txt")
  "$BIN/gv-carmen2rawlog" "$b.log" "$w/bench.obs.rawlog" --format obs --max-range auto --quiet
  (cd "$w" && /usr/bin/time -v -o icp.time taskset -c "$CORE" "$ICP" "$SHARED/bench/peers/icp_classic_tuned.ini" bench.obs.rawlog > icp.log 2>&1)
  read -r icp_cpu icp_rss < <(cpu "$w/icp.time")
  python3 "$HERE/peer_traj.py" icp "$b.log" "$w/OUT" "$w/trajectory_icp.txt"
  icp_stats=$(python3 - "$w/OUT/log_times.txt" "$scans" <<'EOF'
import math, sys
rows = [float(l.split()[0]) for l in open(sys.argv[1]) if l.strip()]
laser = sorted(rows[1::2])  # entries ODOMETRY, FLASER per scan: the laser rows are the 2nd, 4th, ...
assert len(laser) == int(sys.argv[2]), (len(laser), sys.argv[2])
q = lambda p: laser[max(0, math.ceil(p * len(laser)) - 1)]  # nearest rank, as report.json's
print('%.2f / %.2f / %.2f' % (q(0.5), q(0.99), laser[-1]))
EOF
)
  /usr/bin/time -v -o "$w/gv.time" taskset -c "$CORE" "$BIN/gv-em-slam" --input "$b.log" --out "$w/gv" --quiet --online 2> "$w/gv.err"
  read -r gv_cpu gv_rss < <(cpu "$w/gv.time")
  gv_stats=$(python3 -c "import json,sys; o=json.load(open(sys.argv[1]))['online']; c,l,s=o['cpu_ms'],o['latency_ms'],o['synchronous_ms']; print('%.2f / %.2f / %.2f | %.2f / %.2f | %.2f / %.2f' % (c['median'], c['p99'], c['max'], l['median'], l['p99'], s['median'], s['p99']))" "$w/gv/report.json")
  per() { python3 -c "import sys; print('%.2f / %.2f' % (float(sys.argv[1]), 1e3 * float(sys.argv[1]) / int(sys.argv[2])))" "$1" "$scans"; }
  echo "| $l | $scans | $(per "$icp_cpu") | $icp_stats | $(per "$gv_cpu") | $gv_stats | $(loop "$w/trajectory_icp.txt" "$b.ref.txt") / $(loop "$w/gv/trajectory.txt" "$b.ref.txt") / $(loop "$w/gv/trajectory_online.txt" "$b.ref.txt") | $((icp_rss / 1000)) / $((gv_rss / 1000)) |"
done
