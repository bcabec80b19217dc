#!/usr/bin/env bash
# Installs every Debian 12 package that building, testing and benchmarking offsetgen needs.
# Idempotent: installs only what is missing. Must run as root (or with sudo available).
set -euo pipefail

packages=(
  build-essential cmake pkg-config git ninja-build
  libginac-dev libcln-dev
  libfmt-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  glslang-tools spirv-tools libegl-dev libopengl-dev libgles-dev libgl1-mesa-dri libpng-dev
  python3 python3-sympy python3-matplotlib python3-numpy time
  python3-numba
  clang-format clang-tidy
  clang libclang-rt-14-dev
  libopenvdb-dev libboost-iostreams-dev admesh lib3mf-dev
  prusa-slicer openscad  # real parts and a slicer for the mesh --body checks (tools/check_parts.py)
  parallel  # GNU parallel: the split-and-merge test of offsetgen mesh --tile-range
  chromium libvulkan-dev mesa-vulkan-drivers
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers clinfo
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# Node and npm run the WGSL tests (tests/wgsl); a Node that brings its own npm (NodeSource) will do.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then missing+=(nodejs npm); fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
else
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "install_deps: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

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
