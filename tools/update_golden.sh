#!/usr/bin/env bash
# Regenerates the committed golden files in generated/ from generated/MANIFEST. Run it when a change
# to the generator is meant to change its output, review `git diff generated/`, and commit both.
# usage: tools/update_golden.sh [path/to/offsetgen]   (default: build/offsetgen)
set -euo pipefail
cd "$(dirname "$0")/.."
tool=${1:-build/offsetgen}
[ -x "$tool" ] || { echo "update_golden: $tool not found; build first (cmake --build build)" >&2; exit 2; }
while read -r line; do
  case "$line" in ''|'#'*) continue ;; esac
  # shellcheck disable=SC2086  # the manifest holds whitespace-separated arguments
  "$tool" generate $line --out-dir generated --quiet
done < generated/MANIFEST
echo "update_golden: generated/ is up to date with $tool; review with: git diff --stat generated/"
