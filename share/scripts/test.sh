#!/usr/bin/env bash
# Configure, build (2 jobs) and run every test through CTest (arguments go to ctest, e.g. -R integration).
set -euo pipefail
cd "$(dirname "$0")/../.."
bash share/scripts/install-deps.sh
BUILD=${BUILD_DIR:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j 2
cd "$BUILD" && ctest --output-on-failure -j 2 "$@"
