#!/usr/bin/env bash
# doc/parameters.md must list every parameter with its current default:
# its table is exactly what `gv-config --markdown` prints.
set -euo pipefail
doc="$GV_SOURCE_DIR/doc/parameters.md"
gen=$(mktemp); trap 'rm -f "$gen" "$gen.ini"' EXIT
# table_in_doc HEADER: the doc's table that starts with the line HEADER, up to the next blank line.
table_in_doc() { awk -v h="$1" '$0 == h {on = 1} on && /^$/ {exit} on {print}' "$doc"; }
"$GV_BIN/gv-config" --markdown > "$gen"
if ! diff <(table_in_doc "$(head -n 1 "$gen")") "$gen"; then
  echo "doc/parameters.md is out of date; regenerate its table with: gv-config --markdown"
  exit 1
fi
# The default .ini round-trips (gv-em-slam's measured defaults are the library's), and a typo is
# reported with file and key.
"$GV_BIN/gv-config" --ini > "$gen.ini"
"$GV_BIN/gv-config" --check "$gen.ini"
grep -qx "min_points = 3" "$gen.ini"
printf '[gridvector_grid]\nresolutoin = 0.05\n' > "$gen.ini"
if "$GV_BIN/gv-config" --check "$gen.ini" 2> err.txt; then echo "typo accepted"; exit 1; fi
grep -q "resolutoin" err.txt && grep -q "$gen.ini" err.txt
rm -f err.txt
echo "parameters doc is complete"
