#!/usr/bin/env bash
# gv-sim's default run, determinism per seed, option handling, and gv-eval on its output.
set -euo pipefail
BIN=${GV_BIN:?}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN/gv-sim" --out "$T/a" > "$T/out.txt"
grep -q "world corridor-loop, seed 1" "$T/out.txt" || fail "summary: $(cat "$T/out.txt")"
grep -q "wrote $T/a/sim.log" "$T/out.txt" || fail "does not say where it wrote"
for f in sim.log truth_trajectory.txt truth_labels.txt truth_walls.txt truth_seen_walls.txt truth_doors.txt truth_dynamic.txt odometry.txt sim_info.txt; do
  [ -s "$T/a/$f" ] || fail "missing $f"
done
scans=$(grep -c '^FLASER' "$T/a/sim.log")
[ "$scans" -gt 1000 ] || fail "only $scans scans"
[ "$(grep -vc '^#' "$T/a/truth_labels.txt")" -eq "$scans" ] || fail "label lines != scans"
# the log's poses are odometry, not the truth
head -2 "$T/a/truth_trajectory.txt" | tail -1 | grep -q "^1100000000.000000 1.200000 6.200000 0.000000$" || fail "truth start"
grep -m1 '^FLASER' "$T/a/sim.log" | grep -q " 0.000000 0.000000 0.000000 0.000000 0.000000 0.000000 1100000000.000000 gv-sim " || fail "odometry start"

# deterministic per seed
"$BIN/gv-sim" --out "$T/b" --quiet
for f in sim.log truth_labels.txt truth_dynamic.txt truth_seen_walls.txt; do cmp -s "$T/a/$f" "$T/b/$f" || fail "$f differs between runs"; done
"$BIN/gv-sim" --out "$T/c" --seed 2 --quiet
cmp -s "$T/a/sim.log" "$T/c/sim.log" && fail "seed 2 gives the same log"

# options: ini section, flags, exact scan count, other worlds, 181 beams
printf '[gv_sim]\nworld = office\npeople = 6\nbeams = 181\n' > "$T/sim.ini"
"$BIN/gv-sim" --out "$T/d" --config "$T/sim.ini" --scans 2000 --quiet
[ "$(grep -c '^FLASER 181 ' "$T/d/sim.log")" -eq 2000 ] || fail "--scans 2000 with 181 beams"
grep -q "^people 6$" "$T/d/sim_info.txt" || fail "ini people"

# doors used all day (a swing every 30-60 s) and pausers standing for minutes: more swings than the default run's
"$BIN/gv-sim" --out "$T/f" --door-swing-period 30 --pause-s 120 --quiet
few=$(awk '$1 == "door_swings" { print $2 }' "$T/a/sim_info.txt"); many=$(awk '$1 == "door_swings" { print $2 }' "$T/f/sim_info.txt")
[ "$many" -ge $((3 * few)) ] || fail "--door-swing-period 30: $many swings against $few by default"
grep -q "^pause_s 120$" "$T/f/sim_info.txt" || fail "--pause-s not in sim_info.txt"

# bad options: one line, exit 2; unwritable output: exit 1
set +e
"$BIN/gv-sim" --out "$T/e" --peeple 3 2> "$T/err.txt"; rc=$?
[ $rc -eq 2 ] && [ "$(cat "$T/err.txt")" = "gv-sim: unknown option --peeple (see --help)" ] || fail "unknown option: $rc $(cat "$T/err.txt")"
"$BIN/gv-sim" --out "$T/e" --world mars 2> "$T/err.txt"; rc=$?
[ $rc -eq 2 ] && [ "$(cat "$T/err.txt")" = "gv-sim: --world must be one of corridor-loop, office, long-corridor, got 'mars' (see --help)" ] || fail "unknown world: $rc $(cat "$T/err.txt")"
"$BIN/gv-sim" --out "$T/e" --beams many 2> "$T/err.txt"; rc=$?
[ $rc -eq 2 ] || fail "bad number: $rc"
printf '[gv_sim]\nwrold = office\n' > "$T/bad.ini"
"$BIN/gv-sim" --out "$T/e" --config "$T/bad.ini" 2> "$T/err.txt"; rc=$?
[ $rc -eq 1 ] && [ "$(cat "$T/err.txt")" = "gv-sim: $T/bad.ini: unknown key 'wrold' in section [gv_sim]" ] || fail "ini key: $rc $(cat "$T/err.txt")"
"$BIN/gv-sim" --out /proc/gv-sim-cannot-write 2> "$T/err.txt"; rc=$?
set -e
[ $rc -eq 1 ] && grep -q "^gv-sim: /proc/gv-sim-cannot-write: cannot write" "$T/err.txt" || fail "unwritable: $rc $(cat "$T/err.txt")"

# gv-eval: the odometry in the log and in odometry.txt score the same against the truth
a=$("$BIN/gv-eval" traj "$T/a/odometry.txt" "$T/a/truth_trajectory.txt")
b=$("$BIN/gv-eval" traj "$T/a/sim.log" "$T/a/truth_trajectory.txt")
[ "$a" = "$b" ] || fail "log vs odometry.txt: $a / $b"
"$BIN/gv-eval" traj "$T/a/truth_trajectory.txt" "$T/a/truth_trajectory.txt" | grep -q "ate_rmse_m=0.0000 rel_local_t_m=0.0000" || fail "identity not 0"
# a perfect map: the true walls as static vectors, the dynamic hits as dynamic vectors
awk '!/^#/{print $1, $2, $3, $4, 1.0}' "$T/a/truth_walls.txt" > "$T/perfect.txt"
awk '$1=="hit"{print $5, $6, $7, $8, 0.0, "dynamic"}' "$T/a/truth_dynamic.txt" >> "$T/perfect.txt"
awk '!/^#/{print $1, $2, $3}' "$T/a/truth_doors.txt" > "$T/doors.txt"
json=$("$BIN/gv-eval" map "$T/perfect.txt" "$T/a" --doors "$T/doors.txt" --json)
# conditions on the JSON object j on stdin: each must hold
jsonhas() { python3 -c 'import json, sys; j = json.load(sys.stdin); sys.exit(any(eval(c, {"j": j}) != True for c in sys.argv[1:]))' "$@"; }
echo "$json" | jsonhas 'abs(j["static_precision"] - 1) < 1e-6' 'abs(j["static_recall"] - 1) < 1e-6' 'abs(j["dynamic_detection"] - 1) < 1e-6' 'abs(j["door_recall"] - 1) < 1e-6' \
  || fail "precision, recall, detection, doors: $json"
# --breakdown: nothing off the walls in the perfect map; every closed leaf added as static is
# false static, attributed to the doors (0.7 m each: 0.1 m at either end lies within the walls' tolerance)
json=$("$BIN/gv-eval" map "$T/perfect.txt" "$T/a" --json --breakdown)
echo "$json" | jsonhas 'list(j["false_static"])[0] == "false_static_m"' 'abs(j["false_static"]["false_static_m"]) < 1e-6' || fail "breakdown, perfect map: $json"
awk '!/^#/{print $1, $2, $1 + $3 * cos($4), $2 + $3 * sin($4), 1.0}' "$T/a/truth_doors.txt" > "$T/leaves.txt"
cat "$T/perfect.txt" "$T/leaves.txt" > "$T/closed.txt"
text=$("$BIN/gv-eval" map "$T/closed.txt" "$T/a" --breakdown)
doors=$(grep -c . "$T/leaves.txt")
line=$(echo "$text" | grep '^false static:')
python3 - "$doors" "$line" <<'PY' || fail "breakdown, closed leaves: $line"
import re, sys
n = int(sys.argv[1]); v = [float(x) for x in re.findall(r"[0-9]+\.[0-9]+", sys.argv[2])]
total, one, two, obj, people, other = v
assert abs(total - 0.7 * n) < 0.02 * n and abs(one + two - total) < 0.011 and obj == people == other == 0, v
PY
[ "$(echo "$text" | grep -c '^door [0-9]*: ')" = "$doors" ] || fail "breakdown: a line per door: $text"
# without truth_trajectory.txt (not needed by the map metrics) the breakdown's times are absolute
mkdir "$T/notraj" && cp "$T/a"/truth_walls.txt "$T/a"/truth_seen_walls.txt "$T/a"/truth_doors.txt "$T/a"/truth_dynamic.txt "$T/notraj/"
text2=$("$BIN/gv-eval" map "$T/closed.txt" "$T/notraj" --breakdown) || fail "breakdown without truth_trajectory.txt"
[ "$(echo "$text2" | grep '^false static:')" = "$line" ] || fail "breakdown without truth_trajectory.txt: $text2"
echo "$text2" | grep -q '^door [0-9]*: .* passes: \[1100000' || fail "breakdown without truth_trajectory.txt: absolute times: $text2"
# --trajectory: the map and the trajectory in another frame, the first 60 poses at one time (as csail's
# six-digit stamps): the poses are paired as gv-eval traj pairs them (by order), so the map comes back exactly
mkdir "$T/tied" && cp "$T/a"/truth_*.txt "$T/tied/"
awk 'NR <= 61 && !/^#/ { $1 = "1100000000.000000" } { print }' "$T/a/truth_trajectory.txt" > "$T/tied/truth_trajectory.txt"
move='function X(x, y) { return cos(0.6) * x - sin(0.6) * y + 4 } function Y(x, y) { return sin(0.6) * x + cos(0.6) * y - 2 }'
awk "$move"' !/^#/ { print $1, X($2, $3), Y($2, $3), $4 + 0.6 }' "$T/tied/truth_trajectory.txt" > "$T/tied_est.txt"
awk "$move"' !/^#/ { $0 = X($1, $2) " " Y($1, $2) " " X($3, $4) " " Y($3, $4) " " $5 " " $6; print }' "$T/perfect.txt" > "$T/perfect_moved.txt"
json=$("$BIN/gv-eval" map "$T/perfect_moved.txt" "$T/tied" --trajectory "$T/tied_est.txt" --json 2> "$T/err.txt") || fail "tied --trajectory: $(cat "$T/err.txt")"
echo "$json" | jsonhas 'abs(j["static_precision"] - 1) < 1e-6' || fail "tied --trajectory: precision: $json"
grep -q "60 estimate poses share t = 1100000000.000000 and differ: matched by order" "$T/err.txt" || fail "tied --trajectory: $(cat "$T/err.txt")"
set +e
printf '0 0 1 1\n' > "$T/bad.txt"
"$BIN/gv-eval" map "$T/bad.txt" "$T/a" 2> "$T/err.txt"; rc=$?
set -e
[ $rc -eq 1 ] && [ "$(cat "$T/err.txt")" = "gv-eval: $T/bad.txt:1: expected 'x1 y1 x2 y2 p_static [static|dynamic]', found 4 fields" ] || fail "bad vectors: $(cat "$T/err.txt")"
echo "gv_sim_eval: OK"
