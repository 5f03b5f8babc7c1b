#!/usr/bin/env bash
# The subprocess sample of the reader fuzzing (tests/reader_fuzz_test.cpp fuzzes 12000 inputs in
# process): mutated CARMEN logs, rawlogs, .gvmap and .ini files (seeded; extreme values, corrupt
# length fields, byte flips, truncations) through the real tools. Each run: exit 0, or exit 1-127
# with one stderr line "TOOL: FILE: problem" naming the file; no signal, no hang (60 s), peak RSS
# under 500 MB. GV_FUZZ_TOOL_INPUTS (default 8 per format) and GV_FUZZ_SEED set the sample.
set -euo pipefail
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
cd "$W"
B="$GV_BIN"
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v /usr/bin/time > /dev/null || fail "/usr/bin/time (GNU time) is needed to measure peak RSS"
PER=${GV_FUZZ_TOOL_INPUTS:-8} SEED=${GV_FUZZ_SEED:-1}
awk 'BEGIN { pi = atan2(0, -1); print "PARAM robot_front_laser_max 50";
  for (t = 0; t < 12; t++) { x = -2 + 0.15 * t; y = 0.3 * sin(t / 5); th = 0.12 * t; line = "FLASER 181";
    for (i = 0; i < 181; i++) { a = th - pi / 2 + pi * i / 180; dx = cos(a); dy = sin(a); r = 1e9;
      if (dx > 1e-9) r = (4 - x) / dx < r ? (4 - x) / dx : r; if (dx < -1e-9) r = (-4 - x) / dx < r ? (-4 - x) / dx : r;
      if (dy > 1e-9) r = (3 - y) / dy < r ? (3 - y) / dy : r; if (dy < -1e-9) r = (-3 - y) / dy < r ? (-3 - y) / dy : r;
      line = line sprintf(" %.3f", r); }
    ts = 1000 + 0.2 * t;
    printf "%s %.4f %.4f %.4f %.4f %.4f %.4f %.6f sim %.6f\n", line, x, y, th, x, y, th, ts, ts; } }' > seed.log
"$B/gv-carmen2rawlog" seed.log seed.rawlog --quiet --no-compress --format sf
"$B/gv-map" --input seed.log --poses log --out seedmap --quiet
"$B/gv-config" --ini > seed.ini
python3 - "$PER" "$SEED" <<'EOF'
import gzip, random, struct, sys
per, seed = int(sys.argv[1]), int(sys.argv[2])
r = random.Random(seed)
tokens = [b"0", b"-1", b"1e300", b"-1e308", b"1e-300", b"nan", b"inf", b"2147483648", b"1073741824", b"100001",
          b"0x1p3", b"1e6", b"1e15", b"", b"6.2832"]
u32 = [0, 1, 0x7fffffff, 0xffffffff, 1 << 30, 1 << 28, 100001, 0x7fc00000, 0x7f800000]
def text(d):
    d = bytearray(d)
    for _ in range(1 + r.randrange(3)):
        k = r.randrange(4); i = r.randrange(len(d))
        if k == 0:  # a token becomes an extreme value
            b = max(d.rfind(b" ", 0, i), d.rfind(b"\n", 0, i), d.rfind(b"=", 0, i)) + 1
            e = min([x for x in (d.find(b" ", i), d.find(b"\n", i)) if x >= 0] or [len(d)])
            d[b:e] = r.choice(tokens)
        elif k == 1: d[i] = r.randrange(256)
        elif k == 2: del d[i:]
        else: d[i:i] = bytes([r.randrange(256)] * (1 + r.randrange(8)))
        if not d: break
    return bytes(d)
def binary(d):
    d = bytearray(d)
    for _ in range(1 + r.randrange(2)):
        k = r.randrange(4); i = r.randrange(len(d) - 8)
        if k == 0:  # a length field: a small count becomes an extreme value
            for _ in range(64):
                p = r.randrange(len(d) - 4)
                if 1 <= struct.unpack_from("<I", d, p)[0] <= 100000:
                    struct.pack_into("<I", d, p, r.choice(u32)); break
        elif k == 1: struct.pack_into("<d", d, i, r.choice([float("nan"), float("inf"), 1e308, 1e15, -1.0]))
        elif k == 2: d[i] ^= 1 << r.randrange(8)
        else: del d[i:]
        if len(d) < 16: break
    return bytes(d)
log, raw, ini = open("seed.log", "rb").read(), open("seed.rawlog", "rb").read(), open("seed.ini", "rb").read()
gvmap = gzip.decompress(open("seedmap/map.gvmap", "rb").read())
for n in range(per):
    open(f"m{n}.log", "wb").write(text(log))
    open(f"m{n}.rawlog", "wb").write(binary(raw))
    open(f"m{n}.gvmap", "wb").write(gzip.compress(binary(gvmap)) if n % 2 else binary(gzip.compress(gvmap)))
    open(f"m{n}.ini", "wb").write(text(ini))
EOF
runs=0 rejected=0
run() {
  local file=$1; shift
  set +e
  ( ulimit -v 4000000; timeout 60 /usr/bin/time -f "%M" -o rss.txt "$@" > out.txt 2> err.txt )
  local rc=$?
  set -e
  [ "$rc" -ne 124 ] || fail "hang (60 s) for: $*"
  [ "$rc" -lt 128 ] || fail "signal (exit $rc) for: $* -> $(head -c 300 err.txt)"
  [ "$(tail -1 rss.txt)" -lt 512000 ] || fail "peak RSS $(tail -1 rss.txt) KB for: $*"
  runs=$((runs + 1))
  [ "$rc" -ne 0 ] || return 0
  rejected=$((rejected + 1))
  [ "$(grep -c . err.txt)" -eq 1 ] || fail "not one line for: $* -> $(head -c 600 err.txt)"
  grep -q "^$(basename "$1"): $file" err.txt || fail "not 'TOOL: $file...' for: $* -> $(cat err.txt)"
}
for ((n = 0; n < PER; n++)); do
  run "m$n.log" "$B/gv-map" --input "m$n.log" --poses log --out "o$n" --quiet
  run "m$n.rawlog" "$B/gv-bench-extract" "m$n.rawlog" --repeat 1
  run "m$n.gvmap" "$B/gv-map-info" "m$n.gvmap"
  run "m$n.ini" "$B/gv-config" --check "m$n.ini"
done
echo "fuzz_tools: $runs mutated inputs through gv-map, gv-bench-extract, gv-map-info and gv-config (seed $SEED): $rejected rejected with one line, none crashed or hung"
