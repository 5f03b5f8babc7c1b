#!/usr/bin/env bash
# Installs gridvector's build and test dependencies from Debian's packages.
set -euo pipefail
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
PKGS="build-essential cmake pkg-config libeigen3-dev libsuitesparse-dev libgtest-dev googletest
 libmrpt-maps-dev libmrpt-slam-dev libmrpt-graphslam-dev libmrpt-obs-dev libmrpt-gui-dev
 mrpt-apps mrpt-common python3 zlib1g-dev"
missing=""
for p in $PKGS; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
if [ -n "$missing" ]; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
fi
