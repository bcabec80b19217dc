#!/usr/bin/env bash
# Long fuzz runs, one target after another, for docs/fuzzing.md: each target runs SECONDS (default
# 1800) from the committed corpus (read only) into a fresh scratch corpus, and its last lines
# (executions, coverage, corpus size, any crash) go to LOGDIR/<target>.log.
# Usage: tools/fuzz_long.sh [SECONDS] [LOGDIR]   (build-fuzz/ built first, see docs/testing.md)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-1800}
logdir=${2:-fuzz-logs}
mkdir -p "$logdir"
for name in expression metadata body; do
  scratch="$logdir/corpus_$name"
  rm -rf "$scratch" && mkdir -p "$scratch" "$logdir/artifacts_$name"
  seeds=$(find "fuzz/corpus/$name" -type f | wc -l)
  echo "== fuzz_$name: ${seconds} s from $seeds seed inputs ($(date -u +%FT%TZ))" | tee "$logdir/$name.log"
  status=0
  ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$PWD/fuzz/lsan.supp \
    "build-fuzz/fuzz/fuzz_$name" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 \
    -print_final_stats=1 -artifact_prefix="$logdir/artifacts_$name/" "$scratch" "fuzz/corpus/$name" \
    >>"$logdir/$name.log" 2>&1 || status=$?
  echo "== exit $status; new corpus inputs: $(find "$scratch" -type f | wc -l); findings: $(find "$logdir/artifacts_$name" -type f | wc -l)" | tee -a "$logdir/$name.log"
done
