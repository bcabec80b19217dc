#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite (the README's second command; CI runs it).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
# Fuzz smoke: each libFuzzer target (fuzz/) for 60 s, in a clang tree instrumented with ASan and UBSan.
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOFFSETGEN_FUZZ=ON
cmake --build build-fuzz -j"$(nproc)" --target fuzz_expression fuzz_metadata fuzz_body
ctest --test-dir build-fuzz -L fuzz --output-on-failure
