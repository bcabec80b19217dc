#!/usr/bin/env bash
# A slice split over "machines" with GNU parallel (three shares of the layers, --layer-range I/3, two
# at a time on this machine) and joined with --merge gives the single run's bytes, as CLI and SL1
# (docs/slice.md's recipe; mesh's is tests/mesh/split_merge_parallel.sh).
#   tests/slice/split_merge_parallel.sh OFFSETGEN SCRATCH_DIR
set -euo pipefail
offsetgen=$1
dir=$2
rm -rf "$dir"
mkdir -p "$dir/merged"
command -v parallel >/dev/null || { echo "GNU parallel is missing (apt-get install parallel)"; exit 1; }
args=(slice --surface gyroid --density 0.2 --cells 1 --cell-size 4 --layer-height 0.2 --quiet)
passed=0
failed=0
for ext in cli sl1; do
  "$offsetgen" "${args[@]}" -o "$dir/part.$ext"
  parallel --will-cite --jobs 2 --halt now,fail=1 \
    "$offsetgen" "${args[@]}" --threads 1 --layer-range {}/3 -o "$dir/share{}.$ext.part" ::: 0 1 2
  "$offsetgen" slice --quiet --merge "$dir/share0.$ext.part" "$dir/share1.$ext.part" "$dir/share2.$ext.part" \
    -o "$dir/merged/part.$ext"
  if cmp "$dir/part.$ext" "$dir/merged/part.$ext"; then
    echo "$ext: the merged shares equal the single run ($(stat -c %s "$dir/merged/part.$ext") bytes)"
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
  fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
