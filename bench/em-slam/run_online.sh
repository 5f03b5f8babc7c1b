#!/usr/bin/env bash
# gv-em-slam --online against the batch on the benchmark logs (doc/benchmarks.md, "Online EM-SLAM"):
# per log the batch, --online and --online --refine, one at a time on one core, each trajectory scored
# by evaltraj.py (trajectory_online.txt too), the online per-scan latency from report.json.
#   bench/em-slam/run_online.sh BIN_DIR OUT_DIR [LOG...]   (LOG: e.g. intel_s1; default: the 8 logs, seed 1)
set -euo pipefail
bin=$1 out=$2; shift 2
logs=("$@")
[ ${#logs[@]} -gt 0 ] || logs=(acapulco_s1 aces_s1 csail_s1 freiburg-079_s1 freiburg-101_s1 infinite-corridor_s1 intel_s1 seattle_s1)
bench=/work/benchlogs eval="python3 /work/shared/bench/evaltraj.py"
mkdir -p "$out"
for l in "${logs[@]}"; do
  for mode in batch online refine; do
    d=$out/$l.$mode
    case $mode in batch) extra=();; online) extra=(--online);; refine) extra=(--online --refine);; esac
    taskset -c 0 "$bin/gv-em-slam" --input "$bench/$l.log" --out "$d" --quiet "${extra[@]}" || true
    echo "$l $mode final $($eval "$d/trajectory.txt" "$bench/$l.ref.txt")"
    if [ "$mode" != batch ]; then
      echo "$l $mode causal $($eval "$d/trajectory_online.txt" "$bench/$l.ref.txt")"
      python3 -c "import json,sys; o=json.load(open(sys.argv[1]))['online']; c, l, b = o['cpu_ms'], o['latency_ms'], o['background_ms']; print(sys.argv[2], 'cpu_ms median %.2f p99 %.2f max %.2f; wall_ms median %.2f p99 %.2f; background %d optimisations cpu_ms median %.1f max %.1f' % (c['median'], c['p99'], c['max'], l['median'], l['p99'], b['optimisations'], b['cpu_median'], b['cpu_max']))" "$d/report.json" "$l $mode"
    fi
  done
done
