#!/usr/bin/env bash
# Regenerates the pictures in docs/images/ (docs/glsl.md, docs/mesh.md; the README links them) from freshly generated GLSL
# snippets, rendered headless on Mesa llvmpipe by render_shell (tools/render). No GPU or display.
#
# usage: tools/render_readme_images.sh [build-dir]     (default: build)
#
# It builds the offsetgen and render_shell targets in build-dir if needed, generates the snippets
# into a temporary directory with `offsetgen generate --lang glsl`, pastes each one byte for byte
# into render_shell's fragment shader, and writes:
#   docs/images/gyroid_shell.png    gyroid, one cell, t = 0.1, order 4        (paper Figure 2)
#   docs/images/schwarzp_shell.png  Schwarz P, one cell, t = 0.1, order 4     (paper Figure 4)
#   docs/images/neovius_shell.png   Neovius, one cell, t = 0.1, order 4       (paper Figure 6)
#   docs/images/gyroid_graded.png   gyroid, 3 cells along x, t = 0.02 + 0.04 x, order 4 (Figure 9)
#   docs/images/gyroid_density.png  gyroid, 3 cells along x, relative density 0.3 falling to 0.1,
#                                   order 4 (--density-field, docs/density.md)
#   docs/images/gyroid_graded_mesh.png  the STL of `offsetgen mesh` (gyroid, 3x2x2 cells of 10 mm,
#                                   t = 0.04 + 0.04 x, adaptivity 0.1), drawn by tools/render_stl.py
#                                   (matplotlib); skipped when offsetgen was built without mesh
#   docs/images/part_bunny_gyroid_cut.png  PrusaSlicer's bunny (Debian prusa-slicer) at half size filled
#                                   with a gyroid of density 0.25 inside a 1.5 mm skin (--voxel 0.2
#                                   --adaptivity 0.2, for a picture), cut open at z = 30 mm; skipped
#                                   without the bunny
#   docs/images/part_bunny_drained_cut.png  the same with --drain 2, cut open at z = 6 mm, 3.4 mm
#                                   above the base: the lattice and the labyrinths' drain holes (docs/parts.md)
#
# Deterministic: the same offsetgen and the same Mesa/LLVM give the same bytes (llvmpipe is
# bit-reproducible, the PNG writer stores no timestamp). Renders in 5-25 s on 2 cores once built.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=docs/images

if [ ! -f "$build/CMakeCache.txt" ]; then
  echo "render_readme_images: configuring $build" >&2
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target offsetgen render_shell -j"$(nproc)" >/dev/null
offsetgen="$build/offsetgen"
render_shell=$(find "$build" -name render_shell -type f -perm -u+x | head -n 1)
[ -x "$offsetgen" ] || { echo "render_readme_images: no $offsetgen" >&2; exit 2; }
[ -n "$render_shell" ] || { echo "render_readme_images: render_shell not built (EGL/libpng missing? run tools/install_deps.sh)" >&2; exit 2; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"

# name surface order [extra offsetgen args...]
snippet() {
  local name=$1 surface=$2 order=$3
  shift 3
  "$offsetgen" generate --surface "$surface" --order "$order" --lang glsl --name "$name" \
    --out-dir "$tmp" --quiet "$@"
}

# png snippet-name [render_shell args...]
render() {
  local png=$1 name=$2
  shift 2
  "$render_shell" --snippet "$tmp/$name.glsl" --prefix "$name" --samples 3 -o "$out/$png" "$@"
}

snippet gyroid_o4 gyroid 4
snippet schwarzp_o4 schwarzp 4
snippet neovius_o4 neovius 4
snippet gyroid_graded_o4 gyroid 4 --thickness "0.02 + 0.04*x"
snippet gyroid_density_o4 gyroid 4 --density-field "0.3 - 0.2*x/3"

render gyroid_shell.png gyroid_o4 --thickness 0.1 --size 480x480
render schwarzp_shell.png schwarzp_o4 --thickness 0.1 --size 480x480
render neovius_shell.png neovius_o4 --thickness 0.1 --size 480x480
render gyroid_graded.png gyroid_graded_o4 --graded --thickness 0.02 --box 3x1x1 \
  --view 0.22 -0.95 0.3 --size 960x360
# --thickness: the thinnest wall (rho = 0.1: t = 0.0324), which sets the march step.
render gyroid_density.png gyroid_density_o4 --graded --thickness 0.032 --box 3x1x1 \
  --view 0.22 -0.95 0.3 --size 960x360

# The meshed part: the STL itself, not the GLSL.
if "$offsetgen" mesh --help >/dev/null 2>&1; then
  "$offsetgen" mesh --surface gyroid --thickness "0.04 + 0.04*x" --cells 3x2x2 --cell-size 10 \
    --adaptivity 0.1 -o "$tmp/gyroid_graded.stl" --quiet
  /usr/bin/python3 tools/render_stl.py "$tmp/gyroid_graded.stl" "$out/gyroid_graded_mesh.png" --azimuth 300 \
    --title "offsetgen mesh: gyroid, wall 0.04 to 0.16 cell along x, 3x2x2 cells of 10 mm"
  bunny=/usr/share/PrusaSlicer/shapes/bunny.stl
  if [ -f "$bunny" ]; then
    "$offsetgen" mesh --surface gyroid --density 0.25 --body "$bunny" --scale 0.5 --skin 1.5 --cell-size 6 \
      --voxel 0.2 --adaptivity 0.2 -o "$tmp/bunny_filled.stl" --quiet
    /usr/bin/python3 tools/render_stl.py "$tmp/bunny_filled.stl" "$out/part_bunny_gyroid_cut.png" --cut-above 30
    "$offsetgen" mesh --surface gyroid --density 0.25 --body "$bunny" --scale 0.5 --skin 1.5 --cell-size 6 \
      --voxel 0.2 --adaptivity 0.2 --drain 2 -o "$tmp/bunny_drained.stl" --quiet
    /usr/bin/python3 tools/render_stl.py "$tmp/bunny_drained.stl" "$out/part_bunny_drained_cut.png" --cut-above 6 \
      --elevation 60
  else
    echo "render_readme_images: no $bunny (apt-get install prusa-slicer): part_bunny_gyroid_cut.png skipped" >&2
  fi
else
  echo "render_readme_images: offsetgen has no mesh command (OpenVDB missing): gyroid_graded_mesh.png skipped" >&2
fi

ls -l "$out"/*.png
