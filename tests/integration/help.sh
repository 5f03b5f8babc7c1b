#!/usr/bin/env bash
# --help of every tool, checked mechanically: every option listed is accepted, every value option
# states its default or "(required)", and nothing the parser accepts is missing (io::ArgParser prints
# its own option table from the specs it parses with; --help, --version listed).
# Four runs per tool (each start of a tool costs ~0.3 s of CPU loading MRPT's ~330 libraries):
# --help; every listed option at once, then an unlisted one, which must be the one refused (the
# parser reports unknown options before anything else, so each listed one was known); a value
# option without its value ("needs a value") and a flag given one ("takes no value"), which
# together with the shared spec table cover the arity of the others.
set -euo pipefail
: "${GV_BIN:?}"
python3 - "$GV_BIN" <<'PY'
import re, subprocess, sys
bin = sys.argv[1]
import os
# every tool the build made: a new one cannot be left out of the check
tools = sorted(t for t in os.listdir(bin) if t.startswith("gv-") and os.access(f"{bin}/{t}", os.X_OK))
if len(tools) < 14: sys.exit(f"FAIL: only {len(tools)} tools in {bin}")
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
    everything = []
    for name, (takes_value, text) in listed.items():
        options += 1
        if takes_value and not re.search(r"\((default: \S.*|required)\)$", text):
            bad.append(f"{tool} --{name}: no default in {text!r}")
        if not takes_value and "(default:" in text: bad.append(f"{tool} --{name}: a flag with a default: {text!r}")
        if name not in ("help", "version"): everything.append(f"--{name}=x" if takes_value else f"--{name}")
    rc, _, err = run(tool, *everything, "--no-such-option")
    if rc != 2 or not err.startswith(f"{tool}: unknown option --no-such-option"):
        bad.append(f"{tool}: every listed option and an unlisted one: exit {rc}, {err.strip()!r}")
    values = [n for n, (tv, _) in listed.items() if tv]
    flags = [n for n, (tv, _) in listed.items() if not tv and n not in ("help", "version")] or ["version"]
    for name, arg, want in ([(values[-1], f"--{values[-1]}", "needs a value")] if values else []) + \
                           [(flags[0], f"--{flags[0]}=x", "takes no value")]:
        rc, _, err = run(tool, arg)
        if rc != 2 or not err.startswith(f"{tool}: option --{name} {want}"):
            bad.append(f"{tool} --{name}: listed but not accepted as listed: exit {rc}, {err.strip()!r}")
if bad:
    print("FAIL:\n" + "\n".join(bad), file=sys.stderr); sys.exit(1)
print(f"help: {len(tools)} tools, {options} options OK")
PY
