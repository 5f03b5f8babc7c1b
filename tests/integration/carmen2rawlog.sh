#!/usr/bin/env bash
# gv-carmen2rawlog writes rawlogs that MRPT's own rawlog-edit reads with the right
# counts, labels and timestamps; bad input gives one line and a non-zero exit.
set -euo pipefail
BIN=${GV_BIN:?}; DATA=${GV_SHARED_DIR:?}/data
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN/gv-carmen2rawlog" "$DATA/intel-corrected.log.gz" "$T/obs.rawlog" > "$T/out.txt"
grep -q "910 scans (910 FLASER)" "$T/out.txt" || fail "summary: $(cat "$T/out.txt")"
grep -q "wrote $T/obs.rawlog: 910 scans, 910 odometry observations" "$T/out.txt" || fail "wrote line"
"$BIN/gv-carmen2rawlog" "$DATA/freiburg-101-corrected.log.gz" "$T/sf.rawlog" --format sf --quiet
[ -s "$T/sf.rawlog" ] || fail "no sf rawlog"

if command -v rawlog-edit >/dev/null; then
  rawlog-edit --info -i "$T/obs.rawlog" > "$T/info.txt" 2>&1 || fail "rawlog-edit failed: $(tail -3 "$T/info.txt")"
  grep -Eq "Observations format +: Yes" "$T/info.txt" || fail "not observation format"
  grep -Eq "FLASER / +910" "$T/info.txt" || fail "FLASER count: $(grep FLASER "$T/info.txt")"
  grep -Eq "ODOMETRY / +910" "$T/info.txt" || fail "ODOMETRY count"
  grep -q "Earliest timestamp                : 32.906800" "$T/info.txt" || fail "first timestamp: $(grep Earliest "$T/info.txt")"
  rawlog-edit --info -i "$T/sf.rawlog" > "$T/info2.txt" 2>&1 || fail "rawlog-edit failed on sf"
  grep -Eq "Actions/SensoryFrame format +: Yes" "$T/info2.txt" || fail "not sensory-frame format"
  grep -Eq "FLASER / +292" "$T/info2.txt" || fail "sf FLASER count: $(grep FLASER "$T/info2.txt")"
else
  echo "rawlog-edit not installed: MRPT cross-check skipped"
fi

# --max-range auto: a scanner saturating below the declared maximum (ACES: exactly 50 m under
# mkbench's declared 81 m) gets that as its no-return range; other logs keep the declared one.
python3 "$GV_SHARED_DIR/bench/mkbench.py" "$DATA/aces-corrected.log.gz" "$T/aces" --seed 1 > /dev/null
"$BIN/gv-carmen2rawlog" "$T/aces.log" "$T/aces.rawlog" --max-range auto > "$T/out.txt"
grep -q "no-return value: max range 50.00 m instead of 81.00 m; max range set to 50.00 m" "$T/out.txt" || fail "aces auto: $(head -1 "$T/out.txt")"
"$BIN/gv-carmen2rawlog" "$T/aces.log" "$T/aces_default.rawlog" > "$T/out.txt"  # auto is the default
grep -q "; max range set to 50.00 m" "$T/out.txt" || fail "aces default: $(head -1 "$T/out.txt")"
"$BIN/gv-carmen2rawlog" "$T/aces.log" "$T/aces_declared.rawlog" --max-range declared > "$T/out.txt"
grep -q "max range 81.00 m; 440 ODOM, 3 PARAM; declared max range kept" "$T/out.txt" || fail "aces declared: $(head -1 "$T/out.txt")"
"$BIN/gv-carmen2rawlog" "$DATA/intel-corrected.log.gz" "$T/i.rawlog" --max-range auto > "$T/out.txt"
grep -q "; declared max range kept" "$T/out.txt" || fail "intel auto: $(head -1 "$T/out.txt")"
if command -v rawlog-edit >/dev/null; then
  # the 620 readings of 50 m are no longer valid points: MRPT's own export shows the
  # validity (rows: time, 180 ranges, 180 validity flags)
  (cd "$T" && rawlog-edit --export-2d-scans-txt -i aces.rawlog > /dev/null 2>&1) || fail "rawlog-edit export"
  [ -s "$T/aces_FLASER.txt" ] || fail "no exported scans: $(ls "$T")"
  n50=$(awk 'NR > 1 { for (i = 2; i <= 181; i++) if ($i + 0 >= 49.999 && $(i + 180) == 1) c++ } END { print c + 0 }' "$T/aces_FLASER.txt")
  [ "$n50" -eq 0 ] || fail "$n50 readings of 50 m still valid"
fi
set +e
"$BIN/gv-carmen2rawlog" "$T/aces.log" "$T/x.rawlog" --max-range -3 2> "$T/err.txt"; rc=$?
set -e
[ $rc -eq 2 ] && grep -q "max-range must be auto, declared or a positive number" "$T/err.txt" || fail "bad --max-range: exit $rc, $(cat "$T/err.txt")"

# errors: one line on stderr, exit 1 for bad input, 2 for bad usage, no output file left behind
printf 'FLASER 3 1.0 nan 2.0 0 0 0 0 0 0 5.0 h 5.0\n' > "$T/bad.log"
set +e
"$BIN/gv-carmen2rawlog" "$T/bad.log" "$T/bad.rawlog" 2> "$T/err.txt"; rc=$?
set -e
[ $rc -eq 1 ] || fail "bad input: exit $rc"
[ "$(cat "$T/err.txt")" = "gv-carmen2rawlog: $T/bad.log:1: FLASER range 1 is 'nan' (not a finite number)" ] || fail "message: $(cat "$T/err.txt")"
[ ! -e "$T/bad.rawlog" ] || fail "output written for bad input"
set +e
"$BIN/gv-carmen2rawlog" "$DATA/intel-corrected.log.gz" "$T/x.rawlog" --frmat sf 2> "$T/err.txt"; rc=$?
"$BIN/gv-carmen2rawlog" "$DATA/intel-corrected.log.gz" "$T/no/such/dir/x.rawlog" 2> "$T/err2.txt"; rc2=$?
set -e
[ $rc -eq 2 ] && [ "$(wc -l < "$T/err.txt")" -eq 1 ] || fail "unknown option: exit $rc, $(cat "$T/err.txt")"
[ $rc2 -eq 1 ] && grep -q "cannot write (No such file or directory)" "$T/err2.txt" || fail "unwritable: $(cat "$T/err2.txt")"
ls "$T" | grep -q "\.tmp" && fail "temporary file left behind"
echo "carmen2rawlog: OK"
