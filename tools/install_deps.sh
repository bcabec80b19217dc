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
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install_deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
