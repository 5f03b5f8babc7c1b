#!/usr/bin/env bash
# One MRPT peer on one benchmark log (doc/benchmarks.md, "MRPT peers"; how: doc/benchmarks-history.md, "Peers in the same run").
#
#   bench/em-slam/peer_run.sh SYSTEM BIN_DIR BENCH_PREFIX WORK_DIR RESULT_DIR
#
# SYSTEM: icp-classic | icp-grid (icp-slam, observation-only rawlog) or rbpf (rbpf-slam,
# action/sensory-frame rawlog). BENCH_PREFIX: mkbench.py output (BENCH_PREFIX.log and
# BENCH_PREFIX.ref.txt). The rawlog is made with BIN_DIR/gv-carmen2rawlog --max-range auto
# (ACES's scanner reports "no return" as exactly 50 m under mkbench's declared 81 m; as
# points those readings wreck ICP), the MRPT app runs pinned to one core (`taskset -c
# ${PEER_CORE:-0}`, wall time), its output is turned into
# `t x y theta` by peer_traj.py and scored by evaltraj.py. Writes one line per result
# column into RESULT_DIR/<column>.txt (icp-classic, icp-grid, rbpf-filtered, rbpf-best):
# the evaltraj.py line plus `time_s=` and `scans=`, or `failed: <reason>`. Always exits 0
# unless called wrongly, so a failing peer is a row, not an abort.
# PEER_TIMEOUT (seconds, default 3600) bounds one MRPT run; MRPT_ICP_SLAM / MRPT_RBPF_SLAM
# name other builds of the apps (default: icp-slam, rbpf-slam on PATH).
set -uo pipefail
[ $# -eq 5 ] || { sed -n '2,18p' "$0" >&2; exit 2; }
SYSTEM=$1 BIN=$2 BENCH=$3 WORK=$4 RES=$5
HERE=$(cd "$(dirname "$0")" && pwd)
SHARED=${GV_SHARED_DIR:-$HERE/../../../shared}
case $SYSTEM in
  icp-classic) app=${MRPT_ICP_SLAM:-icp-slam}; ini=icp_classic_tuned.ini; fmt=obs; cols="icp-classic:icp" ;;
  icp-grid) app=${MRPT_ICP_SLAM:-icp-slam}; ini=icp_grid_tuned.ini; fmt=obs; cols="icp-grid:icp" ;;
  rbpf) app=${MRPT_RBPF_SLAM:-rbpf-slam}; ini=rbpf_os_tuned.ini; fmt=sf; cols="rbpf-filtered:rbpf rbpf-best:rbpf-ml" ;;
  *) echo "unknown peer '$SYSTEM' (icp-classic, icp-grid, rbpf)" >&2; exit 2 ;;
esac
mkdir -p "$WORK" "$RES"
scans=$(wc -l < "$BENCH.ref.txt")

# Every result column of this system gets the same failure line.
fail_all() {
  local c
  for c in $cols; do echo "failed: $*" > "$RES/${c%%:*}.txt"; done
  exit 0
}
# The last error-looking line of an MRPT log, shortened for a table cell.
why() { grep -E -i "exception|error|assert|what\(\)|terminate" "$1" | tail -1 | tr -s ' \t|' ' ' | cut -c1-120; }

command -v "$app" > /dev/null || fail_all "$app not installed (apt-get install mrpt-apps)"
name=$(basename "$app")
rawlog="$WORK/bench.$fmt.rawlog"
"$BIN/gv-carmen2rawlog" "$BENCH.log" "$rawlog" --format "$fmt" --max-range auto --quiet 2> "$WORK/convert.err" ||
  fail_all "$(head -1 "$WORK/convert.err")"  # the message names the tool

rm -rf "$WORK/OUT"
t0=$(date +%s.%N)
(cd "$WORK" && timeout "${PEER_TIMEOUT:-3600}" taskset -c "${PEER_CORE:-0}" "$app" "$SHARED/bench/peers/$ini" "$rawlog") \
  > "$WORK/run.log" 2>&1
rc=$?
t1=$(date +%s.%N)
[ $rc -eq 124 ] && fail_all "$name timed out after ${PEER_TIMEOUT:-3600} s"
reason=$(why "$WORK/run.log")
[ $rc -eq 0 ] || fail_all "$name exit $rc${reason:+: $reason}"
secs=$(python3 -c "import sys; print('%.1f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$t0" "$t1")

for c in $cols; do
  col=${c%%:*} kind=${c##*:}
  traj="$WORK/trajectory_$col.txt"
  if ! python3 "$HERE/peer_traj.py" "$kind" "$BENCH.log" "$WORK/OUT" "$traj" 2> "$WORK/extract.err"; then
    echo "failed: $(head -1 "$WORK/extract.err")" > "$RES/$col.txt"; continue
  fi
  if ! r=$(python3 "$SHARED/bench/evaltraj.py" "$traj" "$BENCH.ref.txt" 2>&1); then
    echo "failed: evaltraj: $(echo "$r" | tail -1)" > "$RES/$col.txt"; continue
  fi
  echo "$r time_s=$secs scans=$scans" > "$RES/$col.txt"
done
exit 0
