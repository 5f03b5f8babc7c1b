#!/usr/bin/env bash
# Installs gridvector's build and test dependencies from Debian's packages.
set -euo pipefail
# libopenblas0-serial: CHOLMOD's BLAS/LAPACK for the pose graph (about 2x less CPU at 5,000
# scans than the reference libblas3, doc/benchmarks-history.md "BLAS for CHOLMOD"); Debian's package
# makes itself libblas.so.3 / liblapack.so.3 through the alternatives (priority 90 > 10).
# nlohmann-json3-dev, libcli11-dev: header-only, the JSON outputs and the tools' command lines.
# strace: integration.output_sets traces each tool's writes to check its marker file is the last.
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
PKGS="build-essential cmake pkg-config libeigen3-dev libsuitesparse-dev libgtest-dev googletest
 libmrpt-maps-dev libmrpt-slam-dev libmrpt-graphslam-dev libmrpt-obs-dev libmrpt-gui-dev
 mrpt-apps mrpt-common python3 zlib1g-dev nlohmann-json3-dev libcli11-dev
 libopenblas0-serial strace"
missing=""
# installed, not merely known to dpkg (a removed package's config files keep `dpkg -s` at 0)
for p in $PKGS; do
  [ "$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null)" = installed ] || missing="$missing $p"
done
if [ -n "$missing" ]; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
fi
