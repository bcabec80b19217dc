#!/usr/bin/env bash
# Installs the Debian 12 packages offsetgen needs. Idempotent: installs only what is missing. Must run
# as root (or with sudo available).
#
#   tools/install_deps.sh --core    what building offsetgen alone needs: generate, list, density, check of C (tools/demo.sh)
#   tools/install_deps.sh --build   that, and what offsetgen-mesh (OpenVDB) and offsetgen-step (OpenCASCADE) need
#   tools/install_deps.sh [--all]   that, and everything the tests and benchmarks use (tools/test.sh)
set -euo pipefail

usage() {
  echo "usage: tools/install_deps.sh [--core | --build | --all]" >&2
  exit 2
}
[ $# -le 1 ] || usage
case "${1:---all}" in
  --all) want=all ;;
  --build) want=build ;;
  --core) want=core ;;
  -h | --help)
    sed -n '2,7s/^# \{0,1\}//p' "$0"
    exit 0
    ;;
  *) usage ;;
esac

# The core set: the compiler and CMake, GiNaC/CLN, fmt, CLI11 and nlohmann-json: offsetgen itself;
# libpng and zlib for `offsetgen slice` (SL1 layers as PNG, the archive's CRC-32), Clipper
# (libpolyclipping) for its CLI --beam-offset.
core_packages=(
  build-essential cmake pkg-config
  libginac-dev libcln-dev
  libfmt-dev libcli11-dev nlohmann-json3-dev
  libpng-dev zlib1g-dev libpolyclipping-dev
)
# The build set adds OpenVDB (with Boost.Iostreams, which Debian's FindOpenVDB.cmake needs) and lib3mf
# for offsetgen-mesh, OpenCASCADE (foundation, modeling data and algorithms, data exchange) for
# offsetgen-step. GoogleTest too, although only the tests use it: a plain `cmake -S . -B build`
# configures them (OFFSETGEN_BUILD_TESTS is ON at the top level) and tests/ has find_package(GTest REQUIRED).
build_packages=(
  libopenvdb-dev libboost-iostreams-dev lib3mf-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev
  libgtest-dev
)
# The test set: the runners of every target (GL, Vulkan, Chromium, pocl, Python, clang), the
# benchmarks, the mesh checks and the tools the tests call.
test_packages=(
  git ninja-build
  libgmock-dev libbenchmark-dev
  glslang-tools spirv-tools libegl-dev libopengl-dev libgles-dev libgl1-mesa-dri libpng-dev
  python3 python3-sympy python3-matplotlib python3-numpy time
  python3-numba
  clang-format clang-tidy
  clang libclang-rt-14-dev
  admesh
  prusa-slicer openscad  # real parts and a slicer for the mesh --body checks (tools/check_parts.py)
  parallel  # GNU parallel: the split-and-merge test of offsetgen mesh --tile-range
  occt-draw libocct-draw-dev  # OpenCASCADE's own harness reads offsetgen step's files back (tests/step)
  freecad  # FreeCAD opens offsetgen step's files and cuts them with a box (tests/step)
  chromium libvulkan-dev mesa-vulkan-drivers
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers clinfo
)

packages=("${core_packages[@]}")
if [ "$want" != core ]; then packages+=("${build_packages[@]}"); fi
if [ "$want" = all ]; then packages+=("${test_packages[@]}"); fi

# One dpkg-query for all of them (one per package costs seconds on a busy machine).
# It fails when a package is unknown to dpkg (never installed): that one is missing, not an error.
installed_now=" $({ dpkg-query -W -f='${Package}=${Status}\n' "${packages[@]}" 2>/dev/null || true; } |
  sed -n 's/=install ok installed$//p' | tr '\n' ' ') "
missing=()
for p in "${packages[@]}"; do
  if [[ "$installed_now" != *" $p "* ]]; then missing+=("$p"); fi
done

# Node and npm run the WGSL tests (tests/wgsl); a Node that brings its own npm (NodeSource) will do.
if [ "$want" = all ] && { ! command -v node >/dev/null || ! command -v npm >/dev/null; }; then
  missing+=(nodejs npm)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages of the $want set present"
else
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "install_deps: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

[ "$want" = all ] || exit 0

# Dawn's Node bindings for the WGSL tests, at the version pinned in tests/wgsl/package-lock.json.
wgsl_dir="$(cd "$(dirname "$0")/.." && pwd)/tests/wgsl"
pinned=$(node -p "require('$wgsl_dir/package.json').dependencies.webgpu")
installed=$(node -p "require('$wgsl_dir/node_modules/webgpu/package.json').version" 2>/dev/null || true)
if [ "$installed" = "$pinned" ]; then
  echo "install_deps: webgpu $pinned present in tests/wgsl/node_modules"
else
  echo "install_deps: npm ci --prefix tests/wgsl (Dawn's Node bindings, the npm package webgpu)"
  npm ci --prefix "$wgsl_dir" --no-audit --no-fund
fi
