#!/usr/bin/env bash
# issue 42's trimmed parts, end to end: occt-draw makes the body (a B-rep written as STEP, and its
# triangulation as STL); `offsetgen step --body` trims a lattice by it; `offsetgen mesh --body` fills
# the STL with the same walls; FreeCAD (freecadcmd, no display) reads the STEP part, finds every solid
# valid and closed, and a half-space box through it gives a valid cut and common that add up to the whole.
# The two routes' volumes agree within 0.5%. Prints its outputs only when a check fails.
#   body_part_readback.sh <offsetgen> <occt-draw> <freecadcmd> <scratch dir> sphere|holed_box
set -euo pipefail
offsetgen=$1 draw=$2 freecad=$3 dir=$4 case=$5
voxel=0.1 # mm, 100 per cell: the mesh route's volume moved 0.03% (gyroid) and 0.07% (diamond) at 0.05 mm
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail() {
  for f in draw.txt step.txt mesh.txt freecad.txt; do [ -f "$f" ] && cat "$f" >&2; done
  echo "FAIL: $*" >&2
  exit 1
}
# The bodies (issue 42): a sphere 30 mm across; a 40 x 30 x 20 mm box with a hole 10 mm across through it.
case $case in
sphere)
  make='psphere body 15
ttranslate body 15 15 15'
  lattice=(--surface gyroid --thickness 0.1) skin=0 ;;
holed_box)
  make='box b 40 30 20
pcylinder c 5 20
ttranslate c 20 15 0
bcut body b c'
  lattice=(--surface diamond --thickness 0.1) skin=1.5 ;;
*) fail "unknown case $case" ;;
esac
cat >make.tcl <<TCL
pload ALL
$make
stepwrite a body body.step
incmesh body 0.001
writestl body body.stl
exit
TCL
"$draw" -b -f make.tcl >draw.txt 2>&1 || true
[ -s body.step ] && [ -s body.stl ] || fail "occt-draw wrote no body"

# 10 mm cells, 1 mm walls (t = 0.1 cell in both commands: mesh's --thickness is in cell units too);
# the cells from (0, 0, 0) in both (the triangulation's box starts a few micrometres off the body's).
"$offsetgen" step "${lattice[@]}" --cell-size 10 --tolerance 0.01 --body body.step --skin $skin --origin 0,0,0 \
  -o part.step \
  >step.txt 2>&1 || fail "offsetgen step --body exited $?"
"$offsetgen" mesh "${lattice[@]}" --cell-size 10 --body body.stl --skin $skin --origin 0,0,0 \
  --voxel $voxel -o part.stl \
  >mesh.txt 2>&1 || fail "offsetgen mesh --body exited $?"
step_volume=$(sed -n 's/.*part (.*volume \([0-9.]*\) mm^3.*/\1/p' step.txt)
mesh_volume=$(sed -n 's/.* part \([0-9.e+]*\) mm^3 against.*/\1/p' mesh.txt | head -1)
[ -n "$step_volume" ] && [ -n "$mesh_volume" ] || fail "no volume read (step '$step_volume', mesh '$mesh_volume')"
awk -v s="$step_volume" -v m="$mesh_volume" 'BEGIN { d = (s - m) / m; if (d < 0) d = -d; exit !(d < 5e-3) }' ||
  fail "STEP part $step_volume mm^3 and mesh part $mesh_volume mm^3 differ by 0.5% or more"

cat >read.py <<PY
import FreeCAD
import Part
shape = Part.read("$PWD/part.step")
bb = shape.BoundBox
box = Part.makeBox(100, 100, 100, FreeCAD.Vector(bb.XMin + 0.37 * bb.XLength, bb.YMin - 1, bb.ZMin - 1))
cut, common = shape.cut(box), shape.common(box)
closed = all(s.isClosed() for s in shape.Shells)
print("SHAPE", shape.isValid(), closed, len(shape.Solids), repr(shape.Volume))
print("CUT", cut.isValid(), repr(cut.Volume))
print("COMMON", common.isValid(), repr(common.Volume))
PY
"$freecad" read.py >freecad.txt 2>&1 || true
read -r _ valid closed solids volume < <(grep -m1 "^SHAPE " freecad.txt) || fail "FreeCAD printed no shape"
[ "$valid" = True ] && [ "$closed" = True ] && [ "$solids" -ge 1 ] || fail "FreeCAD: not valid closed solids"
read -r _ cut_valid cut < <(grep -m1 "^CUT " freecad.txt) || fail "no cut"
read -r _ common_valid common < <(grep -m1 "^COMMON " freecad.txt) || fail "no common"
[ "$cut_valid" = True ] && [ "$common_valid" = True ] || fail "the boolean with a box is not valid"
awk -v s="$step_volume" -v m="$volume" 'BEGIN { d = (s - m) / m; if (d < 0) d = -d; exit !(d < 1e-4) }' ||
  fail "FreeCAD's volume $volume is not offsetgen's $step_volume"
awk -v a="$common" -v b="$cut" -v m="$volume" 'BEGIN { d = (a + b - m) / m; if (d < 0) d = -d;
  exit !(a > 0 && b > 0 && d < 1e-3) }' || fail "the pieces of the boolean do not add up to the whole"
