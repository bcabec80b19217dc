#!/usr/bin/env bash
# OpenCASCADE's own test harness reads a file of offsetgen step back (one run for the file): the
# shape is valid (checkshape), holds one solid and one shell (nbshapes), and its volume (vprops) lies
# within 0.1% of the exact wall volume that offsetgen step printed; a boolean cut by a box through the
# middle of a cell (x = 3.7 mm, where no face edge lies) gives two valid pieces whose volumes add up (to 2e-5: vprops prints 6 digits).
# A surface whose block holds several pieces of wall (diamond: 3) gives that many solids and shells.
# Box patches (the gyroid) meet along their edges within the fit's tolerance rather than exactly, and
# the volumes of the boolean's pieces then add up to 1e-4 or so: the last argument is that bound.
#   occt_draw_readback.sh <offsetgen> <occt-draw> <scratch dir> [surface cells solids additivity cell-size thickness]
set -euo pipefail
offsetgen=$1 draw=$2 dir=$3 surface=${4:-schwarzp} cells=${5:-2x1x1} solids=${6:-1} additivity=${7:-2e-5}
# A box cell (--cell-size X,Y,Z) takes its wall in mm: 1 mm there, as 0.1 of a 10 mm cube cell.
cell_size=${8:-10} thickness=${9:-0.1}
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
# A file written once for both readers (box_cells_readback.sh): its p.step and summary.txt, copied.
if [ -n "${STEP_WRITTEN_IN:-}" ]; then
  cp "$STEP_WRITTEN_IN/p.step" "$STEP_WRITTEN_IN/summary.txt" .
else
  "$offsetgen" step --surface "$surface" --thickness "$thickness" --cells "$cells" --cell-size "$cell_size" \
    --tolerance 0.01 -o p.step >summary.txt
fi
cat summary.txt
exact=$(sed -n 's/.*exact wall \([0-9.]*\) mm^3.*/\1/p' summary.txt)
cat >read.tcl <<'TCL'
pload ALL
testreadstep p.step sh
puts "CHECKSHAPE: [checkshape sh]"
puts [nbshapes sh]
puts [vprops sh]
box b 3.7 -1 -1 40 40 40
bcommon inside sh b
bcut outside sh b
puts "COMMON: [checkshape inside]"
puts "CUT: [checkshape outside]"
puts "VOLUMES: [lindex [vprops inside] 2] [lindex [vprops outside] 2]"
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
grep -Eq "^ *SOLID +: $solids$" draw.txt || fail "not $solids solid(s)"
grep -Eq "^ *SHELL +: $solids$" draw.txt || fail "not $solids shell(s)"
mass=$(sed -n 's/^Mass : *\([0-9.e+-]*\).*/\1/p' draw.txt | head -1)
grep -q "COMMON: This shape seems to be valid" draw.txt || fail "the common with a box is not valid"
grep -q "CUT: This shape seems to be valid" draw.txt || fail "the cut by a box is not valid"
read -r inside outside < <(sed -n 's/^VOLUMES: //p' draw.txt)
[ -n "$mass" ] && [ -n "$exact" ] || fail "no volume read (vprops: '$mass', offsetgen: '$exact')"
awk -v m="$mass" -v e="$exact" 'BEGIN { d = (m - e) / e; if (d < 0) d = -d; printf "vprops %s, exact %s: %.3g%%\n", m, e, 100 * d; exit !(d < 1e-3) }' ||
  fail "vprops' volume is not within 0.1% of the exact wall volume"
awk -v bound="$additivity" -v a="$inside" -v b="$outside" -v m="$mass" 'BEGIN { d = (a + b - m) / m; if (d < 0) d = -d;
  printf "common %s + cut %s = %s, whole %s\n", a, b, a + b, m; exit !(a > 0 && b > 0 && d < bound) }' ||
  fail "the pieces of the boolean do not add up to the whole"
echo "occt-draw: $surface, $solids valid solid(s), volume within 0.1%, a boolean cut by a box gives two valid pieces"
