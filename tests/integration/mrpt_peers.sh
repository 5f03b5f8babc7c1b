#!/usr/bin/env bash
# The MRPT peer steps of bench/em-slam: peer_traj.py reads MRPT 2.5's output layouts
# (icp-slam laser rows, rbpf-slam filtered rows, best particle expanded to every scan) and
# peer_run.sh turns every failure into a "failed: <reason>" result instead of aborting;
# one real icp-slam run on freiburg-101 goes through the whole chain.
set -euo pipefail
BIN=${GV_BIN:?}; SRC=${GV_SOURCE_DIR:?}; SHARED=${GV_SHARED_DIR:?}
B="$SRC/bench/em-slam"
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# A 3-scan benchmark log: FLASER n r1..rn x y th odo_x odo_y odo_th ts host lts.
for i in 0 1 2; do echo "FLASER 2 1.0 2.0 0 0 0 0 0 0 10$i.5 bench 10$i.5"; done > "$T/b.log"
mkdir -p "$T/icp" "$T/rbpf"
# icp-slam: step x y yaw, odometry and laser rows alternate.
printf '0 9 9 9\n1 0 0 0\n2 9 9 9\n3 1 0 0.1\n4 9 9 9\n5 2 0 0.2\n' > "$T/icp/log_estimated_path.txt"
python3 "$B/peer_traj.py" icp "$T/b.log" "$T/icp" "$T/icp.txt"
[ "$(sed -n 3p "$T/icp.txt")" = "102.5 2.000000 0.000000 0.200000" ] || fail "icp rows: $(cat "$T/icp.txt")"
# rbpf-slam: step x y z yaw pitch roll timestamp; best path = start + one pose per update
# (updates at steps 0 and 2); step 1 follows the odometry from step 0.
printf '%% h\n0 0 0 0 0 0 0 100.5\n1 1 0 0 0 0 0 101.5\n2 2 0 0 1.5 0 0 102.5\n' > "$T/rbpf/log_estimated_path.txt"
printf '%% h\n0 30 1 1\n1 30 1 0\n2 30 2 1\n' > "$T/rbpf/log_times.txt"
printf '%% h\n0\t0\t0\t0\t0\t0\t0\n1\t0.5\t0\t0\t0\t0\t0\n2\t1\t0\t0\t0\t0\t0\n' > "$T/rbpf/log_odometry_path.txt"
printf '0 0 0\n0 0 1.5707963\n3 4 0\n' > "$T/rbpf/most_likely_path.txt"
python3 "$B/peer_traj.py" rbpf "$T/b.log" "$T/rbpf" "$T/f.txt"
[ "$(sed -n 3p "$T/f.txt")" = "102.5 2.000000 0.000000 1.500000" ] || fail "rbpf rows: $(cat "$T/f.txt")"
python3 "$B/peer_traj.py" rbpf-ml "$T/b.log" "$T/rbpf" "$T/ml.txt"
[ "$(sed -n 2p "$T/ml.txt")" = "101.5 0.000000 0.500000 1.570796" ] || fail "best path between updates: $(cat "$T/ml.txt")"
[ "$(sed -n 3p "$T/ml.txt")" = "102.5 3.000000 4.000000 0.000000" ] || fail "best path at update: $(cat "$T/ml.txt")"
# Shape mismatches are one line and exit 1.
printf '0 0 0\n' > "$T/rbpf/most_likely_path.txt"
if python3 "$B/peer_traj.py" rbpf-ml "$T/b.log" "$T/rbpf" "$T/x.txt" 2> "$T/err"; then fail "short best path accepted"; fi
grep -q "most_likely_path.txt has 1 poses for 2 filter updates" "$T/err" || fail "message: $(cat "$T/err")"
printf '0 0 0 0\n' > "$T/icp/log_estimated_path.txt"
if python3 "$B/peer_traj.py" icp "$T/b.log" "$T/icp" "$T/x.txt" 2> "$T/err"; then fail "short icp path accepted"; fi
grep -q "1 rows, expected 6" "$T/err" || fail "message: $(cat "$T/err")"

# peer_run.sh: failures become result lines, exit 0.
python3 "$SHARED/bench/mkbench.py" "$SHARED/data/freiburg-101-corrected.log.gz" "$T/fr101" --seed 1 > /dev/null
MRPT_RBPF_SLAM=/nonexistent/rbpf-slam bash "$B/peer_run.sh" rbpf "$BIN" "$T/fr101" "$T/w0" "$T/r0" || fail "missing app aborted"
grep -q "^failed: /nonexistent/rbpf-slam not installed" "$T/r0/rbpf-best.txt" || fail "missing app: $(cat "$T/r0/rbpf-best.txt")"
grep -q "^failed: /nonexistent/rbpf-slam not installed" "$T/r0/rbpf-filtered.txt" || fail "missing app, filtered column"
MRPT_ICP_SLAM=false bash "$B/peer_run.sh" icp-classic "$BIN" "$T/fr101" "$T/w3" "$T/r3" || fail "failing app aborted"
[ "$(cat "$T/r3/icp-classic.txt")" = "failed: false exit 1" ] || fail "failing app: $(cat "$T/r3/icp-classic.txt")"
cp "$T/fr101.ref.txt" "$T/bad.ref.txt"; printf 'FLASER 2 1 nan 0 0 0 0 0 0 1 h 1\n' > "$T/bad.log"
bash "$B/peer_run.sh" icp-grid "$BIN" "$T/bad" "$T/w1" "$T/r1" || fail "bad log aborted"
grep -q "^failed: gv-carmen2rawlog: .*not a finite number" "$T/r1/icp-grid.txt" || fail "bad log: $(cat "$T/r1/icp-grid.txt")"

if command -v icp-slam > /dev/null; then
  bash "$B/peer_run.sh" icp-classic "$BIN" "$T/fr101" "$T/w2" "$T/r2"
  r=$(cat "$T/r2/icp-classic.txt")
  [[ $r == n=292\ * && $r == *time_s=*scans=292 ]] || fail "icp-classic on freiburg-101: $r"
  loop=$(echo "$r" | sed -n 's/.*rel_loop_t_m=\([0-9.]*\).*/\1/p')
  python3 -c "import sys; sys.exit(not 0 < float(sys.argv[1]) < 1.0)" "$loop" || fail "icp-classic loop error $loop"
else
  echo "icp-slam not installed: real peer run skipped"
fi
echo "mrpt_peers: OK"
