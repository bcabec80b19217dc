#!/bin/sh
# Asserts that GCC vectorises every batch loop of a generated header.
# Usage: check_vectorised.sh CC HEADER PREFIX USE_BATCH_C [extra -D flags...]
# Compiles USE_BATCH_C (which calls every _n function) with the header's recommended flags and
# -fopt-info-vec-optimized, and looks for "HEADER:LINE:...loop vectorized" on the line after each
# `OFFSETGEN_SIMD_LOOP` inside a function.
set -eu
cc=$1 header=$2 prefix=$3 source=$4
shift 4
dir=$(dirname "$header")
name=$(basename "$header")
report=$("$cc" -std=c99 -O3 -march=native -fno-math-errno -fopt-info-vec-optimized -I"$dir" \
         -DOFFSETGEN_HEADER="\"$name\"" -DOFFSETGEN_PREFIX="$prefix" "$@" -c "$source" -o /dev/null 2>&1)
loops=$(grep -n '^    OFFSETGEN_SIMD_LOOP$' "$header" | cut -d: -f1)
[ -n "$loops" ] || { echo "no batch loops found in $header" >&2; exit 1; }
status=0
for line in $loops; do
  loop=$((line + 1))
  if printf '%s\n' "$report" | grep -q "$name:$loop:.*loop vectorized"; then
    echo "vectorised: $name:$loop ($(sed -n "$((line - 3))p" "$header" | sed 's/(.*//'))"
  else
    echo "NOT vectorised: $name:$loop" >&2
    status=1
  fi
done
[ $status -eq 0 ] || printf '%s\n' "$report" | grep "$name" | grep -v "^$name:[0-9]*:[0-9]*: optimized" | head -20 >&2
exit $status
