#!/usr/bin/env bash
# --help of every tool, checked mechanically: every option listed is accepted (a value option
# given without its value is "needs a value", a flag given a value is "takes no value", never
# "unknown option"), every value option states its default or "(required)", and nothing the
# parser accepts is missing (io::ArgParser prints its own option table; --help, --version listed).
set -euo pipefail
: "${GV_BIN:?}"
python3 - "$GV_BIN" <<'PY'
import re, subprocess, sys
bin = sys.argv[1]
tools = ["gv-em-slam", "gv-map", "gv-sim", "gv-eval", "gv-carmen2rawlog", "gv-bench-log", "gv-graphslam",
         "gv-map-info", "gv-config", "gv-bench-extract", "gv-bench-wipe", "gv-bench-map", "gv-bench-icp"]
def run(tool, *args):
    p = subprocess.run([f"{bin}/{tool}", *args], capture_output=True, text=True, timeout=60, stdin=subprocess.DEVNULL)
    return p.returncode, p.stdout, p.stderr
bad = []
options = 0
for tool in tools:
    rc, out, err = run(tool, "--help")
    if rc != 0 or err: bad.append(f"{tool} --help: exit {rc}, stderr {err!r}"); continue
    lines = out.split("\n")
    if not lines[0].startswith(f"usage: {tool} "): bad.append(f"{tool}: first line {lines[0]!r}")
    listed = {}
    for i, line in enumerate(lines):
        if not line.startswith("  --"): continue
        # io::ArgParser's table: "  --name [VALUE]" padded to 26 columns, then the help; a longer
        # left part stands alone and the help follows on the next line
        alone = i + 1 < len(lines) and lines[i + 1].startswith(" " * 26) and lines[i + 1].strip()
        left, text = (line, lines[i + 1].strip()) if alone else (line[:26], line[26:].strip())
        words = left.split()
        listed[words[0][2:]] = (len(words) > 1, text)
    for must in ("help", "version"):
        if must not in listed: bad.append(f"{tool}: --{must} not listed")
    for name, (takes_value, text) in listed.items():
        options += 1
        if takes_value:
            if not re.search(r"\((default: \S.*|required)\)$", text): bad.append(f"{tool} --{name}: no default in {text!r}")
            rc, _, err = run(tool, f"--{name}")
            want = f"{tool}: option --{name} needs a value"
        else:
            if "(default:" in text: bad.append(f"{tool} --{name}: a flag with a default: {text!r}")
            rc, _, err = run(tool, f"--{name}=x")
            want = f"{tool}: option --{name} takes no value"
        if rc != 2 or not err.startswith(want): bad.append(f"{tool} --{name}: listed but not accepted as listed: exit {rc}, {err.strip()!r}")
    rc, _, err = run(tool, "--no-such-option")
    if rc != 2 or "unknown option --no-such-option" not in err: bad.append(f"{tool}: an unlisted option: exit {rc}, {err.strip()!r}")
if bad:
    print("FAIL:\n" + "\n".join(bad), file=sys.stderr); sys.exit(1)
print(f"help: {len(tools)} tools, {options} options OK")
PY
