#!/usr/bin/env bash
# Plug-in proof: MRPT's own, unmodified icp-slam builds a CGridVectorMap when
# libgridvector.so is preloaded and the .ini declares gridVectorMap_count=1: the README's
# LD_PRELOAD line, by the installed path of a fresh `cmake --install`.
set -euo pipefail
RAWLOG="$GV_MRPT_DATASETS/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"
command -v icp-slam >/dev/null || { echo "icp-slam not installed (mrpt-apps)"; exit 1; }
[ -f "$RAWLOG" ] || { echo "$RAWLOG missing (mrpt-common)"; exit 1; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cmake --install "$(dirname "$GV_BIN")" --prefix "$work/prefix" > "$work/install.log"
LIB="$work/prefix/lib/libgridvector.so"
INI="$work/prefix/share/gridvector/icp-slam-gridvector.ini"
[ -e "$LIB" ] && [ -e "$INI" ] || { echo "not installed: $LIB or $INI"; exit 1; }
cd "$work"
# GV_SANITIZER_PRELOAD (share/scripts/sanitize.sh): the ASan/UBSan runtimes, which must come first
LD_PRELOAD="${GV_SANITIZER_PRELOAD:+$GV_SANITIZER_PRELOAD:}$LIB" icp-slam "$INI" "$RAWLOG" > icp.log 2>&1 || { tail -20 icp.log; exit 1; }
# a preload the loader cannot find is only a warning of ld.so's, and icp-slam runs without the map
! grep -q "ld.so" icp.log || { grep "ld.so" icp.log; exit 1; }
vec=$(ls LOG_ICP-SLAM-GV/*CGridVectorMap*_vectors.txt)
rows=$(grep -vc '^#' "$vec")
echo "icp-slam wrote $rows grid vectors to $(basename "$vec")"
[ "$rows" -ge 20 ] || { echo "too few vectors: $rows"; exit 1; }
# Every row: 4 coordinates and p_static in [0,1].
awk '!/^#/ { if (NF != 5 || $5 < 0 || $5 > 1) { print "bad row: " $0; exit 1 } }' "$vec"
# The simplemap icp-slam saved rebuilds a CGridVectorMap that serializes and loads back.
"$GV_BIN/gv-map-info" --from-simplemap LOG_ICP-SLAM-GV/_finalmap_.simplemap --save rebuilt.gvmap | tee info1.txt
"$GV_BIN/gv-map-info" rebuilt.gvmap | tee info2.txt
n1=$(sed -E 's/^CGridVectorMap: ([0-9]+) grid vectors.*/\1/' info1.txt)
n2=$(sed -E 's/^CGridVectorMap: ([0-9]+) grid vectors.*/\1/' info2.txt)
[ "$n1" -ge 20 ] && [ "$n1" = "$n2" ] || { echo "vector counts differ or too few: $n1 vs $n2"; exit 1; }
# Bad input: a clear one-line error and a non-zero exit, never a crash.
head -c 100 rebuilt.gvmap > truncated.gvmap
if "$GV_BIN/gv-map-info" truncated.gvmap 2> err.txt; then echo "truncated file accepted"; exit 1; fi
grep -q "truncated.gvmap" err.txt && [ "$(wc -l < err.txt)" -eq 1 ] || { cat err.txt; exit 1; }
echo "plug-in test passed"
