#!/usr/bin/env bash
# Every reproducer of issue 22 ($GV_SHARED_DIR/repro, README there) with its command, and the
# inputs the README names besides (/dev/zero as --input and --config, a FIFO without a writer, a
# 5 MB line, a pipe as --input). Each bad input: exit 1-127, one stderr line "TOOL: FILE: problem"
# naming the file, under 5 s of CPU and 500 MB peak RSS (a hang: 60 s of wall time). The valid
# input (a pipe) maps as the file does. Every config reproducer is also rejected by gv-config --check.
set -euo pipefail
R="$GV_SHARED_DIR/repro"
[ -d "$R" ] || { echo "repro: $R missing"; exit 1; }
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
cd "$W"
B="$GV_BIN"
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v /usr/bin/time > /dev/null || fail "/usr/bin/time (GNU time) is needed to measure CPU time and peak RSS"
zcat "$GV_SHARED_DIR/data/intel-corrected.log.gz" | head -300 > LOG.log || true  # zcat ends by SIGPIPE
[ "$(wc -l < LOG.log)" -eq 300 ] || fail "LOG.log: not the 300 first lines of intel-corrected.log.gz"
MAX_CPU=5 MAX_RSS_KB=512000

n=0 seen=""
# bad FILE -- command...: exit 1-127, one line "TOOL: ...FILE...", CPU and RSS within bounds
bad() {
  local file=$1; shift 2
  rm -rf out
  set +e
  ( ulimit -v 4000000; timeout 60 /usr/bin/time -f "%U %S %M" -o time.txt "$@" > out.txt 2> err.txt )
  local rc=$?
  set -e
  [ "$rc" -ne 124 ] || fail "hang (60 s) for: $*"
  [ "$rc" -ge 1 ] && [ "$rc" -le 127 ] || fail "exit $rc for: $* -> $(head -c 300 err.txt)"
  [ "$(grep -c . err.txt)" -eq 1 ] || fail "not one line for: $* -> $(head -c 600 err.txt)"
  grep -q "^$(basename "$1"): " err.txt || fail "the tool is not named first for: $* -> $(cat err.txt)"
  grep -qF -- "$file" err.txt || fail "'$file' not named for: $* -> $(cat err.txt)"
  read -r user sys rss < <(tail -1 time.txt)
  awk -v u="$user" -v s="$sys" -v m="$MAX_CPU" 'BEGIN { exit !(u + s < m) }' ||
    fail "${user}+${sys} s of CPU for: $* -> $(cat err.txt)"
  [ "$rss" -lt "$MAX_RSS_KB" ] || fail "peak RSS ${rss} KB for: $* -> $(cat err.txt)"
  printf '%-36s exit %d, %5.2f s CPU, %4d MB: %s\n' "$(basename "$file")" "$rc" \
    "$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')" $((rss / 1024)) "$(cut -c1-150 err.txt)"
  seen="$seen $(basename "$file")"
  n=$((n + 1))
}

bad "$R/res1e300.log" -- "$B/gv-map" --input "$R/res1e300.log" --poses log --out out --quiet
for f in robotlaser_res_1e300.log side_offset_m1e308.log side_offset_1e6_min.log rawlog_sensorpose_nan.rawlog \
  rawlog_sensorpose_y1e15.rawlog rawlog_N_2p30_271B.rawlog rawlog_action_estimation_flip.rawlog \
  rawlog_sf_actionflip.rawlog rawlog_N_2p28_membomb.rawlog; do
  bad "$R/$f" -- "$B/gv-em-slam" --input "$R/$f" --out out --quiet
done
for f in gvmap_amplify_100vec.gvmap gvmap_flip_no_trailer.gvmap; do
  bad "$R/$f" -- "$B/gv-map-info" "$R/$f"
done
for f in config_grid_res_1e-300.ini config_grid_res_1e-6.ini config_occ_res_1e-3.ini config_matcher_maxiter_2p31.ini \
  config_line_without_equals.ini; do
  bad "$R/$f" -- "$B/gv-em-slam" --input LOG.log --out out --config "$R/$f" --quiet
  bad "$R/$f" -- "$B/gv-config" --check "$R/$f"
done

# the valid one: a pipe as --input reads every byte (the gzip sniff took the first 8 KiB, 8 of 11 scans)
f=pipe_drops_8k.log
"$B/gv-map" --input "$R/$f" --poses log --out file --quiet
cat "$R/$f" | "$B/gv-map" --input /dev/stdin --poses log --out pipe --quiet
cmp file/vectors.txt pipe/vectors.txt || fail "$f through a pipe maps differently from the file"
"$B/gv-map" --input "$R/$f" --poses log --out fifo0 > summary.txt 2>&1
grep -q ": 11 of 11 scans mapped" summary.txt || fail "$f: not 11 scans: $(cat summary.txt)"
mkfifo fifo.log
( sleep 1; cat "$R/$f" > fifo.log ) &
"$B/gv-map" --input fifo.log --poses log --out fifo --quiet  # a writer that comes within the wait
wait
cmp file/vectors.txt fifo/vectors.txt || fail "$f through a FIFO maps differently from the file"
seen="$seen $f"
echo "$f: a pipe and a FIFO map as the file does (11 scans)"

# every file of the folder is covered above
for f in "$R"/*; do
  case "$(basename "$f")" in README.md) continue ;; esac
  case " $seen " in *" $(basename "$f") "*) ;; *) fail "$(basename "$f") has no case here" ;; esac
done

# the README's "also": /dev/zero as --input and --config, a FIFO with no writer, an endless line
bad /dev/zero -- "$B/gv-map" --input /dev/zero --poses log --out out --quiet
bad /dev/zero -- "$B/gv-em-slam" --input LOG.log --config /dev/zero --out out --quiet
bad /dev/zero -- "$B/gv-config" --check /dev/zero
mkfifo nowriter.log
bad nowriter.log -- "$B/gv-map" --input nowriter.log --poses log --out out --quiet
mkfifo nowriter.ini
bad nowriter.ini -- "$B/gv-config" --check nowriter.ini
{ head -c 5000000 /dev/zero | tr '\0' '1'; echo; } > longline.log
bad longline.log -- "$B/gv-em-slam" --input longline.log --out out --quiet
awk '!done && $1 == "FLASER" { $3 = "0x1p3"; done = 1 } { print }' LOG.log > hex.log
grep -q "0x1p3" hex.log || fail "hex.log: no hex float written"
bad hex.log -- "$B/gv-em-slam" --input hex.log --out out --quiet
echo "repro: $n cases OK"
