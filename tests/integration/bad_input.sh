#!/usr/bin/env bash
# Bad input across the apps, for what the per-app tests do not cover (gv_map.sh,
# em_slam.sh, carmen2rawlog.sh, gv_graphslam.sh, gv_sim_eval.sh, icp_slam_plugin.sh):
# truncated/corrupt gzip logs, inf/negative ranges, empty scans, unknown config keys,
# unwritable output, missing input, garbage trajectories and .gvmap files.
# Every case: exit 1 (2 for bad usage), one stderr line naming the tool, then the file, no control
# bytes, no crash, no output file, no temporary file and no new (empty) output directory left behind.
set -euo pipefail
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
cd "$W"
B="$GV_BIN"
fail() { echo "FAIL: $*" >&2; exit 1; }
# a robot in an 8 x 6 m room, 20 scans of 181 beams (as gv_map.sh)
awk 'BEGIN { pi = atan2(0, -1);
  for (t = 0; t < 20; t++) { x = -2 + 0.1 * t; y = 0.3 * sin(t / 5); th = 0.15 * t; line = "FLASER 181";
    for (i = 0; i < 181; i++) { a = th - pi / 2 + pi * i / 180; dx = cos(a); dy = sin(a); r = 1e9;
      if (dx > 1e-9) r = (4 - x) / dx < r ? (4 - x) / dx : r; if (dx < -1e-9) r = (-4 - x) / dx < r ? (-4 - x) / dx : r;
      if (dy > 1e-9) r = (3 - y) / dy < r ? (3 - y) / dy : r; if (dy < -1e-9) r = (-3 - y) / dy < r ? (-3 - y) / dy : r;
      line = line sprintf(" %.3f", r); }
    ts = 1000 + 0.2 * t;
    printf "%s %.4f %.4f %.4f %.4f %.4f %.4f %.6f sim %.6f\n", line, x, y, th, x, y, th, ts, ts;
    printf "%.6f %.4f %.4f %.4f\n", ts, x, y, th > "traj.txt"; } }' > room.log
gzip -c room.log > room.log.gz
head -c $(( $(stat -c %s room.log.gz) / 2 )) room.log.gz > trunc.log.gz
python3 -c "
d = bytearray(open('room.log.gz', 'rb').read())
for i in range(200, 260): d[i] ^= 0x5a
open('corrupt.log.gz', 'wb').write(d)"
sed '5s/^\(FLASER 181 [^ ]* [^ ]* \)[^ ]*/\1inf/' room.log > inf.log
sed '5s/^\(FLASER 181 [^ ]* [^ ]* \)[^ ]*/\1-1.5/' room.log > neg.log
{ head -3 room.log; echo "FLASER 0 0 0 0 0 0 0 1000.7 sim 1000.7"; tail -n +4 room.log; } > emptyscan.log
: > empty.log
printf '[gridvector_grid]\nresolutoin = 0.05\n' > typo.ini
printf '[gridvector_grid]\nhalf_width = 1.5\n' > badval.ini
printf '[gridvector_gird]\nresolution = 0.05\n' > sectypo.ini  # a misspelt section: its keys were dropped silently
printf 'resolution = 0.05\n[gridvector_grid]\nhalf_width = 2\n' > nosection.ini
printf '[gridvector_grid\nresolution = 0.05\n' > openheader.ini
sed '5s/^FLASER 181/FLASER 182/' room.log > beamcount.log  # one beam more than the line has
mkdir -p dir.rawlog
printf '\001\377\033[2Jab 1 2 3\n' > binary.txt  # a binary token with a terminal escape
printf 'hello world\n1 2\n' > garbage.txt
printf '1000 nan 0 0\n1000.2 1 1 1\n' > nantraj.txt
printf '\x86a\x1b[2Jb\x00 garbage' | gzip -c > garbage.gvmap  # class name with an escape sequence
"$B/gv-carmen2rawlog" room.log room.rawlog --quiet
head -c $(( $(stat -c %s room.rawlog) / 2 )) room.rawlog > trunc.rawlog
"$B/gv-map" --input room.log --poses log --out ok --quiet
head -c $(( $(stat -c %s ok/map.gvmap) / 2 )) ok/map.gvmap > trunc.gvmap
INI="$GV_SOURCE_DIR/share/gridvector/graphslam-gridvector.ini"

n=0
# expect STATUS WORD OUTPUT -- command...: exit STATUS, one stderr line containing WORD, OUTPUT not created,
# no new directory
expect() {
  local status=$1 word=$2 output=$3; shift 4
  find . -type d | sort > dirs.before
  set +e; "$@" > out.txt 2> err.txt; local rc=$?; set -e
  find . -type d | sort | comm -13 dirs.before - > dirs.new
  [ ! -s dirs.new ] || fail "directories left behind by: $* -> $(tr '\n' ' ' < dirs.new)"
  [ "$rc" -eq "$status" ] || fail "exit $rc (want $status) for: $* -> $(head -c 400 err.txt)"
  [ "$(grep -c . err.txt)" -eq 1 ] || fail "not one line for: $* -> $(cat err.txt)"
  grep -qF -- "$word" err.txt || fail "'$word' not named for: $* -> $(cat err.txt)"
  # every tool's convention (doc/io.md): "TOOL: FILE: problem", "TOOL: problem (see --help)"
  grep -q "^$(basename "$1"): " err.txt || fail "the tool is not named first for: $* -> $(cat err.txt)"
  [ "$status" -ne 2 ] || grep -q " (see --help)$" err.txt || fail "a usage error without '(see --help)': $*"
  ! LC_ALL=C grep -q '[[:cntrl:]]' <(tr -d '\n' < err.txt) || fail "control bytes in the message for: $*"
  [ "$output" = - ] || [ ! -e "$output" ] || fail "$output written for: $*"
  n=$((n + 1))
}
# corrupt logs: every reader names the file and the problem
expect 1 "trunc.log.gz: truncated or corrupt gzip data" o1/map.gvmap -- "$B/gv-map" --input trunc.log.gz --poses log --out o1 --quiet
expect 1 "trunc.log.gz: truncated or corrupt gzip data" e1/report.json -- "$B/gv-em-slam" --input trunc.log.gz --out e1 --quiet
expect 1 "trunc.log.gz: truncated or corrupt gzip data" t1.rawlog -- "$B/gv-carmen2rawlog" trunc.log.gz t1.rawlog --quiet
expect 1 "trunc.log.gz: truncated or corrupt gzip data" b1.log -- "$B/gv-bench-log" trunc.log.gz b1 --quiet
expect 1 "trunc.log.gz: truncated or corrupt gzip data" - -- "$B/gv-bench-extract" trunc.log.gz --repeat 1
expect 1 "trunc.log.gz: truncated or corrupt gzip data" - -- "$B/gv-eval" traj trunc.log.gz traj.txt
expect 1 "corrupt.log.gz: truncated or corrupt gzip data" e2/report.json -- "$B/gv-em-slam" --input corrupt.log.gz --out e2 --quiet
expect 1 "corrupt.log.gz: truncated or corrupt gzip data" b2.log -- "$B/gv-bench-log" corrupt.log.gz b2 --quiet
expect 1 "inf.log:5: FLASER range 2 is 'inf'" o3/map.gvmap -- "$B/gv-map" --input inf.log --poses log --out o3 --quiet
expect 1 "neg.log:5: FLASER range 2 is -1.5 (negative)" e3/report.json -- "$B/gv-em-slam" --input neg.log --out e3 --quiet
expect 1 "emptyscan.log:4: FLASER: zero beams" o4/map.gvmap -- "$B/gv-map" --input emptyscan.log --poses log --out o4 --quiet
expect 1 "emptyscan.log:4: FLASER beam count is 0" b4.log -- "$B/gv-bench-log" emptyscan.log b4 --quiet
expect 1 "beamcount.log:5: FLASER: 182 beams announced: expected 193 fields, found 192" e4/report.json -- "$B/gv-em-slam" --input beamcount.log --out e4 --quiet
expect 1 "empty.log: no laser scans" e5/report.json -- "$B/gv-em-slam" --input empty.log --out e5 --quiet
expect 1 "empty.log: no odometry" - -- "$B/gv-eval" traj empty.log traj.txt
expect 1 "trunc.rawlog: truncated or corrupt gzip data" o6/map.gvmap -- "$B/gv-map" --input trunc.rawlog --poses log --out o6 --quiet
expect 1 "trunc.rawlog: entry" g6/trajectory.txt -- "$B/gv-graphslam" --2d -i "$INI" -r trunc.rawlog --disable-visuals --output-dir g6
# missing input (a nested output directory is not created either)
expect 1 "missing.log: cannot read" - -- "$B/gv-map" --input missing.log --poses log --out n1/a/b --quiet
expect 1 "missing.log: cannot read" - -- "$B/gv-em-slam" --input missing.log --out n2/a --quiet
expect 1 "missing.rawlog" - -- "$B/gv-graphslam" --2d -i "$INI" -r missing.rawlog --disable-visuals --output-dir n3/a
expect 1 "dir.rawlog: cannot read (it is a directory)" g7/trajectory.txt -- "$B/gv-graphslam" --2d -i "$INI" -r dir.rawlog --disable-visuals --output-dir g7
expect 1 "dir.rawlog: cannot read (it is a directory)" - -- "$B/gv-graphslam" --2d -i dir.rawlog -r room.rawlog --disable-visuals --output-dir g7
expect 1 "dir.rawlog: cannot read (it is a directory)" o7/map.gvmap -- "$B/gv-map" --input dir.rawlog --poses log --out o7 --quiet
expect 1 "missing.log: cannot read" b7.log -- "$B/gv-bench-log" missing.log b7 --quiet
expect 1 "missing.log: cannot read" - -- "$B/gv-bench-extract" missing.log
expect 1 "missing.txt: cannot read" - -- "$B/gv-eval" traj traj.txt missing.txt
expect 1 "missing.gvmap: no such file" - -- "$B/gv-map-info" missing.gvmap
# unknown config keys (and a gv-sim file without its section)
expect 1 "typo.ini: unknown key 'resolutoin' in section [gridvector_grid]" o8/map.gvmap -- "$B/gv-map" --input room.log --poses log --out o8 --config typo.ini --quiet
expect 1 "typo.ini: unknown key 'resolutoin'" e8/report.json -- "$B/gv-em-slam" --input room.log --out e8 --config typo.ini --quiet
expect 1 "typo.ini: unknown key 'resolutoin'" - -- "$B/gv-bench-extract" room.log --config typo.ini
expect 1 "typo.ini: unknown key 'resolutoin'" m8.gvmap -- "$B/gv-map-info" --from-simplemap x.simplemap --config typo.ini --save m8.gvmap
expect 1 "typo.ini: unknown key 'resolutoin'" g8/trajectory.txt -- "$B/gv-graphslam" --2d -i typo.ini -r room.rawlog --disable-visuals --output-dir g8
expect 1 "sectypo.ini: unknown section [gridvector_gird] (the gridvector_ sections are extraction, grid," e8/report.json -- "$B/gv-em-slam" --input room.log --out e8 --config sectypo.ini --quiet
expect 1 "sectypo.ini: unknown section [gridvector_gird]" o8/map.gvmap -- "$B/gv-map" --input room.log --poses log --out o8 --config sectypo.ini --quiet
expect 1 "sectypo.ini: unknown section [gridvector_gird]" - -- "$B/gv-config" --check sectypo.ini
expect 1 "nosection.ini:1: 'resolution = 0.05' is outside any [section]" e8/report.json -- "$B/gv-em-slam" --input room.log --out e8 --config nosection.ini --quiet
expect 1 "openheader.ini:1: section header without ']'" - -- "$B/gv-config" --check openheader.ini
expect 1 "badval.ini: [gridvector_grid] half_width = '1.5' is not an integer" e8/report.json -- "$B/gv-em-slam" --input room.log --out e8 --config badval.ini --quiet
expect 1 "badval.ini: [gridvector_grid] half_width = '1.5' is not an integer" - -- "$B/gv-config" --check badval.ini
printf 'seed = 3\n[gv_sim]\nworld = office\n' > simnosec.ini  # the seed was ignored
expect 1 "simnosec.ini:1: 'seed = 3' is outside any [section]" s8/sim.log -- "$B/gv-sim" --config simnosec.ini --out s8 --quiet --scans 20
expect 1 "typo.ini: no [gv_sim] section" s8/sim.log -- "$B/gv-sim" --config typo.ini --out s8 --quiet
# gv-sim's values are read as the other .ini values (io/IniValue.h), ranges as its flags'
printf '[gv_sim]\nlaps = 4294967297\n' > simlaps.ini  # was read as 1 lap
expect 1 "simlaps.ini: [gv_sim] laps = '4294967297' is not an integer" s8/sim.log -- "$B/gv-sim" --config simlaps.ini --out s8 --quiet
expect 2 "gv-sim: --laps needs an integer, got '4294967297' (see --help)" s8/sim.log -- "$B/gv-sim" --laps 4294967297 --out s8 --quiet
printf '[gv_sim]\nspeed = nan\n' > simnan.ini
expect 1 "simnan.ini: [gv_sim] speed = 'nan' is not a finite number" s8/sim.log -- "$B/gv-sim" --config simnan.ini --out s8 --quiet
printf '[gv_sim]\ndoors = of\n' > simbool.ini
expect 1 "simbool.ini: [gv_sim] doors = 'of' is not on/off, true/false, yes/no or 1/0" s8/sim.log -- "$B/gv-sim" --config simbool.ini --out s8 --quiet
printf '[gv_sim]\nlaps = 5000 ; a long run\n' > simrange.ini
expect 1 "simrange.ini: [gv_sim] laps = '5000' must be in 0..1000" s8/sim.log -- "$B/gv-sim" --config simrange.ini --out s8 --quiet --laps 2
printf '[gv_sim]\nworld = mars\n' > simworld.ini
expect 1 "simworld.ini: [gv_sim] world = 'mars' must be one of corridor-loop, office, long-corridor" s8/sim.log -- "$B/gv-sim" --config simworld.ini --out s8 --quiet
# a flag's range error names the flag as typed, underscores as dashes in the flag only
expect 2 "gv-sim: --turn-rate-deg must be in (0, 360], got '400' (see --help)" s8/sim.log -- "$B/gv-sim" --turn-rate-deg 400 --out s8 --quiet
expect 2 "gv-sim: --world must be one of corridor-loop, office, long-corridor, got 'mars_2' (see --help)" s8/sim.log -- "$B/gv-sim" --world mars_2 --out s8 --quiet
printf '[gv_sim]\nscans = 20 ; short\ndoors = OFF\n' > simok.ini  # a comment after a value was refused
"$B/gv-sim" --config simok.ini --out s9 --quiet && [ "$(grep -c '^FLASER' s9/sim.log)" -eq 20 ] || fail "gv-sim: simok.ini"
# a config from a pipe (--config <(...)): read, not sized by seeking; a directory is named as such
expect 1 "unknown key 'resolutoin'" - -- "$B/gv-config" --check <(cat typo.ini)
"$B/gv-config" --check <(printf '[gridvector_grid]\nresolution = 0.1\n') > /dev/null || fail "gv-config: a config from a pipe is refused"
expect 1 "ok: cannot read config file (it is a directory)" - -- "$B/gv-config" --check ok
# unwritable output (the parent is a file)
expect 1 "room.log/x: cannot write (Not a directory)" - -- "$B/gv-em-slam" --input room.log --out room.log/x --quiet
expect 1 "room.log/x: cannot write (Not a directory)" - -- "$B/gv-sim" --out room.log/x --quiet --scans 20
expect 1 "room.log/x.rawlog: cannot write (Not a directory)" - -- "$B/gv-carmen2rawlog" room.log room.log/x.rawlog --quiet
expect 1 "room.log/b.log: cannot write (Not a directory)" - -- "$B/gv-bench-log" room.log room.log/b --quiet
expect 1 "room.log/m.gvmap: cannot write (Not a directory)" - -- "$B/gv-map-info" ok/map.gvmap --save room.log/m.gvmap
expect 1 "room.log/x: cannot write (Not a directory)" - -- "$B/gv-graphslam" --2d -i "$INI" -r room.rawlog --disable-visuals --output-dir room.log/x
# the output is checked before the (long) read: an unwritable output is reported, not the bad input
expect 1 "room.log/x.rawlog: cannot write (Not a directory)" - -- "$B/gv-carmen2rawlog" trunc.log.gz room.log/x.rawlog --quiet
expect 1 "nodir/x.rawlog: cannot write (No such file or directory)" - -- "$B/gv-carmen2rawlog" missing.log nodir/x.rawlog --quiet
expect 1 "ok: cannot write (it is a directory)" - -- "$B/gv-carmen2rawlog" trunc.log.gz ok --quiet
expect 1 "room.log/b.log: cannot write (Not a directory)" - -- "$B/gv-bench-log" trunc.log.gz room.log/b --quiet
expect 1 "nodir/b.log: cannot write (No such file or directory)" - -- "$B/gv-bench-log" missing.log nodir/b --quiet
expect 1 "room.log/m.gvmap: cannot write (Not a directory)" - -- "$B/gv-map-info" trunc.gvmap --save room.log/m.gvmap
expect 1 "nodir/m.gvmap: cannot write (No such file or directory)" - -- "$B/gv-map-info" --from-simplemap missing.simplemap --save nodir/m.gvmap
expect 1 "room.log/x: cannot write (Not a directory)" - -- "$B/gv-map" --input trunc.log.gz --poses log --out room.log/x --quiet
expect 1 "room.log/x: cannot write (Not a directory)" - -- "$B/gv-em-slam" --input trunc.log.gz --out room.log/x --quiet
# the converters create no directories
expect 1 "nodir/x.rawlog: cannot write (No such file or directory)" - -- "$B/gv-carmen2rawlog" room.log nodir/x.rawlog --quiet
expect 1 "nodir/b.log: cannot write (No such file or directory)" - -- "$B/gv-bench-log" room.log nodir/b --quiet
# garbage trajectories (MRPT's own ground-truth reader would crash on the last one)
expect 1 "garbage.txt:1: expected 't x y theta', found 2 fields" o9/map.gvmap -- "$B/gv-map" --input room.log --poses garbage.txt --out o9 --quiet
# poses matched by time: two different poses at the time nearest a scan cannot be told apart
{ head -3 traj.txt; awk 'NR == 3 { print $1, $2 + 1, $3, $4 }' traj.txt; tail -n +5 traj.txt; } > twice.txt
expect 1 "twice.txt: 2 different poses at t = 1000.400000: scans cannot be matched to poses by time" o9/map.gvmap -- "$B/gv-map" --input room.log --poses twice.txt --out o9 --quiet
expect 1 "twice.txt: 2 different poses at t = 1000.400000" e9/report.json -- "$B/gv-em-slam" --input room.log --init twice.txt --out e9 --quiet
expect 1 "nantraj.txt:1: x is 'nan'" e9/report.json -- "$B/gv-em-slam" --input room.log --init nantraj.txt --out e9 --quiet
# gv-eval traj: by time a shared time would pick one of two poses, by order the times do not pair up
expect 1 "twice.txt vs traj.txt: 2 estimate poses share t = 1000.400000 and differ: matching by time would pick one of them, and matching by order needs one pose per scan of the same log (20 estimate and 20 reference poses, pose 4 at other times)" - -- "$B/gv-eval" traj twice.txt traj.txt
expect 1 "garbage.txt:1: expected 't x y theta'" - -- "$B/gv-eval" traj garbage.txt traj.txt
expect 1 "nantraj.txt:1: x is 'nan'" - -- "$B/gv-eval" traj traj.txt nantraj.txt
printf '# only a comment\n' > nopose.txt
expect 1 "nopose.txt: no poses" - -- "$B/gv-eval" traj nopose.txt traj.txt
awk '{ print $1 + 100, $2, $3, $4 }' traj.txt > later.txt
expect 1 "later.txt vs traj.txt: too few matched poses (0) within --max-dt 0.05 s" - -- "$B/gv-eval" traj later.txt traj.txt
expect 1 "binary.txt:1: t is '\\x01\\xff\\x1b[2Jab' (not a finite number)" - -- "$B/gv-eval" traj binary.txt traj.txt
# gv-eval map: binary tokens of a vectors file and of the truth files are quoted printably, 40 bytes at most
"$B/gv-sim" --out sim --quiet --scans 20
printf '0 0 1 1 0.5 \001\377\033[2Jdyn\n' > binlabel.txt
expect 1 "binlabel.txt:1: label is '\x01\xff\x1b[2Jdyn' (expected static or dynamic)" - -- "$B/gv-eval" map binlabel.txt sim
echo "0 0 1 1 0.5" > okvec.txt; cp -r sim simbad && printf '\033]0;%s\a\n' "$(printf 'x%.0s' {1..60})" >> simbad/truth_dynamic.txt
expect 1 "truth_dynamic.txt:$(wc -l < simbad/truth_dynamic.txt): unknown record '\x1b]0;$(printf 'x%.0s' {1..36})...'" - -- "$B/gv-eval" map okvec.txt simbad
expect 2 "--pass-gap must be > 0" - -- "$B/gv-eval" map okvec.txt sim --breakdown --pass-gap 0
expect 2 "--pass-gap needs a number, got 'nan'" - -- "$B/gv-eval" map okvec.txt sim --breakdown --pass-gap nan
expect 1 "garbage.txt:1: ground-truth lines must be 't x y theta'" g9/trajectory.txt -- "$B/gv-graphslam" --2d -i "$INI" -r room.rawlog -g garbage.txt --disable-visuals --output-dir g9
# .gvmap files
expect 1 "trunc.gvmap: truncated or corrupt gzip data (CRC/length trailer mismatch)" m10.gvmap -- "$B/gv-map-info" trunc.gvmap --save m10.gvmap
expect 1 "garbage.gvmap: not a valid mrpt::maps::CGridVectorMap file" - -- "$B/gv-map-info" garbage.gvmap
# session 10 audit (doc/benchmarks-history.md "Session 10: sanitizers and bad input")
# graphslam ground truth: MRPT's engine indexes it without bounds checks (empty file: a segfault)
: > gt0.txt; head -5 traj.txt > gt5.txt
expect 1 "gt0.txt: no ground-truth poses" g10/trajectory.txt -- "$B/gv-graphslam" --2d -i "$INI" -r room.rawlog -g gt0.txt --disable-visuals --output-dir g10 --quiet
expect 1 "gt5.txt: 5 ground-truth poses, the engine reads pose 6 at entry 11 of room.rawlog (one pose per scan)" g10/trajectory.txt -- "$B/gv-graphslam" --2d -i "$INI" -r room.rawlog -g gt5.txt --disable-visuals --output-dir g10 --quiet
sed 's/^\[GeneralConfiguration\]/[GeneralConfiguration]\nground_truth_file_format = foo/' "$INI" > gtfmt.ini
expect 1 "gtfmt.ini: [GeneralConfiguration] ground_truth_file_format = 'foo': MRPT 2.5's graphslam engine reads ground truth (-g) as NavSimul only" g10/trajectory.txt -- "$B/gv-graphslam" --2d -i gtfmt.ini -r room.rawlog -g traj.txt --disable-visuals --output-dir g10 --quiet
# a graphslam .ini that is not one (MRPT's reader skipped every line: the run used defaults)
head -c 3000 /dev/zero | tr '\0' '\001' > binary.ini
expect 1 "binary.ini:1: '\\x01\\x01" g10/trajectory.txt -- "$B/gv-graphslam" --2d -i binary.ini -r room.rawlog --disable-visuals --output-dir g10 --quiet
expect 1 "binary.ini:1: '\\x01\\x01" - -- "$B/gv-config" --check binary.ini
# gv-bench-log: a wrong beam count shifted the pose (mkbench.py reads it after the announced ranges)
sed '5s/^FLASER 181/FLASER 180/' room.log > fewer.log
expect 1 "fewer.log:5: FLASER: 180 beams announced: expected 191 fields, found 192" b10.log -- "$B/gv-bench-log" fewer.log b10 --quiet
# a .gvmap argument that is a directory ("unknown error" before)
expect 1 "gv-map-info: dir.rawlog: cannot read (it is a directory)" - -- "$B/gv-map-info" dir.rawlog
# an occupancy grid too fine for memory: rejected with the config, not as std::bad_alloc after four outputs
printf '[gridvector_occupancy]\nresolution = 0.00001\n' > tinyocc.ini
expect 1 "tinyocc.ini: [gridvector_occupancy] resolution = '1e-05' must be >= 0.01 (finer cells outgrow memory)" e10/report.json -- "$B/gv-em-slam" --input room.log --out e10 --config tinyocc.ini --quiet
expect 1 "tinyocc.ini: [gridvector_occupancy] resolution = '1e-05' must be >= 0.01 (finer cells outgrow memory)" o10/map.gvmap -- "$B/gv-map" --input room.log --poses log --out o10 --config tinyocc.ini --quiet
# more of the matrix, already right: plain log cut mid-line, NaN range, binary garbage, empty gzip,
# a rawlog cut mid-object, a .gvmap of a future version, bad --max-iterations, an --out that is a file
head -c $(( $(stat -c %s room.log) / 2 + 17 )) room.log > midline.log
expect 1 "midline.log:11: FLASER: 181 ranges announced, line has only 2 more fields" e10/report.json -- "$B/gv-em-slam" --input midline.log --out e10 --quiet
sed '5s/^\(FLASER 181 [^ ]* [^ ]* \)[^ ]*/\1nan/' room.log > nan.log
expect 1 "nan.log:5: FLASER range 2 is 'nan' (not a finite number)" t10.rawlog -- "$B/gv-carmen2rawlog" nan.log t10.rawlog --quiet
python3 -c "import random; r = random.Random(7); open('garbage.log', 'wb').write(bytes(r.randrange(256) for _ in range(5000)))"
expect 1 "garbage.log:1: unrecognised line starting with '\\xa5M\\xca" o10/map.gvmap -- "$B/gv-map" --input garbage.log --poses log --out o10 --quiet
: | gzip -c > empty.log.gz
expect 1 "empty.log.gz: no laser scans" e10/report.json -- "$B/gv-em-slam" --input empty.log.gz --out e10 --quiet
"$B/gv-carmen2rawlog" room.log plain.rawlog --quiet --no-compress
head -c $(( $(stat -c %s plain.rawlog) / 2 + 17 )) plain.rawlog > midobj.rawlog
expect 1 "midobj.rawlog: entry 21: truncated or corrupt rawlog" e10/report.json -- "$B/gv-em-slam" --input midobj.rawlog --out e10 --quiet
python3 -c "
import gzip
raw = bytearray(gzip.decompress(open('ok/map.gvmap', 'rb').read()))
i = raw.find(b'CGridVectorMap') + len(b'CGridVectorMap'); raw[i] = 99
open('future.gvmap', 'wb').write(gzip.compress(bytes(raw)))"
expect 1 "future.gvmap: not a valid mrpt::maps::CGridVectorMap file (Cannot parse object: unknown serialization version number: '99')" m10.gvmap -- "$B/gv-map-info" future.gvmap --save m10.gvmap
expect 2 "--max-iterations must be in 1..1000, got -1" e10/report.json -- "$B/gv-em-slam" --input room.log --out e10 --quiet --max-iterations -1
expect 2 "--max-iterations needs an integer, got 'abc'" e10/report.json -- "$B/gv-em-slam" --input room.log --out e10 --quiet --max-iterations abc
expect 1 "room.log: cannot write" - -- "$B/gv-em-slam" --input room.log --out room.log --quiet
expect 1 "room.log: cannot write" - -- "$B/gv-map" --input room.log --poses log --out room.log --quiet
expect 2 "--input and --out are required" - -- "$B/gv-em-slam"
expect 2 "gv-bench-map: --band must be > 0 (metres), got -1" - -- "$B/gv-bench-map" room.log --band -1
expect 2 "gv-bench-icp: --every must be in 2..1000000, got 1" - -- "$B/gv-bench-icp" room.log room.log --every 1
expect 1 "gv-bench-icp: room.log: not a valid mrpt::maps::CGridVectorMap file" - -- "$B/gv-bench-icp" room.log traj.txt --map room.log
# the tools converted to ArgParser: bad usage is one line and 2, --help is 0
for tool in gv-map gv-em-slam gv-sim gv-eval gv-carmen2rawlog gv-bench-log gv-bench-map gv-bench-wipe gv-bench-icp gv-graphslam; do
  "$B/$tool" --help | head -1 | grep -q "^usage: $tool $tool" && fail "$tool --help: the usage line repeats the tool's name"
  "$B/$tool" --help | grep -q "^usage: $tool " || fail "$tool --help"
done
for tool in gv-map-info gv-config gv-bench-extract; do
  expect 2 "$tool: unknown option --frobnicate (see --help)" - -- "$B/$tool" --frobnicate
  "$B/$tool" --help | grep -q "^usage: $tool " || fail "$tool --help"
done
expect 2 "--repeat must be in 1..1000000, got 0" - -- "$B/gv-bench-extract" room.log --repeat 0
expect 2 "--config applies to --from-simplemap only" - -- "$B/gv-map-info" ok/map.gvmap --config typo.ini
# a .gvmap rewritten by --save loads again
"$B/gv-map-info" ok/map.gvmap --save re.gvmap > info1.txt && "$B/gv-map-info" re.gvmap > info2.txt
cmp info1.txt info2.txt || fail "re-saved .gvmap differs: $(diff info1.txt info2.txt)"
! find . -name '*.tmp*' | grep -q . || fail "temporary files left: $(find . -name '*.tmp*')"
echo "bad_input: $n cases OK"
