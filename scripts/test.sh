#!/usr/bin/env bash
# Configure, build (2 jobs) and run every test through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
BUILD=${BUILD_DIR:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" -j 2
cd "$BUILD" && ctest --output-on-failure -j 2
