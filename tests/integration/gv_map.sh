#!/usr/bin/env bash
# gv-map end to end on a small simulated CARMEN log (a room, a robot turning in
# it, FLASER lines with corrected poses): every output is written and sane, a
# trajectory file gives the same map, and errors are one line with a non-zero exit.
set -euo pipefail
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
log="$work/room.log"
# 181 beams over 180 deg from poses inside the 8 x 6 m room [-4,4] x [-3,3]
awk 'BEGIN {
  pi = atan2(0, -1);
  for (t = 0; t < 40; t++) {
    x = -2 + 0.1 * t; y = 0.3 * sin(t / 5); th = 0.15 * t;
    line = "FLASER 181";
    for (i = 0; i < 181; i++) {
      a = th - pi / 2 + pi * i / 180; dx = cos(a); dy = sin(a); r = 1e9;
      if (dx > 1e-9) r = (4 - x) / dx < r ? (4 - x) / dx : r;
      if (dx < -1e-9) r = (-4 - x) / dx < r ? (-4 - x) / dx : r;
      if (dy > 1e-9) r = (3 - y) / dy < r ? (3 - y) / dy : r;
      if (dy < -1e-9) r = (-3 - y) / dy < r ? (-3 - y) / dy : r;
      line = line sprintf(" %.3f", r);
    }
    ts = 1000 + 0.2 * t;
    printf "%s %.4f %.4f %.4f %.4f %.4f %.4f %.6f sim %.6f\n", line, x, y, th, x, y, th, ts, ts;
    printf "%.6f %.4f %.4f %.4f\n", ts, x, y, th > "/dev/stderr";
  }
}' > "$log" 2> "$work/traj.txt"

"$GV_BIN/gv-map" --input "$log" --poses log --out "$work/out" --quiet
for f in map.gvmap vectors.txt vectors.svg occupancy.png occupancy.pgm occupancy.yaml map.3Dscene memory.json; do
  [ -s "$work/out/$f" ] || { echo "missing $f"; exit 1; }
done
# the room's four walls, ~28 m of vectors, merged into few vectors
n=$(grep -vc '^#' "$work/out/vectors.txt")
len=$(awk '!/^#/ { s += sqrt(($3-$1)^2 + ($4-$2)^2) } END { printf "%d", s }' "$work/out/vectors.txt")
[ "$n" -ge 4 ] && [ "$n" -le 10 ] || { echo "unexpected vector count $n"; exit 1; }
[ "$len" -ge 25 ] && [ "$len" -le 30 ] || { echo "unexpected total length $len"; exit 1; }
head -c 2 "$work/out/occupancy.pgm" | grep -q P5
grep -q '^image: occupancy.pgm$' "$work/out/occupancy.yaml"
grep -q '"n_g"' "$work/out/memory.json"
ls -A "$work/out" | grep -q '\.tmp' && { echo "temporary file left"; exit 1; }
# the saved map loads in MRPT tools
if [ -x "$GV_BIN/gv-map-info" ]; then "$GV_BIN/gv-map-info" "$work/out/map.gvmap" > /dev/null; fi

# poses from a trajectory file: same vectors
"$GV_BIN/gv-map" --input "$log" --poses "$work/traj.txt" --out "$work/out2" --quiet
cmp <(grep -v '^#' "$work/out/vectors.txt") <(grep -v '^#' "$work/out2/vectors.txt")

# errors: one line "file: problem", non-zero exit
if "$GV_BIN/gv-map" --input "$work/none.log" --poses log --out "$work/o3" 2> "$work/err"; then exit 1; fi
[ "$(wc -l < "$work/err")" -eq 1 ] && grep -q "none.log" "$work/err"
if "$GV_BIN/gv-map" --input "$log" --poses log --out /proc/forbidden 2> "$work/err"; then exit 1; fi
[ "$(wc -l < "$work/err")" -eq 1 ] && grep -q "/proc/forbidden" "$work/err"
if "$GV_BIN/gv-map" --input "$log" --out "$work/o4" 2> "$work/err"; then exit 1; fi
grep -q -- "--poses" "$work/err"
echo "gv-map ok: $n vectors, $len m"
