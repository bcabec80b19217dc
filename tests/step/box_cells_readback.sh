#!/usr/bin/env bash
# Issue 42's box cells: a block of 2 x 2 x 2 cells of 10 x 10 x 15 mm with a 1 mm wall, written once at
# --tolerance 0.01 and read back by both outside readers as the other read-back tests do: occt-draw
# (checkshape, solids and shells, volume within 0.1% of the exact wall's, a boolean with a box) and
# FreeCAD (Part.read valid, the same counts and volume, a valid cut and common that add up).
#   box_cells_readback.sh <offsetgen> <occt-draw> <freecadcmd> <scratch dir> <surface> <solids>
set -euo pipefail
offsetgen=$1 draw=$2 freecad=$3 dir=$4 surface=$5 solids=$6
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$dir" && mkdir -p "$dir/written"
"$offsetgen" step --surface "$surface" --thickness 1 --cells 2x2x2 --cell-size 10,10,15 --tolerance 0.01 \
  -o "$dir/written/p.step" >"$dir/written/summary.txt"
# Box patches meet within the fit's tolerance: the boolean's pieces add up to 3e-4 or better.
STEP_WRITTEN_IN="$dir/written" "$here/occt_draw_readback.sh" "$offsetgen" "$draw" "$dir/occt_draw" "$surface" 2x2x2 \
  "$solids" 3e-4
STEP_WRITTEN_IN="$dir/written" "$here/freecad_readback.sh" "$offsetgen" "$freecad" "$dir/freecad" "$surface" 2x2x2 \
  "$solids" 3e-4
