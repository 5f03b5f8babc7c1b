#!/usr/bin/env bash
# `cmake --install` gives a usable package: an outside MRPT program built with
# find_package(gridvector) loads a map saved by the project and extends it.
set -euo pipefail
build_dir=$(dirname "$GV_BIN")
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
for f in lib/libgridvector.so lib/libgridvector-graphslam.so include/mrpt/maps/CGridVectorMap.h include/gridvector/GridVector.h \
         bin/gv-map-info share/gridvector/icp-slam-gridvector.ini lib/cmake/gridvector/gridvectorConfig.cmake; do
  [ -e "$work/prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
# Only the public API is installed (doc/architecture.md): the internals stay in the source tree.
(cd "$work/prefix/include" && find . -name '*.h' | sort) > "$work/headers.txt"
(cd "$GV_SOURCE_DIR/libgridvector/include" && find . -name '*.h' | sort) | diff - "$work/headers.txt" \
  || { echo "installed headers differ from libgridvector/include"; exit 1; }
! grep -q 'GlobalMap.h\|MStep.h\|ArgParser.h' "$work/headers.txt" || { echo "an internal header is installed"; exit 1; }
# Every installed header compiles on its own (it includes no internal header).
while read -r h; do
  echo "#include \"${h#./}\"" > "$work/one.cpp"
  c++ -std=c++17 -fsyntax-only -I"$work/prefix/include" $(find /usr/include/mrpt -maxdepth 2 -name include -type d -printf '-isystem %p ') \
      -isystem /usr/include/eigen3 -isystem /usr/include/suitesparse "$work/one.cpp" || { echo "installed header $h does not compile alone"; exit 1; }
done < "$work/headers.txt"
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
# A program that creates the map only through an .ini (no gridvector symbol referenced), linked
# with --as-needed as Debian's and Ubuntu's toolchains may: the map type is still registered.
cmake -S "$GV_SOURCE_DIR/doc/examples/ini-consumer" -B "$work/ini-consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXE_LINKER_FLAGS=-Wl,--as-needed > "$work/icfg.log" || { cat "$work/icfg.log"; exit 1; }
cmake --build "$work/ini-consumer" > "$work/ibuild.log" || { tail -30 "$work/ibuild.log"; exit 1; }
LD_LIBRARY_PATH="$work/prefix/lib" "$work/ini-consumer/gv-ini-consumer" | tee "$work/iout.txt"
grep -q "^1 map(s): mrpt::maps::CGridVectorMap" "$work/iout.txt"
# The README's C++ snippets compile as shown against the install: their own #include lines and nothing
# else of ours; the variables they use are the reader's, declared by the wrapper.
# readme_snippet MARKER NAME 'SIGNATURE' [TAIL]: the first ```cpp block after the line matching MARKER
readme_snippet() {
  awk -v m="$1" '$0 ~ m { on = 1 } on && /^```cpp$/ { code = 1; next } code && /^```$/ { exit } code { print }' \
    "$GV_SOURCE_DIR/README.md" > "$work/$2.txt"
  [ -s "$work/$2.txt" ] || { echo "README: no C++ block after '$1'"; exit 1; }
  {
    grep '^#include' "$work/$2.txt"
    echo '#include <mrpt/obs/CObservation2DRangeScan.h>'
    echo '#include <mrpt/poses/CPose3D.h>'
    echo 'template <class... T> void use(const T&...) {}'
    echo "void $2($3) {"
    grep -v '^#include' "$work/$2.txt"
    echo "${4:-} }"
  } > "$work/$2.cpp"
  c++ -std=c++17 -fsyntax-only -I"$work/prefix/include" $(find /usr/include/mrpt -maxdepth 2 -name include -type d -printf '-isystem %p ') \
      -isystem /usr/include/eigen3 "$work/$2.cpp" || { echo "the README's snippet after '$1' does not compile"; exit 1; }
}
readme_snippet '^On a robot' embed 'const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose3D& robotPose3D'
readme_snippet 'gridvector/OnlineEmSlam.h`, installed' online \
  'const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& odometryPose' 'use(step, grid);'
echo "install_consumer: OK (README snippets compile)"
