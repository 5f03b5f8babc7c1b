#!/usr/bin/env bash
# gv-graphslam (MRPT's graphslam-engine) with the grid-vector deciders (CEmptyGSO, the default) and with
# MRPT's ICP deciders (CLevMarqGSO), same .ini, same rawlog, same run, one core; scored with evaltraj.py.
#
#   bench/graphslam/run_deciders.sh OUTDIR [LOGS] [SEEDS]
#   LOGS: names of ../shared/data/NAME-corrected.log.gz (default: all eight); SEEDS default "1"
# Needs BIN (default build/bin) and SHARED (default ../shared). Prints one row per log and system.
set -euo pipefail
OUT=${1:?OUTDIR}
LOGS=${2:-"intel aces freiburg-079 freiburg-101 csail seattle acapulco infinite-corridor"}
SEEDS=${3:-1}
HERE=$(cd "$(dirname "$0")/../.." && pwd)
BIN=${BIN:-$HERE/build/bin}
SHARED=${SHARED:-$HERE/../shared}
INI=$HERE/share/gridvector/graphslam-gridvector.ini
CORE=${CORE:-0}
mkdir -p "$OUT"
echo "| log | seed | deciders | scans | ATE [m] | local t [m] | loop t [m] | loop r [deg] | user CPU [s] | scans/s |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for L in $LOGS; do
	for S in $SEEDS; do
		B=$OUT/${L}_s$S
		[ -s "$B.log" ] || python3 "$SHARED/bench/mkbench.py" "$SHARED/data/$L-corrected.log.gz" "$B" --seed "$S" > /dev/null
		[ -s "$B.rawlog" ] || "$BIN/gv-carmen2rawlog" --quiet "$B.log" "$B.rawlog"
		for sys in gv icp; do
			# gv-graphslam's default optimizer: CEmptyGSO with the grid-vector deciders, CLevMarqGSO with MRPT's
			if [ $sys = gv ]; then n=CGridVectorNRD e=CGridVectorERD o=CEmptyGSO; else n=CICPCriteriaNRD e=CICPCriteriaERD o=CLevMarqGSO; fi
			D=$B.$sys
			if [ ! -s "$D/trajectory.txt" ]; then
				rc=0  # 3: the grid-vector deciders' self-check says suspect (outputs complete)
				/usr/bin/time -f "%U" -o "$D.time" taskset -c "$CORE" "$BIN/gv-graphslam" --2d -i "$INI" -r "$B.rawlog" \
					--disable-visuals -n $n -e $e -o $o --output-dir "$D" --quiet 2> "$D.err" || rc=$?
				[ $rc -eq 0 ] || [ $rc -eq 3 ] || echo "failed" > "$D.time"
			fi
			r=$(python3 "$SHARED/bench/evaltraj.py" "$D/trajectory.txt" "$B.ref.txt" 2> /dev/null || true)
			get() { sed -n "s/.*$1=\([^ ]*\).*/\1/p" <<< "$r"; }
			u=$(tail -1 "$D.time")
			scans=$(get n)
			sps=$(awk -v n="$scans" -v u="$u" 'BEGIN { if (u > 0) printf "%.0f", n / u; else print "-" }')
			echo "| $L | $S | $sys | $scans | $(get ate_rmse_m) | $(get rel_local_t_m) | $(get rel_loop_t_m) | $(get rel_loop_r_deg) | $u | $sps |"
		done
	done
done
