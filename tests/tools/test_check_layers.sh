#!/usr/bin/env bash
# The layer check catches what it is for (tests/tools/check_layers.py): a planted include from one
# command's folder into a peer's (mesh/ into check/) and one that points up (run/ into mesh/) each make
# it fail, naming the file; a clean tree passes.
set -u
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail=0
mkdir -p "$tmp/src/mesh" "$tmp/src/check" "$tmp/src/run" "$tmp/src/wall"
echo '#include "wall/wall_field.h"' >"$tmp/src/mesh/ok.cpp"
if ! out=$(python3 "$here/check_layers.py" --root "$tmp"); then echo "FAIL: a clean tree was refused: $out"; fail=1; fi
echo '#include "check/report.h"' >"$tmp/src/mesh/peer.cpp"
if out=$(python3 "$here/check_layers.py" --root "$tmp"); then
  echo "FAIL: mesh/ including check/ passed"; fail=1
elif [[ "$out" != *"src/mesh/peer.cpp: mesh/ includes check/, a peer"* ]]; then
  echo "FAIL: the peer include was not named: $out"; fail=1
fi
rm "$tmp/src/mesh/peer.cpp"
echo '#include "mesh/mesher.h"' >"$tmp/src/run/up.cpp"
if out=$(python3 "$here/check_layers.py" --root "$tmp"); then
  echo "FAIL: run/ including mesh/ passed"; fail=1
elif [[ "$out" != *"src/run/up.cpp: run/ includes mesh/, a later stage"* ]]; then
  echo "FAIL: the upward include was not named: $out"; fail=1
fi
[ $fail = 0 ] && echo "the layer check refuses a peer include and an upward one, and passes a clean tree"
exit $fail
