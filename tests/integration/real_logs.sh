#!/usr/bin/env bash
# Every real log in ../shared/data end to end through gv-em-slam on its seed-1 benchmark
# (gv-bench-log = mkbench.py, byte for byte: integration.bench_vs_python), under a 4 GB
# address-space cap: it must finish, and its loop-relation error must stay below the best
# MRPT peer's on that log (doc/benchmarks.md, "MRPT peers", seed 1). A regression
# gate for what the unit tests' small worlds cannot show (82d76c1 ran out of memory on csail
# and freiburg-079 while every unit test passed).
set -euo pipefail
BIN=${GV_BIN:?}; SHARED=${GV_SHARED_DIR:?}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# best MRPT peer (icp-slam classic / grid, rbpf-slam), loop error [m], seed 1
declare -A PEER=([aces]=0.091 [csail]=0.081 [intel]=0.161 [freiburg-079]=0.077 [freiburg-101]=0.038 [seattle]=0.045)
n=0
for gz in "$SHARED"/data/*-corrected.log.gz; do
  log=$(basename "$gz" -corrected.log.gz)
  [ -n "${PEER[$log]:-}" ] || { echo "$log: no peer figure, skipped"; continue; }
  "$BIN/gv-bench-log" "$gz" "$T/$log" --seed 1 --quiet
  # under AddressSanitizer (share/scripts/sanitize.sh) the cap cannot hold: ASan reserves ~16 TB of
  # address space for its shadow memory at start, so the cap is left to the Release run
  cap=4000000; [ -z "${GV_SANITIZED:-}" ] || cap=unlimited
  ( ulimit -v $cap; "$BIN/gv-em-slam" --input "$T/$log.log" --out "$T/$log.out" --quiet ) \
    || fail "$log: gv-em-slam failed (exit $?)"
  score=$("$BIN/gv-eval" traj "$T/$log.out/trajectory.txt" "$T/$log.ref.txt")
  loop=$(sed -n 's/.*rel_loop_t_m=\([0-9.]*\).*/\1/p' <<< "$score")
  [ -n "$loop" ] || fail "$log: no loop error in '$score'"
  echo "$log: loop error $loop m (best MRPT peer ${PEER[$log]} m)"
  awk -v a="$loop" -v b="${PEER[$log]}" 'BEGIN{exit !(a < b)}' || fail "$log: loop error $loop m not below the peer's ${PEER[$log]} m"
  rm -rf "$T/$log.out" "$T/$log.log"
  n=$((n + 1))
done
[ "$n" -gt 0 ] || fail "no log in $SHARED/data"
echo "real_logs: OK ($n logs)"
