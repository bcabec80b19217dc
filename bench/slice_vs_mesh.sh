#!/bin/bash
# BENCHMARKS.md, "Slicing": offsetgen slice (CLI and SL1) against offsetgen mesh + PrusaSlicer's
# --export-sla, on a 6 x 6 x 6 gyroid block of 8 mm cells at density 0.2 and 0.05 mm layers.
# Usage: bench/slice_vs_mesh.sh BUILD_DIR [WORK_DIR]   (wall clock and peak RSS from /usr/bin/time)
set -eu
offsetgen="$(realpath "${1:?usage: bench/slice_vs_mesh.sh BUILD_DIR [WORK_DIR]}")/offsetgen"
work="${2:-$(mktemp -d)}"
mkdir -p "$work" && cd "$work"
measure() { /usr/bin/time -f "%e s, %M KB peak" "$@" >/dev/null 2>time.txt; tail -1 time.txt; }
part=(--surface gyroid --density 0.2 --cells 6 --cell-size 8)
echo "slice to CLI:      $(measure "$offsetgen" slice "${part[@]}" --layer-height 0.05 -o g.cli -q)"
echo "slice to SL1:      $(measure "$offsetgen" slice "${part[@]}" --layer-height 0.05 -o g.sl1 -q)"
echo "mesh:              $(measure "$offsetgen" mesh "${part[@]}" -o g.stl -q)"
echo "PrusaSlicer (SLA): $(measure prusa-slicer --export-sla --no-supports-enable --no-pad-enable \
  --layer-height 0.05 --initial-layer-height 0.05 -o p.sl1 g.stl)"
ls -l g.cli g.sl1 g.stl p.sl1 | awk '{print $5 " bytes  " $9}'
