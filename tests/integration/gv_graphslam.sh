#!/usr/bin/env bash
# gv-graphslam (MRPT's graphslam-engine with the grid-vector deciders) on a
# rawlog with ground truth: outputs exist, the trajectory is sane, bad input
# gives one-line errors.
#
# Data: the first 250 scans of the shared `intel` benchmark (seed 1), converted
# with gv-carmen2rawlog; reference trajectory from mkbench.py.
set -euo pipefail
: "${GV_BIN:?}" "${GV_SOURCE_DIR:?}" "${GV_SHARED_DIR:?}"
BENCH="$GV_SHARED_DIR/bench"
INI="$GV_SOURCE_DIR/share/gridvector/graphslam-gridvector.ini"
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

python3 "$BENCH/mkbench.py" "$GV_SHARED_DIR/data/intel-corrected.log.gz" "$W/intel" --seed 1
# keep the first 250 scans (each scan is an ODOM + FLASER pair after 3 PARAM lines)
awk '/^(PARAM|#)/ || n < 500 { print } /^(ODOM|FLASER)/ { n++ }' "$W/intel.log" > "$W/short.log"
head -n 250 "$W/intel.ref.txt" > "$W/short.ref.txt"
"$GV_BIN/gv-carmen2rawlog" --quiet "$W/short.log" "$W/short.rawlog"

# --list-regs shows the grid-vector deciders next to MRPT's
"$GV_BIN/gv-graphslam" --list-regs > "$W/regs.txt"
for d in CGridVectorNRD CGridVectorERD CICPCriteriaNRD CFixedIntervalsNRD CICPCriteriaERD CLoopCloserERD; do
	grep -q "^$d\$" "$W/regs.txt" || fail "--list-regs does not list $d"
done

# a run with the grid-vector deciders
"$GV_BIN/gv-graphslam" --2d -i "$INI" -r "$W/short.rawlog" --disable-visuals \
	-n CGridVectorNRD -e CGridVectorERD -o CLevMarqGSO --output-dir "$W/out" > "$W/run.txt" 2> "$W/run.err"
# gv-em-slam's self-check on the online EM-SLAM behind the deciders: this run is ok (exit 0)
[ "$(tail -n 1 "$W/run.err")" = "self-check: ok" ] || fail "self-check line: $(tail -n 1 "$W/run.err")"
grep -q "^gv-graphslam: CGridVectorNRD + CGridVectorERD + CLevMarqGSO: 500 entries, 250 scans" "$W/run.txt" \
	|| fail "unexpected summary: $(grep '^gv-graphslam' "$W/run.txt")"
# (--quiet prints nothing at all: tests/integration/quiet.sh)
# the default optimizer with the grid-vector deciders is an empty one (they optimise Eq. 22 themselves;
# MRPT 2.5's own "CEmptyGSO" entry made a CLevMarqGSO): the same trajectory
"$GV_BIN/gv-graphslam" --2d -i "$INI" -r "$W/short.rawlog" --output-dir "$W/default" > "$W/default.txt"
grep -q "^gv-graphslam: CGridVectorNRD + CGridVectorERD + CEmptyGSO: 500 entries" "$W/default.txt" \
	|| fail "default optimizer: $(grep '^gv-graphslam' "$W/default.txt")"
grep -q "CLevMarqGSO::_optimizeGraph" "$W/default/optimizer.log" && fail "CEmptyGSO ran CLevMarqGSO"
cmp -s "$W/out/trajectory.txt" "$W/default/trajectory.txt" || fail "CEmptyGSO and CLevMarqGSO trajectories differ"
for f in trajectory.txt nodes.txt map.gvmap vectors.txt vectors.svg map.3Dscene output_graph.graph CGraphSlamEngine.log \
	node_registrar.log edge_registrar.log timings.log; do
	[ -s "$W/out/$f" ] || fail "missing or empty output $f"
done
[ "$(grep -c . "$W/out/trajectory.txt")" -eq 250 ] || fail "trajectory.txt should have one pose per scan"
awk 'NF != 4 { exit 1 }' "$W/out/trajectory.txt" || fail "trajectory.txt is not 't x y theta'"
grep -q "^VERTEX_SE2" "$W/out/output_graph.graph" || fail "output_graph.graph has no vertices"
"$GV_BIN/gv-map-info" "$W/out/map.gvmap" > "$W/mapinfo.txt" || fail "map.gvmap does not load"

# sane against the reference: better than the odometry it was given
awk '$1 == "ODOM" { print $8, $2, $3, $4 }' "$W/short.log" > "$W/odo.txt"
score() { python3 "$BENCH/evaltraj.py" "$1" "$W/short.ref.txt" | sed -n 's/.*ate_rmse_m=\([0-9.]*\).*/\1/p'; }
gv=$(score "$W/out/trajectory.txt")
odo=$(score "$W/odo.txt")
echo "ATE: grid-vector deciders $gv m, odometry $odo m"
# the deciders are the online EM-SLAM: 0.054 m here (session 16), against 9.3 m for the odometry
awk -v g="$gv" -v o="$odo" 'BEGIN { exit !(g < 0.1 && g < 0.05 * o) }' \
	|| fail "trajectory not good enough: ATE $gv m (odometry $odo m)"

# every graphslam-engine .ini MRPT ships (their '//' comments included) runs, as MRPT's app takes them
MRPT_INIS=/usr/share/mrpt/config_files/graphslam-engine
n=0
for ini in "$MRPT_INIS"/*.ini; do
	[ -e "$ini" ] || fail "no .ini in $MRPT_INIS (mrpt-common)"
	b=$(basename "$ini" .ini)
	"$GV_BIN/gv-graphslam" --2d -i "$ini" -r "$W/short.rawlog" --disable-visuals -n CGridVectorNRD -e CGridVectorERD \
		-o CLevMarqGSO --output-dir "$W/mrpt-$b" --quiet 2> "$W/mrpt-$b.err" || fail "$ini: $(cat "$W/mrpt-$b.err")"
	[ "$(grep -c . "$W/mrpt-$b/trajectory.txt")" -eq 250 ] || fail "$ini: trajectory.txt should have 250 poses"
	[ -s "$W/mrpt-$b/map.3Dscene" ] || fail "$ini: no map.3Dscene"
	n=$((n + 1))
done
[ "$n" -eq 6 ] || fail "expected MRPT's 6 graphslam-engine .ini files, found $n"

# a broken input (intel's first 300 scans with aces' first 300 odometry, as integration.self_check): the
# outputs are written, the self-check says suspect with its reasons, exit 3; under --quiet that line only
for log in intel aces; do
	zcat "$GV_SHARED_DIR/data/$log-corrected.log.gz" | awk '/^FLASER/ { n++ } n <= 300' > "$W/$log-300.log"
	"$GV_BIN/gv-bench-log" "$W/$log-300.log" "$W/$log" --quiet
done
python3 "$GV_SOURCE_DIR/bench/self-check/breaklog.py" splice "$W/aces.log" "$W/intel.log" "$W/spliced.log"
"$GV_BIN/gv-carmen2rawlog" --quiet "$W/spliced.log" "$W/spliced.rawlog"
set +e
"$GV_BIN/gv-graphslam" --2d -i "$INI" -r "$W/spliced.rawlog" --output-dir "$W/spliced" --quiet > "$W/sp.out" 2> "$W/sp.err"
rc=$?
set -e
[ "$rc" -eq 3 ] || fail "spliced log: exit $rc, expected 3: $(cat "$W/sp.err")"
[ "$(grep -c . "$W/sp.err")" -eq 1 ] && grep -q "^self-check: suspect (exit status 3): [a-z]" "$W/sp.err" \
	|| fail "spliced log --quiet: $(cat "$W/sp.err")"
[ -s "$W/spliced/trajectory.txt" ] && [ ! -s "$W/sp.out" ] || fail "spliced log: outputs missing or stdout not quiet"

# bad input: one line on stderr, non-zero exit, no crash
expect_error() {
	local want="$1"; shift
	set +e; "$GV_BIN/gv-graphslam" "$@" > /dev/null 2> "$W/err.txt"; rc=$?; set -e
	[ "$rc" -ne 0 ] && [ "$rc" -lt 128 ] || fail "exit $rc for: $*"
	[ "$(grep -c . "$W/err.txt")" -eq 1 ] || fail "not one line for: $* -> $(cat "$W/err.txt")"
	grep -q -- "$want" "$W/err.txt" || fail "expected '$want' for: $* -> $(cat "$W/err.txt")"
}
expect_error "no such config file" --2d -i "$W/none.ini" -r "$W/short.rawlog"
expect_error "no such rawlog" --2d -i "$INI" -r "$W/none.rawlog"
expect_error "unknown node registration decider 'CFooNRD'" -i "$INI" -r "$W/short.rawlog" -n CFooNRD
expect_error "only 2D" --3d -i "$INI" -r "$W/short.rawlog"
expect_error "CGridVectorERD needs the node decider CGridVectorNRD" -i "$INI" -r "$W/short.rawlog" \
	-n CICPCriteriaNRD -e CGridVectorERD --output-dir "$W/mixed"
printf '[GridVectorNRD]\nuse_odometry = true\n' > "$W/old.ini"
expect_error "old.ini: unknown key 'use_odometry' in section \[GridVectorNRD\]" \
	-i "$W/old.ini" -r "$W/short.rawlog" --output-dir "$W/old"
printf '[GridVectorERD]\nmax_distanse = 3\n' > "$W/typo.ini"
expect_error "typo.ini: unknown key 'max_distanse' in section \[GridVectorERD\]" \
	-i "$W/typo.ini" -r "$W/short.rawlog" --output-dir "$W/typo"
# [GeneralConfiguration]: MRPT's read_bool took 'ture' as false (no graph written, no word said)
sed 's/^save_graph = true/save_graph = ture/' "$INI" > "$W/general.ini"
expect_error "general.ini: \[GeneralConfiguration\] save_graph = 'ture' is not true or false" \
	-i "$W/general.ini" -r "$W/short.rawlog" --output-dir "$W/general"
[ ! -e "$W/general" ] || fail "general.ini: output directory created"
printf 'this is not a rawlog\n' > "$W/bad.rawlog"
expect_error "bad.rawlog" -i "$INI" -r "$W/bad.rawlog" --output-dir "$W/bad" --quiet
echo "gv_graphslam: OK"
