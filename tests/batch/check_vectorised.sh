#!/bin/sh
# Asserts that a compiler vectorises every batch loop of a generated header with the given flags.
# Usage: check_vectorised.sh CC HEADER PREFIX USE_BATCH_C [flags and -D options...]
# Compiles USE_BATCH_C (which calls every _n function) with the flags plus the compiler's
# vectorisation report (GCC: -fopt-info-vec-optimized, "loop vectorized"; Clang:
# -Rpass=loop-vectorize, "vectorized loop") and looks for HEADER:LINE in it for the block loop on
# the line after each `OFFSETGEN_SIMD_LOOP` inside a function.
set -eu
cc=$1 header=$2 prefix=$3 source=$4
shift 4
dir=$(dirname "$header")
name=$(basename "$header")
if "$cc" --version 2>/dev/null | grep -qi clang; then
  report_flags="-Rpass=loop-vectorize"
  vectorised="vectorized loop"
else
  report_flags="-fopt-info-vec-optimized"
  vectorised="loop vectorized"
fi
# shellcheck disable=SC2086  # report_flags holds one flag
report=$("$cc" -std=c99 $report_flags -I"$dir" -DOFFSETGEN_HEADER="\"$name\"" -DOFFSETGEN_PREFIX="$prefix" "$@" \
         -c "$source" -o /dev/null 2>&1) || { printf '%s\n' "$report" >&2; exit 1; }
loops=$(grep -n '^ *OFFSETGEN_SIMD_LOOP$' "$header" | cut -d: -f1)
[ -n "$loops" ] || { echo "no batch loops found in $header" >&2; exit 1; }
status=0
for line in $loops; do
  loop=$((line + 1))
  if printf '%s\n' "$report" | grep -q "$name:$loop:.*$vectorised"; then
    echo "vectorised: $name:$loop ($cc $*)"
  else
    echo "NOT vectorised: $name:$loop ($cc $*)" >&2
    status=1
  fi
done
[ $status -eq 0 ] || printf '%s\n' "$report" | grep "$name" | grep -v "$vectorised" | head -20 >&2
exit $status
