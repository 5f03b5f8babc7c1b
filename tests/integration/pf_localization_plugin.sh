#!/usr/bin/env bash
# Plug-in proof: MRPT's own, unmodified pf-localization localises a robot on a CGridVectorMap
# when libgridvector.so is preloaded. gv-sim world (office) -> map of seed 1 at the true poses
# (gv-map --simplemap) -> seed 2's run (other people, doors, laser and odometry noise) localised
# by pf-localization -> its path scored against the truth with gv-eval traj --absolute.
set -euo pipefail
command -v pf-localization >/dev/null || { echo "SKIP: pf-localization not installed (mrpt-apps)"; exit 0; }
INI="$GV_SOURCE_DIR/share/gridvector/pf-localization-gridvector.ini"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
"$GV_BIN/gv-sim" --world office --seed 1 --laps 1 --out map-run --quiet
"$GV_BIN/gv-sim" --world office --seed 2 --scans 400 --out loc-run --quiet
"$GV_BIN/gv-map" --input map-run/sim.log --poses map-run/truth_trajectory.txt --out map --simplemap --quiet
"$GV_BIN/gv-carmen2rawlog" loc-run/sim.log loc.rawlog --quiet
# The initial particles: uniform within +-1 m and +-20 deg of the true start.
read -r x0 y0 < <(awk '!/^#/ { print $2, $3; exit }' loc-run/truth_trajectory.txt)
box() { awk -v v="$1" -v d="$2" 'BEGIN { printf "%.3f", v + d }'; }
sed -e "s#^map_file = .*#map_file = map/map.simplemap#" -e "s#^rawlog_file = .*#rawlog_file = loc.rawlog#" \
	-e "s/^particles_count = .*/particles_count = 300/" \
	-e "s/^init_PDF_min_x = .*/init_PDF_min_x = $(box "$x0" -1)/" -e "s/^init_PDF_max_x = .*/init_PDF_max_x = $(box "$x0" 1)/" \
	-e "s/^init_PDF_min_y = .*/init_PDF_min_y = $(box "$y0" -1)/" -e "s/^init_PDF_max_y = .*/init_PDF_max_y = $(box "$y0" 1)/" \
	"$INI" > pf.ini
# GV_SANITIZER_PRELOAD (share/scripts/sanitize.sh): the ASan/UBSan runtimes, which must come first
LD_PRELOAD="${GV_SANITIZER_PRELOAD:+$GV_SANITIZER_PRELOAD:}$GV_LIB" pf-localization pf.ini > pf.log 2>&1 </dev/null ||
	{ grep -v '^\[' pf.log | tail -20; exit 1; }
# The map pf-localization built (it saves it under LOG_PF_GV_000_0000300/map_*) is a CGridVectorMap.
grep -q "C++ Class: 'mrpt::maps::CGridVectorMap'" pf.log && ls LOG_PF_GV_*/map_mrpt__maps__CGridVectorMap_00_vectors.txt >/dev/null ||
	{ echo "pf-localization did not build a gridVectorMap"; exit 1; }
# pf-localization logs the particles' mean after every scan ("PDF estimation: (x,y,phi_deg)"): the
# i-th line is the i-th scan's pose; its time is the scan's (loc-run/odometry.txt, one line per scan).
awk 'FNR == NR { if (!/^#/) t[n++] = $1; next }
	/PDF estimation: \(/ { s = $0; sub(/.*PDF estimation: \(/, "", s); sub(/deg\).*/, "", s); split(s, a, ",")
		printf "%.6f %s %s %.6f\n", t[m++], a[1], a[2], a[3] * 3.14159265358979 / 180 }' loc-run/odometry.txt pf.log > estimated.txt
scans=$(grep -vc '^#' loc-run/odometry.txt)
[ "$(wc -l < estimated.txt)" -eq "$scans" ] || { echo "$(wc -l < estimated.txt) estimates for $scans scans"; exit 1; }
"$GV_BIN/gv-eval" traj estimated.txt loc-run/truth_trajectory.txt --absolute --json | tee eval.json
# Bounds from measured runs (doc/benchmarks.md, "pf-localization on a grid-vector map"): 300-1000
# particles gave abs RMSE 0.03-0.04 m, final error < 0.01 m, every error after convergence < 0.15 m;
# a filter that loses the robot is off by metres. The bounds leave 3-5x margin for the random seed.
python3 - eval.json <<'EOF'
import json, sys
m = json.load(open(sys.argv[1]))
bad = []
if not m["converged"]: bad.append("not converged at the end")
if m["final_t_m"] > 0.15: bad.append("final error %.3f m > 0.15" % m["final_t_m"])
if m["abs_rmse_m"] > 0.15: bad.append("abs RMSE %.3f m > 0.15" % m["abs_rmse_m"])
if m["final_r_deg"] > 5: bad.append("final heading error %.2f deg > 5" % m["final_r_deg"])
if bad: sys.exit("localisation diverged: " + "; ".join(bad))
print("pf-localization on a grid-vector map: abs RMSE %.3f m, final %.3f m" % (m["abs_rmse_m"], m["final_t_m"]))
EOF
echo "pf-localization plug-in test passed"
