#!/usr/bin/env bash
# The README's promises: (1) every relative link in README.md and docs/*.md resolves to an existing
# file (anchors after # are not checked); (2) every `offsetgen ...` command line in the README's ```sh
# blocks runs with the built binary, in a scratch directory, and writes its -o file. Input bodies
# (`--body X`) are taken from /usr/share/PrusaSlicer/shapes/X (Debian prusa-slicer).
# Prints "N passed, M failed" last; exits non-zero if anything failed.
#
#   bash tests/tools/test_readme.sh BUILD_DIR     (BUILD_DIR holds offsetgen and offsetgen-mesh)
set -u

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="$(cd "${1:?usage: test_readme.sh BUILD_DIR}" && pwd)"
PY=/usr/bin/python3
SHAPES=/usr/share/PrusaSlicer/shapes
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
PASS=0
FAIL=0
ok()  { PASS=$((PASS + 1)); echo "PASS: $1"; }
bad() { FAIL=$((FAIL + 1)); echo "FAIL: $1"; }

# ------------------------------------------------------------ (1) relative links
# One line per link: "FILE<TAB>TARGET<TAB>RESOLVED" (fenced code is skipped).
"$PY" - "$ROOT" >"$TMP/links" <<'PYEOF'
import os, re, sys, glob
root = sys.argv[1]
files = [os.path.join(root, 'README.md')] + sorted(glob.glob(os.path.join(root, 'docs', '*.md')))
for f in files:
    fence = False
    for line in open(f, encoding='utf-8'):
        if line.lstrip().startswith('```'):
            fence = not fence
            continue
        if fence:
            continue
        line = re.sub(r'`[^`]*`', '', line)          # inline code is not a link
        for t in re.findall(r'\]\(([^)\s]+)\)', line) + re.findall(r'src="([^"]+)"', line):
            if re.match(r'^[a-z]+:', t) or t.startswith('#'):
                continue
            path = t.split('#', 1)[0]
            print(f'{os.path.relpath(f, root)}\t{t}\t{os.path.normpath(os.path.join(os.path.dirname(f), path))}')
PYEOF
nlinks=0
while IFS=$'\t' read -r file target resolved; do
  nlinks=$((nlinks + 1))
  if [ -e "$resolved" ]; then ok "link $file -> $target"; else bad "link $file -> $target (no $resolved)"; fi
done <"$TMP/links"
if [ "$nlinks" -lt 20 ]; then bad "found only $nlinks relative links in README.md and docs/*.md"; fi

# ------------------------------------------------------------ (2) the README's offsetgen commands
# One command per line (continuation lines joined), from ```sh blocks, lines starting with "offsetgen ".
"$PY" - "$ROOT/README.md" >"$TMP/commands" <<'PYEOF'
import sys
fence = None; pending = ''
for line in open(sys.argv[1], encoding='utf-8'):
    s = line.rstrip('\n')
    if s.startswith('```'):
        fence = s[3:].strip() if fence is None else None
        continue
    if fence != 'sh':
        continue
    if pending:
        s = pending + ' ' + s.strip(); pending = ''
    if s.endswith('\\'):
        pending = s[:-1].rstrip(); continue
    if s.startswith('offsetgen '):
        print(s)
PYEOF
WORK="$TMP/work"
mkdir -p "$WORK"
ncommands=0
while IFS= read -r cmd; do
  ncommands=$((ncommands + 1))
  # Bodies the command reads: from PrusaSlicer's sample shapes.
  body="$(sed -n 's/.*--body \([^ ]*\).*/\1/p' <<<"$cmd")"
  if [ -n "$body" ] && [ ! -e "$WORK/$body" ]; then
    if [ -e "$SHAPES/$(basename "$body")" ]; then cp "$SHAPES/$(basename "$body")" "$WORK/$body"
    else bad "$cmd (input $body: no $SHAPES/$(basename "$body"); install prusa-slicer)"; continue; fi
  fi
  out="$(sed -n 's/.* -o \([^ ]*\).*/\1/p' <<<"$cmd")"
  start=$(date +%s.%N)
  if (cd "$WORK" && PATH="$BUILD:$PATH" bash -c "set -o pipefail; $cmd" >"$TMP/cmd.out" 2>&1); then
    secs=$(echo "$(date +%s.%N) - $start" | bc)
    if [ -n "$out" ] && [ "$out" != "-" ] && [ ! -s "$WORK/$out" ]; then
      bad "$cmd (exit 0 but no $out)"
    else
      ok "$cmd (${secs%???????} s)"
    fi
  else
    bad "$cmd (exit $?)"; tail -20 "$TMP/cmd.out"
  fi
done <"$TMP/commands"
if [ "$ncommands" -lt 5 ]; then bad "found only $ncommands offsetgen commands in the README's sh blocks"; fi

echo "$PASS passed, $FAIL failed"
[ "$FAIL" -eq 0 ]
