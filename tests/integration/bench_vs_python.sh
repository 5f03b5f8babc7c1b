#!/usr/bin/env bash
# gv-bench-log and gv-eval against the reference Python tools in ../shared/bench:
# benchmark logs byte for byte, trajectory scores to 1e-3.
set -euo pipefail
BIN=${GV_BIN:?}; SHARED=${GV_SHARED_DIR:?}
if ! command -v python3 >/dev/null; then echo "python3 not found: skipped"; exit 0; fi
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

for log in intel aces; do
  in="$SHARED/data/$log-corrected.log.gz"
  "$BIN/gv-bench-log" "$in" "$T/ours" --seed 2 --quiet
  python3 "$SHARED/bench/mkbench.py" "$in" "$T/theirs" --seed 2
  cmp "$T/ours.log" "$T/theirs.log" || fail "$log: benchmark logs differ"
  cmp "$T/ours.ref.txt" "$T/theirs.ref.txt" || fail "$log: references differ"
  # estimates: the benchmark's odometry, and every other pose of it shifted by 30 ms
  awk '$1=="FLASER"{n=$2; print $(n+9), $(n+3), $(n+4), $(n+5)}' "$T/ours.log" > "$T/odo.txt"
  awk 'NR%2==0{printf "%.6f %s %s %s\n", $1+0.03, $2, $3, $4}' "$T/odo.txt" > "$T/half.txt"
  for est in odo half; do
    py=$(python3 "$SHARED/bench/evaltraj.py" "$T/$est.txt" "$T/ours.ref.txt")
    gv=$("$BIN/gv-eval" traj "$T/$est.txt" "$T/ours.ref.txt")
    python3 - "$py" "$gv" <<'PY' || fail "$log/$est: gv-eval disagrees: $gv vs $py"
import sys
a = dict(kv.split('=') for kv in sys.argv[1].split())
b = dict(kv.split('=') for kv in sys.argv[2].split())
assert a.keys() == b.keys(), (a, b)
for k in a:
    assert abs(float(a[k]) - float(b[k])) <= 1e-3, (k, a[k], b[k])
PY
  done
done
echo "bench_vs_python: OK"
