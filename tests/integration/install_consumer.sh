#!/usr/bin/env bash
# `cmake --install` gives a usable package: an outside MRPT program built with
# find_package(gridvector) loads a map saved by the project and extends it.
set -euo pipefail
build_dir=$(dirname "$GV_BIN")
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
for f in lib/libgridvector.so include/mrpt/maps/CGridVectorMap.h include/gridvector/GridVector.h \
         bin/gv-map-info share/gridvector/icp-slam-gridvector.ini lib/cmake/gridvector/gridvectorConfig.cmake; do
  [ -e "$work/prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
cmake -S "$GV_SOURCE_DIR/doc/examples/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_BUILD_TYPE=Release > "$work/cfg.log" || { cat "$work/cfg.log"; exit 1; }
cmake --build "$work/consumer" > "$work/build.log" || { tail -30 "$work/build.log"; exit 1; }
# A map saved by the project: rebuilt from MRPT's own sample simplemap.
sm="$GV_MRPT_DATASETS/localization_demo.simplemap.gz"
"$GV_BIN/gv-map-info" --from-simplemap "$sm" --save "$work/demo.gvmap"
LD_LIBRARY_PATH="$work/prefix/lib" "$work/consumer/gv-consumer" "$work/demo.gvmap" | tee "$work/out.txt"
grep -q "^CGridVectorMap: [1-9][0-9]* grid vectors" "$work/out.txt"
# ... and localises the scan it inserted against the map with MRPT's ICP (CICP on the grid-vector map)
grep -q "^ICP: pose \[" "$work/out.txt"
