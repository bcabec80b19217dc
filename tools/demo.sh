#!/usr/bin/env bash
# The README's first command: installs what building offsetgen needs (tools/install_deps.sh --core),
# builds offsetgen alone (no test suite, no offsetgen-mesh or offsetgen-step: OpenVDB and OpenCASCADE
# take minutes to install and compile) in build-demo/, writes the order-4 gyroid for every target into
# out/ and says what to do with each file, and how to get a printable part next.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
tools/install_deps.sh --core
# A tree of its own without the tests: build/ is tools/test.sh's. --log-level=ERROR hides the
# warnings about test and render tools this build does not make (their packages are the test set's).
echo "demo: building offsetgen in build-demo/ (a few minutes the first time)"
cmake -S . -B build-demo -DCMAKE_BUILD_TYPE=Release -DOFFSETGEN_BUILD_TESTS=OFF -DOFFSETGEN_BUILD_MESH=OFF \
  -DOFFSETGEN_BUILD_STEP=OFF --log-level=ERROR >/dev/null
cmake --build build-demo -j"$(nproc)" --target offsetgen >/dev/null
echo "demo: packages and build took $((SECONDS - start)) s"

./build-demo/offsetgen generate --surface gyroid --order 4 --lang all --precision both --out-dir out

cat <<'EOF'

What you got, in out/ (coordinates, h and the wall thickness t are in cell units: divide by your
cell length; gyroid_o4_shell(p, t) < 0 inside a wall of thickness t, the solid to print or render):
  out/gyroid_o4.h     C or C++: #include "gyroid_o4.h", call gyroid_o4_shell(x, y, z, t) (float: _shellf)
  out/gyroid_o4.glsl  GLSL: paste it above the shader code that calls gyroid_o4_shell(p, t)
  out/gyroid_o4.hlsl  HLSL: paste or #include it, call gyroid_o4_shell(p, t)
  out/gyroid_o4.wgsl  WGSL: paste it once into your shader module, call gyroid_o4_shell(p, t)
  out/gyroid_o4.cuh   CUDA: #include it in a .cu file, call gyroid_o4_shell(x, y, z, t) in kernels or host code
  out/gyroid_o4.cl    OpenCL C: prepend it to your program source, call gyroid_o4_shellf(p, t)
  out/gyroid_o4.py    NumPy: import gyroid_o4, call gyroid_o4.gyroid_o4_shell(x, y, z, t) on arrays
Each file's header comment lists all its functions; `build-demo/offsetgen check out/gyroid_o4.h`
measures its accuracy.
EOF
cat <<'EOF'

A printable part next: a 40 mm gyroid cube (4 cells of 10 mm, 1 mm walls), an STL for your slicer.
The mesher, offsetgen-mesh, needs OpenVDB (a larger install and a few more minutes of compiling):
  tools/install_deps.sh --build
  cmake -S . -B build-demo -DOFFSETGEN_BUILD_MESH=ON && cmake --build build-demo -j"$(nproc)" --target offsetgen
  build-demo/offsetgen mesh --surface gyroid --thickness 0.1 --cells 4 --cell-size 10 --adaptivity 0.1 -o out/gyroid.stl
Your own part filled with a lattice inside a 1 mm skin: add --body part.stl --skin 1 (docs/parts.md).
EOF
