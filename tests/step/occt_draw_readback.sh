#!/usr/bin/env bash
# OpenCASCADE's own test harness reads a file of offsetgen step back (one run for the file): the
# shape is valid (checkshape), holds one solid and one shell (nbshapes), and its volume (vprops) lies
# within 0.1% of the exact wall volume that offsetgen step printed.
#   occt_draw_readback.sh <offsetgen> <occt-draw> <scratch dir>
set -euo pipefail
offsetgen=$1 draw=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
"$offsetgen" step --surface schwarzp --thickness 0.1 --cells 2x1x1 --cell-size 10 --tolerance 0.01 \
  -o p.step >summary.txt
cat summary.txt
exact=$(sed -n 's/.*exact wall \([0-9.]*\) mm^3.*/\1/p' summary.txt)
cat >read.tcl <<'TCL'
pload ALL
testreadstep p.step sh
puts "CHECKSHAPE: [checkshape sh]"
puts [nbshapes sh]
puts [vprops sh]
exit
TCL
# occt-draw needs no display in batch mode (-b).
"$draw" -b -f read.tcl >draw.txt 2>&1 || true
cat draw.txt
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
grep -q "CHECKSHAPE: This shape seems to be valid" draw.txt || fail "checkshape does not find the shape valid"
grep -Eq "^ *SOLID +: 1$" draw.txt || fail "not one solid"
grep -Eq "^ *SHELL +: 1$" draw.txt || fail "not one shell"
mass=$(sed -n 's/^Mass : *\([0-9.e+-]*\).*/\1/p' draw.txt | head -1)
[ -n "$mass" ] && [ -n "$exact" ] || fail "no volume read (vprops: '$mass', offsetgen: '$exact')"
awk -v m="$mass" -v e="$exact" 'BEGIN { d = (m - e) / e; if (d < 0) d = -d; printf "vprops %s, exact %s: %.3g%%\n", m, e, 100 * d; exit !(d < 1e-3) }' ||
  fail "vprops' volume is not within 0.1% of the exact wall volume"
echo "occt-draw: one valid solid, volume within 0.1%"
