#!/usr/bin/env bash
# EM-SLAM benchmarks (doc/benchmarks.md, section "EM-SLAM (gv-em-slam)").
#
#   bench/em-slam/run_benchmarks.sh BUILD_BIN_DIR OUT_DIR [SEEDS...]
#
# Real logs: every ../shared/data/*-corrected.log.gz made into a benchmark with
# mkbench.py (default seed 1), mapped by gv-em-slam, scored by evaltraj.py.
# Simulated worlds: gv-sim (default world, seeds 1-3; the other worlds, seed 1),
# scored with gv-eval (trajectory, and the map after aligning it to the truth frame).
# Prints markdown table rows; each run's outputs stay in OUT_DIR.
set -euo pipefail
BIN=$1; OUT=$2; shift 2
SEEDS=${*:-1}
HERE=$(cd "$(dirname "$0")" && pwd)
SHARED=${GV_SHARED_DIR:-$HERE/../../../shared}
mkdir -p "$OUT"
secs() { python3 -c "import sys; print('%.1f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$1" "$2"; }
field() { sed -n "s/.*$1=\([0-9.na]*\).*/\1/p"; }

echo "| log | seed | scans | iterations | converged | time [s] | ATE [m] | rel. local t [m] | rel. loop t [m] | rel. loop r [deg] |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for seed in $SEEDS; do
  for gz in "$SHARED"/data/*-corrected.log.gz; do
    name=$(basename "$gz" -corrected.log.gz)
    b="$OUT/bench_${name}_s$seed"
    python3 "$SHARED/bench/mkbench.py" "$gz" "$b" --seed "$seed" > /dev/null
    t0=$(date +%s.%N)
    "$BIN/gv-em-slam" --input "$b.log" --out "$OUT/${name}_s$seed" --quiet
    t1=$(date +%s.%N)
    r=$(python3 "$SHARED/bench/evaltraj.py" "$OUT/${name}_s$seed/trajectory.txt" "$b.ref.txt")
    rep="$OUT/${name}_s$seed/report.json"
    it=$(sed -n 's/.*"iterations_run": \([0-9]*\).*/\1/p' "$rep")
    conv=$(sed -n 's/.*"converged": \([a-z]*\).*/\1/p' "$rep")
    echo "| $name | $seed | $(echo "$r" | field n) | $it | $conv | $(secs "$t0" "$t1") | $(echo "$r" | field ate_rmse_m) | $(echo "$r" | field rel_local_t_m) | $(echo "$r" | field rel_loop_t_m) | $(echo "$r" | field rel_loop_r_deg) |"
  done
done

echo
echo "| world | seed | scans | iterations | time [s] | ATE [m] | static precision | static recall | ghost share | dynamic detection | door recall |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
sim_row() {
  local world=$1 seed=$2 d="$OUT/sim_$1_s$2"
  "$BIN/gv-sim" --world "$world" --seed "$seed" --out "$d/sim" --quiet
  t0=$(date +%s.%N)
  "$BIN/gv-em-slam" --input "$d/sim/sim.log" --out "$d/em" --quiet
  t1=$(date +%s.%N)
  r=$("$BIN/gv-eval" traj "$d/em/trajectory.txt" "$d/sim/truth_trajectory.txt")
  "$BIN/gv-eval" map "$d/em/vectors.txt" "$d/sim" --trajectory "$d/em/trajectory.txt" \
    --doors "$d/em/doors.txt" > "$d/map_eval.txt"
  m() { sed -n "s/^$1: *\([0-9.]*\).*/\1/p" "$d/map_eval.txt" | head -1; }
  local prec rec ghost det door
  prec=$(sed -n 's/^static vectors:.*precision \([0-9.]*\).*/\1/p' "$d/map_eval.txt")
  rec=$(m "static recall"); det=$(m "dynamic detection"); door=$(m "door recall")
  ghost=$(sed -n 's/^ghost length:.*(\([0-9.]*\) of static.*/\1/p' "$d/map_eval.txt")
  it=$(sed -n 's/.*"iterations_run": \([0-9]*\).*/\1/p' "$d/em/report.json")
  echo "| $world | $seed | $(echo "$r" | field n) | $it | $(secs "$t0" "$t1") | $(echo "$r" | field ate_rmse_m) | $prec | $rec | $ghost | $det | $door |"
}
for seed in 1 2 3; do sim_row corridor-loop "$seed"; done
sim_row office 1
sim_row long-corridor 1
