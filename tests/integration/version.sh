#!/usr/bin/env bash
# --version of every tool: one line "TOOL (gridvector X.Y.Z, git DESCRIPTION, MRPT A.B.C)" on stdout, exit 0,
# the same description in each; gv-graphslam's MRPT-style command line too. The git description is
# "unknown" for a source tree outside git (a tarball): cmake/GitDescribe.cmake on a copy without .git.
set -euo pipefail
B="$GV_BIN"
fail() { echo "FAIL: $*" >&2; exit 1; }
version=$(sed -n 's/^project(gridvector VERSION \([0-9.]*\).*/\1/p' "$GV_SOURCE_DIR/CMakeLists.txt")
[ -n "$version" ] || fail "no project version in CMakeLists.txt"
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
first=""
tools=$(cd "$B" && ls gv-*)  # every tool the build made
[ "$(echo "$tools" | wc -w)" -ge 14 ] || fail "only $(echo "$tools" | wc -w) tools in $B"
for tool in $tools; do
  out=$("$B/$tool" --version 2> "$W/err") || fail "$tool --version: exit $?"
  [ ! -s "$W/err" ] || fail "$tool --version wrote to stderr: $(cat "$W/err")"
  [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || fail "$tool --version: not one line: $out"
  [[ "$out" =~ ^$tool\ \(gridvector\ $version,\ git\ ([^ ,]+),\ MRPT\ 2\.[0-9]+\.[0-9]+\)$ ]] ||
    fail "$tool --version: '$out'"
  rest=${out#"$tool" }; first=${first:-$rest}
  [ "$rest" = "$first" ] || fail "$tool: '$rest' vs '$first'"
  "$B/$tool" --help | grep -q -- "--version" || fail "$tool --help does not list --version"
done
# a tarball: the source without .git
mkdir "$W/src" && cp "$GV_SOURCE_DIR/CMakeLists.txt" "$W/src/" && mkdir "$W/src/cmake" && cp "$GV_SOURCE_DIR/cmake/GitDescribe.cmake" "$W/src/cmake/"
d=$(GIT_CEILING_DIRECTORIES="$W" cmake -DGV_DESCRIBE_DIR="$W/src" -P "$W/src/cmake/GitDescribe.cmake" 2>&1)
[ "$d" = unknown ] || fail "outside git: '$d'"
# a clone (as CI builds): its git description
if command -v git > /dev/null && [ -e "$GV_SOURCE_DIR/.git" ]; then
  git clone -q "$GV_SOURCE_DIR" "$W/clone"
  d=$(cmake -DGV_DESCRIBE_DIR="$W/clone" -P "$GV_SOURCE_DIR/cmake/GitDescribe.cmake" 2>&1)
  [ "$d" = "$(git -C "$W/clone" describe --tags --always --dirty)" ] && [ "$d" != unknown ] || fail "in a clone: '$d'"
fi
echo "version: $(echo "$tools" | wc -w) tools OK"
