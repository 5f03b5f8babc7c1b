#!/usr/bin/env bash
# EM-SLAM benchmarks (doc/benchmarks.md, section "EM-SLAM (gv-em-slam)").
#
#   bench/em-slam/run_benchmarks.sh BUILD_BIN_DIR OUT_DIR [SEEDS...] [options]
#     --seeds "1 2 3"       mkbench seeds (default 1; positional SEEDS do the same)
#     --logs "intel aces"   benchmark logs by name (default: every ../shared/data/*-corrected.log.gz)
#     --systems LIST        comma-separated systems to run on the real logs:
#                           gv,gv-rawlog,icp-classic,icp-grid,rbpf (default: all); gv-rawlog is
#                           gv-em-slam on the peers' rawlog (gv-carmen2rawlog --max-range auto)
#     --reuse               keep MRPT peer results already in OUT_DIR (per log, seed, system)
#                           instead of re-running them; gv-em-slam always runs when selected
#     --no-sim / --no-real  skip the simulated worlds / the real logs
#     --core N              the core every timed process is pinned to (default 0)
#     --sim-rows "W:S[:P] ..."  simulated rows to run instead of the 7 default ones: world W,
#                           seed S, P people (default: the world's own count), e.g.
#                           "corridor-loop:4 office:2 corridor-loop:3:15 corridor-loop:1:0"
#
# Real logs: every log made into a benchmark with mkbench.py, mapped by gv-em-slam and by
# MRPT's icp-slam (icp_classic_tuned.ini, icp_grid_tuned.ini) and rbpf-slam
# (rbpf_os_tuned.ini; filtered estimate and best particle) on rawlogs converted with
# gv-carmen2rawlog (peer_run.sh), each process pinned to one core, all scored by
# evaltraj.py. Prints the gv-em-slam table, then one table per seed comparing the systems
# (peer_table.py; systems not run this time are taken from OUT_DIR/results if there).
# Simulated worlds: gv-sim (default world, seeds 1-3, and seeds 1-2 with 15 people; the other worlds, seed 1;
# or the rows --sim-rows names),
# scored with gv-eval (trajectory, and the map after aligning it to the truth frame, with the
# false-static breakdown: a second table); time [s] is gv-em-slam's wall time, user [s] its user
# CPU time (/usr/bin/time; each row's em_user.txt).
# Prints markdown tables; each run's outputs stay in OUT_DIR.
set -euo pipefail
BIN=$1; OUT=$2; shift 2
SEEDS="" LOGS="" SYSTEMS="gv,gv-rawlog,icp-classic,icp-grid,rbpf" REUSE=0 SIM=1 REAL=1 CORE=0
SIM_ROWS="corridor-loop:1 corridor-loop:2 corridor-loop:3 office:1 long-corridor:1 corridor-loop:1:15 corridor-loop:2:15"
while [ $# -gt 0 ]; do
  case $1 in
    --seeds) SEEDS=$2; shift 2 ;;
    --logs) LOGS=$2; shift 2 ;;
    --systems) SYSTEMS=$2; shift 2 ;;
    --reuse) REUSE=1; shift ;;
    --no-sim) SIM=0; shift ;;
    --no-real) REAL=0; shift ;;
    --core) CORE=$2; shift 2 ;;
    --sim-rows) SIM_ROWS=$2; shift 2 ;;
    -*) echo "unknown option $1" >&2; exit 2 ;;
    *) SEEDS="$SEEDS $1"; shift ;;
  esac
done
SEEDS=${SEEDS:-1}
HERE=$(cd "$(dirname "$0")" && pwd)
SHARED=${GV_SHARED_DIR:-$HERE/../../../shared}
export GV_SHARED_DIR=$SHARED
[ -n "$LOGS" ] || LOGS=$(for gz in "$SHARED"/data/*-corrected.log.gz; do basename "$gz" -corrected.log.gz; done)
for s in ${SYSTEMS//,/ }; do
  case $s in gv|gv-rawlog|icp-classic|icp-grid|rbpf) ;; *) echo "unknown system '$s'" >&2; exit 2 ;; esac
done
selected() { [[ ",$SYSTEMS," == *",$1,"* ]]; }
mkdir -p "$OUT"
secs() { python3 -c "import sys; print('%.1f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$1" "$2"; }
field() { sed -n "s/.*$1=\([0-9.na]*\).*/\1/p"; }
note() { echo "[$(date -u +%H:%M:%S)] $*" >&2; }

# gv-em-slam on one benchmark log: a row of the gv-em-slam table, and its result file.
gv_row() {
  local name=$1 seed=$2 b=$3 res=$4 d="$OUT/${1}_s$2" t0 t1 r rep it conv
  t0=$(date +%s.%N)
  if ! taskset -c "$CORE" "$BIN/gv-em-slam" --input "$b.log" --out "$d" --quiet 2> "$d.err"; then
    echo "failed: $(tail -1 "$d.err")" > "$res/gv.txt"
    echo "| $name | $seed | failed: $(tail -1 "$d.err") |"; return
  fi
  t1=$(date +%s.%N)
  if ! r=$(python3 "$SHARED/bench/evaltraj.py" "$d/trajectory.txt" "$b.ref.txt" 2>&1); then
    echo "failed: evaltraj: $(echo "$r" | tail -1)" > "$res/gv.txt"
    echo "| $name | $seed | failed: evaltraj: $(echo "$r" | tail -1) |"; return
  fi
  echo "$r time_s=$(secs "$t0" "$t1") scans=$(wc -l < "$b.ref.txt")" > "$res/gv.txt"
  rep="$d/report.json"
  it=$(sed -n 's/.*"iterations_run": \([0-9]*\).*/\1/p' "$rep")
  conv=$(sed -n 's/.*"converged": \([a-z]*\).*/\1/p' "$rep")
  echo "| $name | $seed | $(echo "$r" | field n) | $it | $conv | $(secs "$t0" "$t1") | $(echo "$r" | field ate_rmse_m) | $(echo "$r" | field rel_local_t_m) | $(echo "$r" | field rel_loop_t_m) | $(echo "$r" | field rel_loop_r_deg) |"
}

# gv-em-slam on the very rawlog the icp-slam peers read (same input, no-return range included).
gv_rawlog() {
  local name=$1 seed=$2 b=$3 res=$4 w="$OUT/peers/${1}_s$2/gv-rawlog" t0 t1 r
  mkdir -p "$w"
  if ! "$BIN/gv-carmen2rawlog" "$b.log" "$w/bench.obs.rawlog" --max-range auto --quiet 2> "$w/convert.err"; then
    echo "failed: $(head -1 "$w/convert.err")" > "$res/gv-rawlog.txt"; return
  fi
  t0=$(date +%s.%N)
  if ! taskset -c "$CORE" "$BIN/gv-em-slam" --input "$w/bench.obs.rawlog" --out "$w/out" --quiet 2> "$w/run.err"; then
    echo "failed: $(tail -1 "$w/run.err")" > "$res/gv-rawlog.txt"; return
  fi
  t1=$(date +%s.%N)
  if ! r=$(python3 "$SHARED/bench/evaltraj.py" "$w/out/trajectory.txt" "$b.ref.txt" 2>&1); then
    echo "failed: evaltraj: $(echo "$r" | tail -1)" > "$res/gv-rawlog.txt"; return
  fi
  echo "$r time_s=$(secs "$t0" "$t1") scans=$(wc -l < "$b.ref.txt")" > "$res/gv-rawlog.txt"
  note "$name s$seed gv-rawlog: $r"
}

# An MRPT peer, unless --reuse and its results are already there.
peer() {
  local sys=$1 name=$2 seed=$3 b=$4 res=$5 cols=$1 c have=1
  [ "$sys" = rbpf ] && cols="rbpf-filtered rbpf-best"
  for c in $cols; do [ -s "$res/$c.txt" ] || have=0; done
  if [ $REUSE -eq 1 ] && [ $have -eq 1 ]; then note "$name s$seed $sys: reused"; return; fi
  note "$name s$seed $sys ..."
  PEER_CORE=$CORE bash "$HERE/peer_run.sh" "$sys" "$BIN" "$b" "$OUT/peers/${name}_s$seed/$sys" "$res"
  note "$name s$seed $sys: $(head -c 160 "$res/${cols%% *}.txt")"
}

if [ $REAL -eq 1 ]; then
  if selected gv; then
    echo "| log | seed | scans | iterations | converged | time [s] | ATE [m] | rel. local t [m] | rel. loop t [m] | rel. loop r [deg] |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
  fi
  for seed in $SEEDS; do
    for name in $LOGS; do
      b="$OUT/bench_${name}_s$seed" res="$OUT/results/${name}_s$seed"
      mkdir -p "$res"
      python3 "$SHARED/bench/mkbench.py" "$SHARED/data/$name-corrected.log.gz" "$b" --seed "$seed" > /dev/null
      if selected gv; then note "$name s$seed gv-em-slam ..."; gv_row "$name" "$seed" "$b" "$res"; fi
      if selected gv-rawlog; then gv_rawlog "$name" "$seed" "$b" "$res"; fi
      for sys in icp-classic icp-grid rbpf; do
        if selected "$sys"; then peer "$sys" "$name" "$seed" "$b" "$res"; fi
      done
    done
  done
  python3 "$HERE/peer_table.py" "$OUT/results" "$LOGS" "$SEEDS"
fi

[ $SIM -eq 1 ] || exit 0
echo
echo "| world | seed | people | scans | iterations | time [s] | ATE [m] | static precision | static precision (one-state doors static) | static recall | ghost share | ghost share (one-state doors static) | dynamic detection | door recall | door recall (seen swinging) | user [s] |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
sim_row() {
  local world=$1 seed=$2 people=${3:--1} d="$OUT/sim_$1_s$2_p${3:-default}"
  "$BIN/gv-sim" --world "$world" --seed "$seed" --people "$people" --out "$d/sim" --quiet
  t0=$(date +%s.%N)
  if [ -x /usr/bin/time ]; then   # user CPU time [s] of gv-em-slam, the last column
    /usr/bin/time -f %U -o "$d/em_user.txt" "$BIN/gv-em-slam" --input "$d/sim/sim.log" --out "$d/em" --quiet
  else
    "$BIN/gv-em-slam" --input "$d/sim/sim.log" --out "$d/em" --quiet; echo na > "$d/em_user.txt"
  fi
  t1=$(date +%s.%N)
  r=$("$BIN/gv-eval" traj "$d/em/trajectory.txt" "$d/sim/truth_trajectory.txt")
  "$BIN/gv-eval" map "$d/em/vectors.txt" "$d/sim" --trajectory "$d/em/trajectory.txt" \
    --doors "$d/em/doors.txt" --breakdown > "$d/map_eval.txt"
  m() { sed -n "s/^$1: *\([0-9.]*\).*/\1/p" "$d/map_eval.txt" | head -1; }
  local prec rec ghost det door
  prec=$(sed -n 's/^static vectors:.*precision \([0-9.]*\).*/\1/p' "$d/map_eval.txt")
  prec1=$(m "static precision (doors seen in one state are static)")
  rec=$(m "static recall"); det=$(m "dynamic detection"); door=$(m "door recall")
  ghost=$(sed -n 's/^ghost length:.*(\([0-9.]*\) of static.*/\1/p' "$d/map_eval.txt")
  ghost1=$(sed -n 's/^ghost length (doors seen in one state are static):.*(\([0-9.]*\) of static.*/\1/p' "$d/map_eval.txt")
  doorseen=$(sed -n 's/^door recall (seen swinging): *\([0-9.]*\) (\([0-9]* of [0-9]*\).*/\1 (\2)/p' "$d/map_eval.txt")
  it=$(sed -n 's/.*"iterations_run": \([0-9]*\).*/\1/p' "$d/em/report.json")
  sed -n "s/^false static: *\([0-9.]*\) m off every true wall: doors seen in one state \([0-9.]*\), doors seen in two states \([0-9.]*\), moved object \([0-9.]*\), people \([0-9.]*\), other \([0-9.]*\) m/| $world | $seed | ${3:-default} | \1 | \2 | \3 | \4 | \5 | \6 |/p" "$d/map_eval.txt" >> "$OUT/false_static.md"
  echo "| $world | $seed | ${3:-default} | $(echo "$r" | field n) | $it | $(secs "$t0" "$t1") | $(echo "$r" | field ate_rmse_m) | $prec | $prec1 | $rec | $ghost | $ghost1 | $det | $door | $doorseen | $(tail -1 "$d/em_user.txt") |"
}
rm -f "$OUT/false_static.md"
for row in $SIM_ROWS; do
  IFS=: read -r world seed people <<< "$row"
  sim_row "$world" "$seed" $people
done
echo
echo "False static (gv-eval map --breakdown, m; per door and pass in each row's map_eval.txt):"
echo
echo "| world | seed | people | off every wall | doors seen in one state | doors seen in two states | moved object | people | other |"
echo "|---|---|---|---|---|---|---|---|---|"
cat "$OUT/false_static.md"
