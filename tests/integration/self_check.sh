#!/usr/bin/env bash
# gv-em-slam's self-check (doc/io.md, "gv-em-slam's self-check"): a good run says ok and exits 0; a broken
# input (the first 300 scans of Intel with the odometry of ACES' first 300, bench/self-check/breaklog.py)
# completes its outputs, says suspect with its reasons and exits 3, also under --quiet in two lines.
set -euo pipefail
: "${GV_BIN:?}" "${GV_SOURCE_DIR:?}" "${GV_SHARED_DIR:?}"
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
cd "$W"
fail() { echo "FAIL: $*" >&2; exit 1; }
for log in intel aces; do
  zcat "$GV_SHARED_DIR/data/$log-corrected.log.gz" | awk '/^FLASER/ { n++ } n <= 300' > $log-300.log
  "$GV_BIN/gv-bench-log" $log-300.log $log --quiet
done
python3 "$GV_SOURCE_DIR/bench/self-check/breaklog.py" splice aces.log intel.log spliced.log
check() {  # report.json: the verdict and every self_check field, typed
  python3 - "$1" "$2" <<'PY' || fail "$1: self_check"
import json, sys
r = json.load(open(sys.argv[1]))
s = r["self_check"]
assert s["verdict"] == sys.argv[2], s
assert (s["verdict"] == "ok") == (s["reasons"] == []), s
for k in ("converged",):
    assert isinstance(s[k], bool), k
for k in ("iterations", "registrations", "failed_registrations", "registration_edges", "rejected_edges", "keyframes",
          "sequential_edges", "beams", "beams_through_walls", "beams_through_occupied"):
    assert isinstance(s[k], int) and s[k] >= 0, k
for k in ("failed_share", "rejected_share", "unlinked_share", "dynamic_share", "through_wall_share",
          "through_wall_geometric_share"):
    assert 0 <= s[k] <= 1, k
assert s["normalised_chi2"] is None or s["normalised_chi2"] >= 0
assert s["converged"] == r["converged"] and s["iterations"] == r["iterations_run"] and s["keyframes"] == r["keyframes"]
assert s["failed_registrations"] == sum(it["failed_registrations"] for it in r["iterations"])
assert s["beams_through_occupied"] <= s["beams_through_walls"] <= s["beams"] and s["beams"] > 0
PY
}
# the good run: exit 0, "self-check: ok" last, nothing under --quiet
"$GV_BIN/gv-em-slam" --input intel.log --out good 2> err.txt || fail "good run: exit $?: $(tail -2 err.txt)"
check good/report.json ok
tail -n 2 err.txt | head -n 1 | grep -q "^self-check: EM converged" || fail "good run: no evidence line: $(tail -2 err.txt)"
[ "$(tail -n 1 err.txt)" = "self-check: ok" ] || fail "good run: last line $(tail -1 err.txt)"
"$GV_BIN/gv-em-slam" --input intel.log --out good --quiet 2> err.txt || fail "good run --quiet: exit $?"
[ ! -s err.txt ] || fail "good run --quiet printed: $(cat err.txt)"
# the broken input: exit 3, a complete output set, suspect with its reasons, two lines under --quiet
set +e; "$GV_BIN/gv-em-slam" --input spliced.log --out bad --quiet 2> err.txt; rc=$?; set -e
[ "$rc" -eq 3 ] || fail "spliced log: exit $rc, expected 3: $(cat err.txt)"
check bad/report.json suspect
for f in trajectory.txt map.gvmap vectors.txt occupancy.pgm report.json; do [ -s "bad/$f" ] || fail "spliced log: no $f"; done
[ "$(wc -l < err.txt)" -eq 2 ] || fail "spliced log --quiet: $(wc -l < err.txt) lines: $(cat err.txt)"
head -n 1 err.txt | grep -q "^self-check: EM .* registrations failed; .* edges rejected; normalised chi2 .*; map .* dynamic" \
  || fail "spliced log: evidence line $(head -1 err.txt)"
tail -n 1 err.txt | grep -q "^self-check: suspect (exit status 3): [a-zA-Z]" || fail "spliced log: verdict line $(tail -1 err.txt)"
# the reasons on stderr are report.json's
python3 - bad/report.json "$(tail -n 1 err.txt)" <<'PY' || fail "stderr and report.json disagree"
import json, sys
s = json.load(open(sys.argv[1]))["self_check"]
assert sys.argv[2] == "self-check: suspect (exit status 3): " + "; ".join(s["reasons"]), (sys.argv[2], s["reasons"])
PY
# the odometry of the start (GV_EM_DEBUG_DIR's traj_0.txt) is the log's
mkdir dbg
set +e; GV_EM_DEBUG_DIR=dbg "$GV_BIN/gv-em-slam" --input spliced.log --out bad2 --quiet 2> /dev/null; set -e
python3 "$GV_SOURCE_DIR/bench/self-check/odomtraj.py" spliced.log > odo.txt
python3 - dbg/traj_0.txt odo.txt <<'PY' || fail "traj_0.txt is not the log's odometry"
import sys
a = [list(map(float, l.split()[:4])) for l in open(sys.argv[1]) if not l.startswith('#')]
b = [list(map(float, l.split()[:4])) for l in open(sys.argv[2])]
assert len(a) == len(b) == 300, (len(a), len(b))
assert all(max(abs(x - y) for x, y in zip(p, q)) < 1e-5 for p, q in zip(a, b))
PY
echo "self-check: good run ok (exit 0), spliced log suspect (exit 3)"
