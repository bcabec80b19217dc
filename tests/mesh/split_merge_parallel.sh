#!/usr/bin/env bash
# A run split over "machines" with GNU parallel (four shares of the tiles, --tile-range I/4, two at a
# time on this machine) and joined with --merge gives the single run's bytes (docs/tiles.md's recipe).
#   tests/mesh/split_merge_parallel.sh OFFSETGEN SCRATCH_DIR
set -euo pipefail
offsetgen=$1
dir=$2
rm -rf "$dir"
mkdir -p "$dir"
command -v parallel >/dev/null || { echo "GNU parallel is missing (apt-get install parallel)"; exit 1; }
args=(mesh --surface gyroid --thickness 0.1 --cells 3 --cell-size 8 --resolution 40 --tile 48 --quiet)
"$offsetgen" "${args[@]}" -o "$dir/single.stl"
parallel --will-cite --jobs 2 --halt now,fail=1 \
  "$offsetgen" "${args[@]}" --threads 1 --tile-range {}/4 -o "$dir/part{}.stl" ::: 0 1 2 3
"$offsetgen" mesh --merge "$dir"/part0.stl "$dir"/part1.stl "$dir"/part2.stl "$dir"/part3.stl -o "$dir/merged.stl"
if cmp "$dir/single.stl" "$dir/merged.stl"; then
  echo "the merged shares equal the single run ($(stat -c %s "$dir/merged.stl") bytes)"
  echo "1 passed, 0 failed"
else
  echo "0 passed, 1 failed"
  exit 1
fi
