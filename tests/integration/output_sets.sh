#!/usr/bin/env bash
# Output sets (doc/io.md, "Output sets"): each tool writes its marker file last (gv-em-slam
# report.json, gv-map memory.json, gv-sim sim_info.txt, gv-graphslam trajectory.txt) and removes a
# previous run's marker before rewriting anything, so a run into an existing directory that fails
# halfway leaves no marker: never a mixed set that looks complete. The failure is injected after
# some outputs: a directory where a later output file must go.
set -euo pipefail
: "${GV_BIN:?}" "${GV_SOURCE_DIR:?}"
B="$GV_BIN"
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
cd "$W"
fail() { echo "FAIL: $*" >&2; exit 1; }
"$B/gv-sim" --world office --seed 1 --scans 60 --out sim --quiet
"$B/gv-carmen2rawlog" sim/sim.log sim.rawlog --quiet

# check TOOL DIR MARKER LATER EARLIER -- command...: a first run makes a complete set (the marker
# newest of all files); then LATER is replaced by a directory and the run repeated: it fails naming
# LATER, EARLIER (written before LATER) is rewritten, and the old marker is gone
# With strace (if ptrace is allowed) the first run's writes and renames are traced (-y: each fd's
# path) and the last one into DIR must be the marker's: file times alone miss a write in the same
# clock tick (MRPT's graphslam engine flushed timings.log after gv-graphslam's marker, which the
# times showed only when the two fell in different ticks).
STRACE=0
if command -v strace > /dev/null && strace -f -qq -o /dev/null true 2> /dev/null; then STRACE=1; fi
check() {
  local tool=$1 dir=$2 marker=$3 later=$4 earlier=$5; shift 6
  if [ "$STRACE" = 1 ]; then
    # LeakSanitizer cannot run under ptrace (sanitize.sh's build): no leak check in the traced run;
    # the second run below, untraced, still has it
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
      strace -f -qq -y -e trace=write,pwrite64,writev,rename,renameat,renameat2 -o trace.txt "$@" > /dev/null 2>&1 ||
      fail "$tool: first run failed"
    local last
    last=$(grep -E "/$dir/[^>]*>|\"$dir/" trace.txt | tail -n 1 | cut -c1-200)
    echo "$last" | grep -qE "rename.*\"$dir/$marker\"" || fail "$tool: the last write into $dir is not $marker's rename: $last"
  else
    "$@" > /dev/null 2>&1 || fail "$tool: first run failed"
  fi
  [ -s "$dir/$marker" ] || fail "$tool: no $marker after a complete run"
  [ -z "$(find "$dir" -maxdepth 1 -type f -newer "$dir/$marker")" ] || fail "$tool: files written after $marker: $(find "$dir" -maxdepth 1 -type f -newer "$dir/$marker")"
  sleep 1.1; touch -d '-1 hour' "$dir/$earlier"
  rm -f "$dir/$later"; mkdir "$dir/$later"
  set +e; "$@" > out.txt 2> err.txt; local rc=$?; set -e
  [ "$rc" -eq 1 ] || fail "$tool: exit $rc with $later a directory: $(cat err.txt)"
  grep -q "^$tool: .*$later: cannot write" err.txt || fail "$tool: error does not name $later: $(cat err.txt)"
  [ -n "$(find "$dir/$earlier" -newermt '-10 minutes')" ] || fail "$tool: $earlier was not rewritten: the failure is not after some outputs"
  [ ! -e "$dir/$marker" ] || fail "$tool: a previous run's $marker left next to a half-rewritten set"
  ! find "$dir" -name '*.tmp*' | grep -q . || fail "$tool: temporary files left"
}
check gv-em-slam em report.json occupancy.png vectors.txt -- "$B/gv-em-slam" --input sim/sim.log --out em --quiet --max-iterations 2
check gv-map map memory.json occupancy.yaml map.gvmap -- "$B/gv-map" --input sim/sim.log --poses sim/truth_trajectory.txt --out map --quiet
check gv-sim s2 sim_info.txt truth_dynamic.txt sim.log -- "$B/gv-sim" --world office --seed 2 --scans 30 --out s2 --quiet
check gv-graphslam gs trajectory.txt vectors.svg nodes.txt -- "$B/gv-graphslam" --2d -i "$GV_SOURCE_DIR/share/gridvector/graphslam-gridvector.ini" \
  -r sim.rawlog --disable-visuals --output-dir gs --quiet
echo "output_sets: 4 tools OK (write order traced: $([ "$STRACE" = 1 ] && echo yes || echo "no, strace unavailable"))"

# --- a full disk: writes that fail part-way (EFBIG under a file-size limit, ENOSPC on a small
# tmpfs) never leave a truncated file under a target's name, never a marker, never touch a
# previous good file, and the tool says so in one line and exits 1 ---
"$B/gv-map-info" --from-simplemap "${GV_MRPT_DATASETS:-/usr/share/mrpt/datasets}/localization_demo.simplemap.gz" \
  --save good.gvmap > /dev/null
"$B/gv-carmen2rawlog" sim/sim.log good.rawlog --quiet
limited() {  # limited KB cmd...: cmd under a file-size limit, SIGXFSZ ignored (writes fail with EFBIG)
  local kb=$1; shift
  ( trap '' XFSZ; ulimit -f "$kb"; exec "$@" )
}
full_disk() {  # full_disk TOOL TARGET KB -- cmd...: the run fails, TARGET keeps its previous bytes
  local tool=$1 target=$2 kb=$3; shift 4
  local before; before=$(md5sum < "$target")
  set +e; "$@" > out.txt 2> err.txt; local rc=$?; set -e
  [ "$rc" -eq 1 ] || fail "$tool on a full disk ($kb KB): exit $rc: $(cat err.txt)"
  [ "$(grep -c . err.txt)" -eq 1 ] && grep -q "^$tool: .*cannot write" err.txt ||
    fail "$tool on a full disk: not one 'cannot write' line: $(cat err.txt)"
  [ "$(md5sum < "$target")" = "$before" ] || fail "$tool on a full disk: the previous $target was damaged"
  ! find . -maxdepth 2 -name '.*.tmp*' | grep -q . || fail "$tool on a full disk: temporary files left"
}
cp good.gvmap prev.gvmap; cp good.rawlog prev.rawlog
full_disk gv-map-info prev.gvmap 8 -- limited 8 "$B/gv-map-info" good.gvmap --save prev.gvmap
full_disk gv-carmen2rawlog prev.rawlog 8 -- limited 8 "$B/gv-carmen2rawlog" sim/sim.log prev.rawlog --quiet
full_disk gv-carmen2rawlog prev.rawlog 8 -- limited 8 "$B/gv-carmen2rawlog" sim/sim.log prev.rawlog --quiet --no-compress
# a new file under a limit: no file at all
set +e; limited 8 "$B/gv-map-info" good.gvmap --save new.gvmap 2> err.txt; rc=$?; set -e
[ "$rc" -eq 1 ] && [ ! -e new.gvmap ] || fail "gv-map-info --save on a full disk: exit $rc, new.gvmap $(ls new.gvmap 2>&1)"
# output sets: a complete previous set, then a run that runs out of space: no marker, every file
# still there whole (its gzip files intact), no temporary file
sets_full_disk() {  # TOOL DIR MARKER KB -- cmd...
  local tool=$1 dir=$2 marker=$3 kb=$4; shift 5
  "$@" > /dev/null 2>&1 || fail "$tool: first run failed"
  [ -e "$dir/$marker" ] || fail "$tool: no $marker"
  set +e; limited "$kb" "$@" > out.txt 2> err.txt; local rc=$?; set -e
  [ "$rc" -eq 1 ] || fail "$tool on a full disk ($kb KB): exit $rc: $(cat err.txt)"
  grep -q "^$tool: .*cannot write" err.txt || fail "$tool on a full disk: no 'cannot write': $(cat err.txt)"
  [ ! -e "$dir/$marker" ] || fail "$tool on a full disk: $marker next to an incomplete set"
  ! find "$dir" -name '.*.tmp*' | grep -q . || fail "$tool on a full disk: temporary files left"
  for f in "$dir"/*.gvmap "$dir"/*.3Dscene; do
    [ -e "$f" ] || continue
    gzip -t "$f" 2> /dev/null || fail "$tool on a full disk: $f truncated"
  done
}
sets_full_disk gv-map fmap memory.json 4 -- "$B/gv-map" --input sim/sim.log --poses sim/truth_trajectory.txt --out fmap --quiet
sets_full_disk gv-em-slam fem report.json 4 -- "$B/gv-em-slam" --input sim/sim.log --out fem --quiet --max-iterations 2
sets_full_disk gv-graphslam fgs trajectory.txt 4 -- "$B/gv-graphslam" --2d -i "$GV_SOURCE_DIR/share/gridvector/graphslam-gridvector.ini" \
  -r sim.rawlog --disable-visuals --output-dir fgs --quiet
# the same on a real full disk: a 256 KB tmpfs, where mounting is allowed (root in a private mount namespace)
TMPFS=skipped
if unshare -m true 2> /dev/null; then
  cp good.gvmap "$W/tfs-prev.gvmap"
  if unshare -m bash -c "mkdir -p '$W/tfs' && mount -t tmpfs -o size=256k tmpfs '$W/tfs' 2> /dev/null || exit 77
    cp '$W/tfs-prev.gvmap' '$W/tfs/prev.gvmap'; head -c 200k /dev/zero > '$W/tfs/filler' 2> /dev/null || true
    before=\$(md5sum < '$W/tfs/prev.gvmap')
    '$B/gv-map-info' '$W/good.gvmap' --save '$W/tfs/prev.gvmap' 2> '$W/tfs-err.txt' && exit 1
    grep -q 'cannot write' '$W/tfs-err.txt' || exit 2
    [ \"\$(md5sum < '$W/tfs/prev.gvmap')\" = \"\$before\" ] || exit 3
    ! ls -a '$W/tfs' | grep -q tmp || exit 4"; then TMPFS=yes
  else
    rc=$?; [ "$rc" -eq 77 ] || fail "full tmpfs: gv-map-info --save check $rc failed: $(cat "$W/tfs-err.txt" 2> /dev/null)"
  fi
fi
# an unwritable directory (as an unprivileged user when run as root: root writes anywhere)
as_user() { if [ "$(id -u)" = 0 ]; then setpriv --reuid=65534 --regid=65534 --clear-groups "$@"; else "$@"; fi; }
mkdir ro; cp good.gvmap ro/prev.gvmap; chmod 555 ro; chmod 755 "$W"; chmod 644 good.gvmap
set +e; as_user "$B/gv-map-info" good.gvmap --save ro/prev.gvmap 2> err.txt; rc=$?; set -e
[ "$rc" -eq 1 ] && grep -q "ro/prev.gvmap: cannot write" err.txt || fail "unwritable directory: exit $rc: $(cat err.txt)"
cmp -s good.gvmap ro/prev.gvmap || fail "unwritable directory: prev.gvmap changed"
chmod 755 ro
echo "output_sets: full disk (file-size limit; tmpfs $TMPFS) and unwritable directory OK"
