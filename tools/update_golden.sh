#!/usr/bin/env bash
# Rewrites the catalog's sweep table (src/lowering/catalog_sweeps.inc, by offsetgen_catalog_sweeps
# beside offsetgen; when it changes, rebuild and run this again: offsetgen holds the table it was
# built with). Then regenerates the committed golden files in generated/ from generated/MANIFEST (and
# cmake/registries.json, `offsetgen list --registries`): writes what the manifest produces and
# removes every other file (a golden file whose manifest line is gone is
# stale). Run it when a change to the generator is meant to change its output, review
# `git status generated/` and `git diff generated/`, and commit both.
# usage: tools/update_golden.sh [path/to/offsetgen] [golden-dir]   (defaults: build/offsetgen, generated)
set -euo pipefail
cd "$(dirname "$0")/.."
tool=${1:-build/offsetgen}
golden=${2:-generated}
[ -x "$tool" ] || { echo "update_golden: $tool not found; build first (cmake --build build)" >&2; exit 2; }
[ -f "$golden/MANIFEST" ] || { echo "update_golden: $golden/MANIFEST not found" >&2; exit 2; }
sweeps=$(dirname "$tool")/offsetgen_catalog_sweeps
[ -x "$sweeps" ] || { echo "update_golden: $sweeps not found; build it (target offsetgen_catalog_sweeps)" >&2; exit 2; }
table=src/lowering/catalog_sweeps.inc
"$sweeps" "$table.new"
if cmp -s "$table.new" "$table"; then rm "$table.new"; else
  mv "$table.new" "$table"
  echo "update_golden: $table rewritten; rebuild offsetgen and run this again to regenerate $golden/" >&2
  exit 3
fi
fresh=$(mktemp -d)
trap 'rm -rf "$fresh"' EXIT
while read -r line; do
  case "$line" in ''|'#'*) continue ;; esac
  # shellcheck disable=SC2086  # the manifest holds whitespace-separated arguments
  "$tool" generate $line --out-dir "$fresh" --quiet
done < "$golden/MANIFEST"
for file in "$golden"/*; do
  name=$(basename "$file")
  [ "$name" = MANIFEST ] && continue
  if [ ! -e "$fresh/$name" ]; then
    rm -- "$file"
    echo "update_golden: removed $file (not produced by $golden/MANIFEST)"
  fi
done
for file in "$fresh"/*; do
  cmp -s "$file" "$golden/$(basename "$file")" || cp -- "$file" "$golden/"
done
# The registries as data for CMake (cmake/Install.cmake reads them at configure time).
"$tool" list --registries > cmake/registries.json.new
if cmp -s cmake/registries.json.new cmake/registries.json; then rm cmake/registries.json.new; else
  mv cmake/registries.json.new cmake/registries.json
  echo "update_golden: cmake/registries.json rewritten"
fi
echo "update_golden: $golden/ is up to date with $tool; review with: git status $golden/ && git diff --stat $golden/"
