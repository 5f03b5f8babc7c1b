#!/usr/bin/env bash
# Session 14, self-check (issue 21, item 3): gv-em-slam on good and broken inputs; per run the
# trajectory's and the raw odometry's scores (evaltraj.py) beside every self-check signal of report.json.
#   run_table.sh BIN_DIR WORK_DIR NAME:LOG:REF [NAME:LOG:REF ...]  >> table.tsv
# The odometry is scored from GV_EM_DEBUG_DIR's traj_0.txt (gv-em-slam's start).
set -uo pipefail
bin=$1 work=$2; shift 2
ev=/work/shared/bench/evaltraj.py
field() { sed -n "s/.*$1=\([^ ]*\).*/\1/p"; }
for spec in "$@"; do
  IFS=: read -r name log ref <<< "$spec"
  out=$work/$name; rm -rf "$out"; mkdir -p "$out/dbg"
  LD_LIBRARY_PATH=$bin GV_EM_DEBUG_DIR=$out/dbg "$bin/gv-em-slam" --input "$log" --out "$out/em" --quiet 2> "$out/stderr.txt"
  rc=$?
  est=$(python3 $ev "$out/em/trajectory.txt" "$ref" | tr '\n' ' ')
  odo=$(python3 $ev "$out/dbg/traj_0.txt" "$ref" | tr '\n' ' ')
  sc=$(python3 - "$out/em/report.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["self_check"]
g = s["graph"]
chi = s["normalised_chi2"]
print("\t".join(str(x) for x in [s["verdict"], int(s["converged"]), s["iterations"], "%.4f" % s["failed_share"],
      "%.4f" % s["rejected_share"], "nan" if chi is None else "%.3f" % chi,
      "%.3f" % (g["odometry_chi2"] / max(1, g["odometry_dof"])), "%.3f" % (g["registration_chi2"] / max(1, g["registration_dof"])),
      g["downweighted"], "%.4f" % s["through_wall_share"], "|".join(s["reasons"])]))
PY
)
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$rc" "$(echo "$est" | field rel_loop_t_m)" "$(echo "$est" | field ate_rmse_m)" \
    "$(echo "$odo" | field rel_loop_t_m)" "$(echo "$odo" | field ate_rmse_m)" "$sc"
done
