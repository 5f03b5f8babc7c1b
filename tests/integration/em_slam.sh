#!/usr/bin/env bash
# gv-em-slam end to end on a short simulated dynamic corridor: every output file,
# an accuracy bound against the simulator's truth, and one-line errors on bad input.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$GV_BIN/gv-sim" --world long-corridor --seed 2 --scans 400 --out "$tmp/sim" --quiet
# the input under a name with a tab, a quote and a backslash: report.json must still be valid JSON
odd="$tmp/$(printf 'sim\tlog "1"\\a.log')"
cp "$tmp/sim/sim.log" "$odd"
"$GV_BIN/gv-em-slam" --input "$odd" --out "$tmp/out" --quiet
for f in trajectory.txt map.gvmap vectors.txt vectors.svg occupancy.png occupancy.pgm occupancy.yaml doors.txt door_states.txt report.json; do
  [ -s "$tmp/out/$f" ] || { echo "missing or empty: $f"; exit 1; }
done
[ "$(grep -vc '^#' "$tmp/out/door_states.txt")" -eq "$(grep -vc '^#' "$tmp/out/doors.txt")" ] || { echo "door_states.txt: one line per door of doors.txt"; exit 1; }
[ "$(grep -vc '^#' "$tmp/out/trajectory.txt")" -eq 400 ] || { echo "trajectory must have one pose per scan"; exit 1; }
grep -q '"converged": true' "$tmp/out/report.json" || { echo "EM did not converge"; exit 1; }
# the phase timings: the wipe product and the classification within the E-step, merges and doors within the final map
python3 - "$tmp/out/report.json" <<'PY' || { echo "report.json: phase timings missing or inconsistent"; exit 1; }
import json, sys
r = json.load(open(sys.argv[1]))
assert r["input"].endswith('sim\tlog "1"\\a.log'), r["input"]
# what made the run: the versions (as --version) and the initial trajectory (none: odometry)
assert r["init"] is None, r["init"]
assert set(r["version"]) == {"gridvector", "git", "mrpt"} and all(r["version"].values()), r["version"]
assert r["keyframes"] > 0
# the self-check (doc/io.md): a good run of a busy world (most of its length dynamic, converged) is ok
assert r["self_check"]["verdict"] == "ok" and r["self_check"]["reasons"] == [], r["self_check"]
assert r["self_check"]["converged"] == r["converged"]
for it in r["iterations"]:
    assert 0 <= it["wipe_seconds"] and 0 <= it["classify_seconds"]
    assert it["wipe_seconds"] + it["classify_seconds"] <= it["e_seconds"] + 1e-6
assert r["iterations"][0]["wipe_seconds"] > 0
# Sec. 5.3 (doors.during_em): per iteration the doors known and the static children kept out
for it in r["iterations"]:
    for k in ("doors", "doors_found", "door_vectors_excluded", "door_vectors_cut"):
        assert isinstance(it[k], int) and it[k] >= 0, k
    assert 0 <= it["door_seconds"] <= it["e_seconds"] + 1e-6
    assert it["doors_found"] <= it["doors"]
s = r["seconds"]
assert 0 <= s["final_merge"] and 0 <= s["doors"] and s["final_merge"] + s["doors"] <= s["final_map"] + 1e-6
PY
# the E-step's wipe product at the final trajectory: vector by vector (WipeProduct) = scan by scan (ScanWipe), bit for bit
"$GV_BIN/gv-bench-wipe" "$tmp/sim/sim.log" "$tmp/out/trajectory.txt" --repeat 1 > "$tmp/wipe.txt" \
  || { cat "$tmp/wipe.txt"; echo "gv-bench-wipe: the two products differ"; exit 1; }
grep -q "cells differing: 0 (identical)" "$tmp/wipe.txt" || { cat "$tmp/wipe.txt"; exit 1; }
head -n 10 "$tmp/out/trajectory.txt" > "$tmp/short.txt"
if "$GV_BIN/gv-bench-wipe" "$tmp/sim/sim.log" "$tmp/short.txt" 2> "$tmp/wipe.err"; then echo "gv-bench-wipe accepted a short trajectory"; exit 1; fi
grep -q "poses for 400 scans" "$tmp/wipe.err" || { cat "$tmp/wipe.err"; exit 1; }
awk '!/^#/ && $6 != "static" && $6 != "dynamic" { bad = 1 } END { exit bad }' "$tmp/out/vectors.txt" \
  || { echo "vectors.txt: state column must be static|dynamic"; exit 1; }
ate=$("$GV_BIN/gv-eval" traj "$tmp/out/trajectory.txt" "$tmp/sim/truth_trajectory.txt" | sed -n 's/.*ate_rmse_m=\([0-9.]*\).*/\1/p')
echo "ATE $ate m"
awk -v a="$ate" 'BEGIN { exit !(a <= 0.10) }' || { echo "ATE $ate m > 0.10 m"; exit 1; }
# --init: start from a prior trajectory (here the truth, e.g. gv-graphslam's in practice)
"$GV_BIN/gv-em-slam" --input "$tmp/sim/sim.log" --out "$tmp/init" --init "$tmp/sim/truth_trajectory.txt" --quiet
ate2=$("$GV_BIN/gv-eval" traj "$tmp/init/trajectory.txt" "$tmp/sim/truth_trajectory.txt" | sed -n 's/.*ate_rmse_m=\([0-9.]*\).*/\1/p')
echo "ATE from --init truth: $ate2 m"
awk -v a="$ate2" 'BEGIN { exit !(a <= 0.10) }' || { echo "ATE with --init $ate2 m > 0.10 m"; exit 1; }
# the debugging aid: GV_EM_DEBUG_DIR gets traj_, edges_ and static_<iteration>.txt (traj_0.txt: the odometry) and
# changes nothing;
# bench/em-slam/edge_errors.py scores the edges against a reference (here the truth)
mkdir "$tmp/dbg"
GV_EM_DEBUG_DIR="$tmp/dbg" "$GV_BIN/gv-em-slam" --input "$tmp/sim/sim.log" --out "$tmp/dbgout" --quiet
cmp -s "$tmp/dbgout/trajectory.txt" "$tmp/out/trajectory.txt" || { echo "GV_EM_DEBUG_DIR changed the trajectory"; exit 1; }
for f in traj_0.txt traj_1.txt edges_1.txt static_1.txt; do [ -s "$tmp/dbg/$f" ] || { echo "GV_EM_DEBUG_DIR: missing $f"; exit 1; }; done
[ "$(wc -l < "$tmp/dbg/static_1.txt")" -gt 0 ] || { echo "static_1.txt empty"; exit 1; }
python3 "$GV_SOURCE_DIR/bench/em-slam/edge_errors.py" "$tmp/dbg/edges_1.txt" "$tmp/sim/truth_trajectory.txt" > "$tmp/edges.md" \
  || { echo "edge_errors.py failed"; exit 1; }
grep -q "^sequential: [1-9][0-9]* edges" "$tmp/edges.md" || { cat "$tmp/edges.md"; echo "edge_errors.py: no sequential edges"; exit 1; }
printf '# t x y theta\n1.0 0 0 0\n' > "$tmp/far.txt"
if "$GV_BIN/gv-em-slam" --input "$tmp/sim/sim.log" --out "$tmp/bad" --init "$tmp/far.txt" 2> "$tmp/err.txt"; then
  echo "--init without matching timestamps accepted"; exit 1; fi
grep -q "far.txt: no pose within" "$tmp/err.txt" || { cat "$tmp/err.txt"; exit 1; }
# --online: the same files from OnlineEmSlam, the causal trajectory, the per-scan latency; --refine after it
"$GV_BIN/gv-em-slam" --input "$tmp/sim/sim.log" --out "$tmp/online" --online --quiet
for f in trajectory.txt trajectory_online.txt map.gvmap vectors.txt occupancy.png doors.txt report.json; do
  [ -s "$tmp/online/$f" ] || { echo "--online: missing or empty: $f"; exit 1; }
done
[ "$(grep -vc '^#' "$tmp/online/trajectory_online.txt")" -eq 400 ] || { echo "trajectory_online.txt: one pose per scan"; exit 1; }
python3 - "$tmp/online/report.json" <<'PY' || { echo "report.json: online figures missing"; exit 1; }
import json, sys
o = json.load(open(sys.argv[1]))["online"]
assert 0 < o["latency_ms"]["median"] <= o["latency_ms"]["p99"] <= o["latency_ms"]["max"], o["latency_ms"]
assert 0 < o["cpu_ms"]["median"] <= o["cpu_ms"]["p99"], o["cpu_ms"]
assert o["keyframes"] > 0 and o["edges"]["sequential"] > 0 and o["refined"] is False, o
# the doors and the final merges run inside the final map's time online: not timed apart, so null, not 0
s = json.load(open(sys.argv[1]))["seconds"]
assert s["doors"] is None and s["final_merge"] is None and s["final_map"] > 0, s
PY
for d in online; do
  a=$("$GV_BIN/gv-eval" traj "$tmp/$d/trajectory.txt" "$tmp/sim/truth_trajectory.txt" | sed -n 's/.*ate_rmse_m=\([0-9.]*\).*/\1/p')
  echo "--online: ATE $a m"
  awk -v a="$a" 'BEGIN { exit !(a <= 0.10) }' || { echo "--online: ATE $a m > 0.10 m"; exit 1; }
done
"$GV_BIN/gv-em-slam" --input "$tmp/sim/sim.log" --out "$tmp/refine" --online --refine --quiet
grep -q '"refined": true' "$tmp/refine/report.json" || { echo "--refine: not in report.json"; exit 1; }
if "$GV_BIN/gv-em-slam" --input "$tmp/sim/sim.log" --out "$tmp/bad" --refine 2> "$tmp/err.txt"; then echo "--refine without --online accepted"; exit 1; fi
grep -q "needs --online" "$tmp/err.txt" || { cat "$tmp/err.txt"; exit 1; }
# bad input: one line "file: problem", non-zero exit, no crash
printf 'FLASER 3 1.0 oops\n' > "$tmp/bad.log"
if "$GV_BIN/gv-em-slam" --input "$tmp/bad.log" --out "$tmp/bad" 2> "$tmp/err.txt"; then echo "bad log accepted"; exit 1; fi
[ "$(wc -l < "$tmp/err.txt")" -eq 1 ] && grep -q "bad.log" "$tmp/err.txt" || { cat "$tmp/err.txt"; exit 1; }
if "$GV_BIN/gv-em-slam" --input "$tmp/missing.log" --out "$tmp/bad" 2> "$tmp/err.txt"; then echo "missing log accepted"; exit 1; fi
[ "$(wc -l < "$tmp/err.txt")" -eq 1 ] || { cat "$tmp/err.txt"; exit 1; }
if "$GV_BIN/gv-em-slam" --input "$tmp/sim/sim.log" 2> /dev/null; then echo "missing --out accepted"; exit 1; fi
echo "gv-em-slam end to end OK"
