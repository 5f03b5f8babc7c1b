#!/usr/bin/env bash
# --quiet and progress: the long-running tools draw progress (scans done / total, iteration, ETA)
# on stderr only when it is a terminal (here a pseudo-terminal made by script(1)), never into a
# file or pipe, and with --quiet print nothing but errors: gv-em-slam, gv-map, gv-sim,
# gv-graphslam and gv-carmen2rawlog nothing at all, the benchmarks only their figures on stdout.
set -euo pipefail
: "${GV_BIN:?}" "${GV_SOURCE_DIR:?}" "${GV_SHARED_DIR:?}"
B="$GV_BIN"
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
cd "$W"
fail() { echo "FAIL: $*" >&2; exit 1; }
INI="$GV_SOURCE_DIR/share/gridvector/graphslam-gridvector.ini"
"$B/gv-sim" --world office --seed 1 --scans 40 --out sim --quiet
"$B/gv-carmen2rawlog" sim/sim.log sim.rawlog --quiet
# name|command (each run of a tool rewrites the same outputs)
tools=(
  "gv-em-slam|$B/gv-em-slam --input sim/sim.log --out em --max-iterations 2"
  "gv-map|$B/gv-map --input sim/sim.log --poses sim/truth_trajectory.txt --out map"
  "gv-sim|$B/gv-sim --world office --seed 2 --scans 20 --out s2"
  "gv-graphslam|$B/gv-graphslam --2d -i $INI -r sim.rawlog --disable-visuals --output-dir gs"
  "gv-carmen2rawlog|$B/gv-carmen2rawlog $GV_SHARED_DIR/data/aces-corrected.log.gz c.rawlog"  # progress every 4096 lines
  "gv-bench-extract|$B/gv-bench-extract sim/sim.log --repeat 2"
  "gv-bench-wipe|$B/gv-bench-wipe sim/sim.log sim/truth_trajectory.txt --repeat 2"
  "gv-bench-map|$B/gv-bench-map sim/sim.log --max-scans 30"
  "gv-bench-icp|$B/gv-bench-icp sim/sim.log sim/truth_trajectory.txt --every 4"
)
for entry in "${tools[@]}"; do
  name=${entry%%|*}; cmd=${entry#*|}
  run() { echo "$cmd $*"; }
  # --quiet, into files: nothing on stderr; nothing on stdout but a benchmark's figures
  $(run --quiet) > out.txt 2> err.txt || fail "$name --quiet: exit $?: $(cat err.txt)"
  [ ! -s err.txt ] || fail "$name --quiet wrote to stderr: $(head -c 300 err.txt)"
  case $name in gv-bench-*) [ -s out.txt ] || fail "$name --quiet: no figures" ;;
                 *) [ ! -s out.txt ] || fail "$name --quiet wrote to stdout: $(head -c 300 out.txt)" ;; esac
  # not quiet, into files: no progress drawing (no terminal)
  $(run) > out.txt 2> err.txt || fail "$name: exit $?: $(cat err.txt)"
  ! grep -q $'\e\[K' out.txt err.txt || fail "$name: progress drawn into a file"
  # on a terminal: progress (a line redrawn with ESC[K, a percentage) unless --quiet
  script -qefc "$(run)" /dev/null < /dev/null > tty.txt || fail "$name on a terminal: exit $?"
  grep -q $'\e\[K.*%' tty.txt || fail "$name: no progress on a terminal: $(head -c 300 tty.txt | cat -v)"
  script -qefc "$(run --quiet)" /dev/null < /dev/null > tty.txt || fail "$name --quiet on a terminal: exit $?"
  ! grep -q $'\e\[K' tty.txt || fail "$name --quiet: progress on a terminal"
  case $name in gv-bench-*) ;; *) [ ! -s tty.txt ] || fail "$name --quiet printed on a terminal: $(head -c 300 tty.txt | cat -v)" ;; esac
done
echo "quiet: ${#tools[@]} tools OK"
