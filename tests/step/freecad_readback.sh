#!/usr/bin/env bash
# FreeCAD (freecadcmd, no display) opens a file of offsetgen step as CAD users will: Part.read gives
# one valid solid with one shell whose volume lies within 0.1% of the exact wall volume offsetgen step
# printed, and a boolean with a box through the middle of a cell (x = 3.7 mm, where no face edge lies)
# gives a valid cut and a valid common whose volumes add up to the whole (to 2e-5, as volume integration
# of B-spline faces goes: 6e-6 measured).
# A surface whose block holds several pieces of wall (diamond: 3) gives that many solids and shells.
# Box patches (the gyroid) meet along their edges within the fit's tolerance rather than exactly, and
# the volumes of the boolean's pieces then add up to 1e-4 or so: the last argument is that bound.
#   freecad_readback.sh <offsetgen> <freecadcmd> <scratch dir> [surface cells solids additivity cell-size thickness]
set -euo pipefail
offsetgen=$1 freecad=$2 dir=$3 surface=${4:-schwarzp} cells=${5:-2x1x1} solids=${6:-1} additivity=${7:-2e-5}
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
cat >read.py <<PY
import FreeCAD
import Part
shape = Part.read("$PWD/p.step")
box = Part.makeBox(40, 40, 40, FreeCAD.Vector(3.7, -1, -1))
cut, common = shape.cut(box), shape.common(box)
print("SHAPE", shape.isValid(), len(shape.Solids), len(shape.Shells), repr(shape.Volume))
print("CUT", cut.isValid(), repr(cut.Volume))
print("COMMON", common.isValid(), repr(common.Volume))
PY
"$freecad" read.py >freecad.txt 2>&1 || true
cat freecad.txt
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
read -r _ valid got_solids shells volume < <(grep -m1 "^SHAPE " freecad.txt) || fail "FreeCAD printed no shape"
[ "$valid" = True ] || fail "FreeCAD does not find the shape valid"
[ "$got_solids" = "$solids" ] && [ "$shells" = "$solids" ] ||
  fail "not $solids solid(s) with a shell each ($got_solids solids, $shells shells)"
read -r _ cut_valid cut < <(grep -m1 "^CUT " freecad.txt) || fail "no cut"
read -r _ common_valid common < <(grep -m1 "^COMMON " freecad.txt) || fail "no common"
[ "$cut_valid" = True ] && [ "$common_valid" = True ] || fail "the boolean with a box is not valid"
awk -v m="$volume" -v e="$exact" 'BEGIN { d = (m - e) / e; if (d < 0) d = -d; printf "FreeCAD volume %s, exact %s: %.3g%%\n", m, e, 100 * d; exit !(d < 1e-3) }' ||
  fail "FreeCAD's volume is not within 0.1% of the exact wall volume"
awk -v bound="$additivity" -v a="$common" -v b="$cut" -v m="$volume" 'BEGIN { d = (a + b - m) / m; if (d < 0) d = -d;
  printf "common %s + cut %s = %s, whole %s\n", a, b, a + b, m; exit !(a > 0 && b > 0 && d < bound) }' ||
  fail "the pieces of the boolean do not add up to the whole"
echo "FreeCAD: $surface, $solids valid solid(s), volume within 0.1%, a boolean with a box gives a valid cut and common"
