#!/usr/bin/env bash
# The main job on a built-in default: simulate a dynamic corridor world (walking people,
# swinging doors, a moved object), map it with EM-SLAM from noisy odometry, score it
# against the simulator's ground truth, and say where everything was written.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash share/scripts/install-deps.sh
BUILD=${BUILD_DIR:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j 2 --target gv-sim gv-em-slam gv-eval >/dev/null
OUT=${1:-out/demo}
mkdir -p "$OUT"
"$BUILD/bin/gv-sim" --out "$OUT/sim"
"$BUILD/bin/gv-em-slam" --input "$OUT/sim/sim.log" --out "$OUT/map"
"$BUILD/bin/gv-eval" traj "$OUT/map/trajectory.txt" "$OUT/sim/truth_trajectory.txt" | tee "$OUT/eval_trajectory.txt"
"$BUILD/bin/gv-eval" map "$OUT/map/vectors.txt" "$OUT/sim" --trajectory "$OUT/map/trajectory.txt" --doors "$OUT/map/doors.txt" | tee "$OUT/eval_map.txt"
echo
echo "Outputs in $(cd "$OUT" && pwd):"
echo "  sim/  simulated CARMEN log + ground truth"
echo "  map/  trajectory.txt, vectors.svg (static blue, dynamic red, doors), occupancy.png/.pgm/.yaml, doors.txt, door_states.txt, report.json, map.gvmap"
echo "  eval_trajectory.txt, eval_map.txt  scores against the truth"
