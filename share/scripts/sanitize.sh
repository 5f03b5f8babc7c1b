#!/usr/bin/env bash
# The whole CTest under AddressSanitizer + UndefinedBehaviorSanitizer (our code instrumented; MRPT,
# Eigen's compiled parts and libstdc++ are not). Not part of .ci/run (CI time budget).
# Arguments go to ctest (e.g. -R bad_input).
#   bash share/scripts/sanitize.sh                 # configure + build build-asan/, run every test
#   BUILD_DIR=/tmp/asan bash share/scripts/sanitize.sh -R 'integration\.'
# A finding fails the test that triggers it (halt_on_error; a leak makes the process exit non-zero).
# Suppressions (share/sanitizers/*.supp) name only frames inside MRPT/Eigen/libstdc++, each with why.
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD=${BUILD_DIR:-build-asan}
F="-fsanitize=address,undefined -fno-omit-frame-pointer"
# -O1 -g1: line numbers in the reports, and far quicker to compile than -O2 -g (session 10: the
# library alone at 15 % after 22 min with -O2 -g; library and apps in ~25 min with -O1 -g1, load 6-13)
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_CXX_FLAGS="$F" \
  -DCMAKE_EXE_LINKER_FLAGS="$F" -DCMAKE_SHARED_LINKER_FLAGS="$F" >/dev/null
cmake --build "$BUILD" -j 2
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$ROOT/share/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$ROOT/share/sanitizers/ubsan.supp"
# MRPT's uninstrumented icp-slam loads the instrumented libgridvector.so (icp_slam_plugin.sh): the
# runtimes go first; the installed-package consumer (install_consumer.sh) is compiled with the flags.
export GV_SANITIZER_PRELOAD="$(g++ -print-file-name=libasan.so):$(g++ -print-file-name=libubsan.so)"
export CXXFLAGS="$F" LDFLAGS="$F"
export GV_SANITIZED=1  # integration.real_logs drops its 4 GB address-space cap (ASan's shadow needs ~16 TB)
cd "$BUILD" && ctest --output-on-failure -j 2 "$@"
