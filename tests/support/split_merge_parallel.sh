#!/usr/bin/env bash
# A run split over "machines" with GNU parallel (SHARES shares, two at a time on this machine) and
# joined with --merge gives the single run's bytes, for each extension: mesh's --tile-range
# (docs/tiles.md's recipe) and slice's --layer-range (docs/slice.md's).
#   tests/support/split_merge_parallel.sh OFFSETGEN SCRATCH_DIR COMMAND RANGE_OPTION SHARES SHARE_NAME EXTS ARGS...
# SHARE_NAME: a share's file, with {} for its index and EXT for the extension (share{}.EXT.part);
# EXTS: the extensions, space-separated; ARGS: the command's options without -o.
set -euo pipefail
offsetgen=$1
dir=$2
command=$3
range_option=$4
shares=$5
share_name=$6
exts=$7
shift 7
args=("$command" "$@" --quiet)
rm -rf "$dir"
mkdir -p "$dir/single" "$dir/merged"
command -v parallel >/dev/null || { echo "GNU parallel is missing (apt-get install parallel)"; exit 1; }
passed=0
failed=0
for ext in $exts; do
  share=${share_name//EXT/$ext}
  # The single run and the merged file have the same name: a slice's job name is the file's.
  "$offsetgen" "${args[@]}" -o "$dir/single/part.$ext"
  parallel --will-cite --jobs 2 --halt now,fail=1 \
    "$offsetgen" "${args[@]}" --threads 1 "$range_option" "{}/$shares" -o "$dir/$share" ::: $(seq 0 $((shares - 1)))
  parts=()
  for ((i = 0; i < shares; ++i)); do parts+=("$dir/${share//\{\}/$i}"); done
  "$offsetgen" "$command" --quiet --merge "${parts[@]}" -o "$dir/merged/part.$ext"
  if cmp "$dir/single/part.$ext" "$dir/merged/part.$ext"; then
    echo "$ext: the merged shares equal the single run ($(stat -c %s "$dir/merged/part.$ext") bytes)"
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
  fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
