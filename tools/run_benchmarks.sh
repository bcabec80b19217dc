#!/usr/bin/env bash
# Runs the whole benchmark suite (issue 6) in one go on this machine and writes BENCHMARKS.md:
#   generation time and peak memory per catalog surface and order (end to end through the CLI),
#   the naive nested-GiNaC-diff baseline, SymPy's pipeline, op counts (ours, ours under SymPy's
#   count_ops rules, SymPy's cse), ns per point of the scalar functions at -O2 and -O3 -march=native
#   against SymPy's C and nested AD, the batch API, and the float path.
# Every timing is the median of repetitions (the machine is shared and noisy).
#
# Usage: tools/run_benchmarks.sh [--quick] [--sympy-o5] [--methods-only] [--build-dir DIR] [--output FILE]
#   --quick      fewer repetitions (a smoke run, ~5 minutes after the build)
#   --methods-only  only the offset methods side by side (issue 10: bench_methods and generation time
#                of both methods), in a run of its own that replaces just that section of the output
#   --sympy-o5   also run SymPy's pipeline for the gyroid at order 5 once (~76 s more)
# Needs the packages of tools/install_deps.sh (libbenchmark-dev, python3-sympy, time).
set -euo pipefail
cd "$(dirname "$0")/.."

build=build-bench
output=BENCHMARKS.md
quick=0
sympy_o5=0
methods_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --sympy-o5) sympy_o5=1 ;;
    --methods-only) methods_only=1 ;;
    --build-dir) build=$2; shift ;;
    --output) output=$2; shift ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "run_benchmarks: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done

py=/usr/bin/python3   # Debian's python, the one with sympy
gen_reps=7; naive_reps=3; sympy_reps=3; bench_reps=7; min_time=0.1
if [ $quick -eq 1 ]; then gen_reps=3; naive_reps=1; sympy_reps=1; bench_reps=3; min_time=0.05; fi
naive_cap=120   # seconds; the naive baseline grows ~25x per order
jobs=$(nproc)

results=$build/bench/results
started=$(date +%s)
stamp() { echo "[run_benchmarks $(( $(date +%s) - started ))s] $*"; }

machine_facts() {
  echo "date=$(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- src templates 2>/dev/null || echo '+local changes')"
  echo "cpu=$(lscpu | sed -n 's/^Model name: *//p' | head -1)"
  echo "cores=$(nproc)"
  echo "compiler=$(${CC:-cc} --version | head -1)"
  echo "load_start=$(cut -d' ' -f1-3 /proc/loadavg)"
}

# Generation time of one method: surface x order runs, through the CLI, into <results>/gen_<method>.tsv.
time_method_generation() {  # method orders... (surfaces from $surfaces)
  local method=$1; shift
  echo -e "surface\torder\trep\twall_s\tuser_s\tsys_s\tmaxrss_kb" > "$results/gen_$method.tsv"
  mkdir -p "$results/gen_$method"
  for surface in $surfaces; do
    for order in "$@"; do
      header="$results/gen_$method/${surface}_o${order}.h"
      $py bench/time_cli.py --runs "$gen_reps" --prefix "$surface\t$order\t" --before "rm -f $header" -- \
        "$offsetgen" generate --surface "$surface" --order "$order" --method "$method" --lang c -o "$header" --quiet \
        >> "$results/gen_$method.tsv"
    done
  done
}

run_bench_methods() {
  "$bench/bench_methods" --benchmark_repetitions="$bench_reps" --benchmark_report_aggregates_only=true \
    --benchmark_min_time="$min_time" --benchmark_out="$results/methods.json" --benchmark_out_format=json \
    > "$results/methods.txt"
  mkdir -p "$results/gen"
  cp "$bench"/generated/*_richardson_o*.h "$bench"/generated/*_projection_o*.h "$results/gen/"
}

if [ $methods_only -eq 1 ]; then
  stamp "configure and build ($build): offsetgen, bench_methods"
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DOFFSETGEN_BUILD_BENCHMARKS=ON -DOFFSETGEN_BUILD_TESTS=OFF > /dev/null
  build_start=$(date +%s)
  cmake --build "$build" -j"$jobs" --target offsetgen bench_methods > "$build/bench_build.log" 2>&1 ||
    { tail -30 "$build/bench_build.log" >&2; exit 1; }
  build_seconds=$(( $(date +%s) - build_start ))
  rm -rf "$results"
  mkdir -p "$results"
  offsetgen=$build/offsetgen
  bench=$build/bench
  { machine_facts; echo "build_seconds=$build_seconds"; echo "quick=$quick"; } > "$results/machine.txt"
  surfaces="gyroid schwarzp neovius diamond"
  stamp "generation: 4 surfaces, richardson orders 2, 4, 8 and projection orders 2, 4, 8, 12, 16"
  time_method_generation richardson 2 4 8
  time_method_generation projection 2 4 8 12 16
  stamp "offset methods side by side: bench_methods ($bench_reps repetitions)"
  run_bench_methods
  echo "load_end=$(cut -d' ' -f1-3 /proc/loadavg)" >> "$results/machine.txt"
  echo "total_seconds=$(( $(date +%s) - started ))" >> "$results/machine.txt"
  stamp "replacing the methods section of $output"
  $py bench/report.py --results "$results" --output "$output" --methods-only
  stamp "done: $output"
  exit 0
fi

stamp "configure and build ($build)"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DOFFSETGEN_BUILD_BENCHMARKS=ON -DOFFSETGEN_BUILD_TESTS=ON > /dev/null
build_start=$(date +%s)
cmake --build "$build" -j"$jobs" --target benchmarks batch_tests > "$build/bench_build.log" 2>&1 ||
  { tail -30 "$build/bench_build.log" >&2; exit 1; }
build_seconds=$(( $(date +%s) - build_start ))

rm -rf "$results"
mkdir -p "$results/gen" "$results/sympy"
offsetgen=$build/offsetgen
bench=$build/bench

# ---- Machine -----------------------------------------------------------------------------------
{
  echo "date=$(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- src templates 2>/dev/null || echo '+local changes')"
  echo "cpu=$(lscpu | sed -n 's/^Model name: *//p' | head -1)"
  echo "cores=$(nproc)"
  echo "compiler=$(${CC:-cc} --version | head -1)"
  echo "sympy=$($py -c 'import sympy; print(sympy.__version__)' 2>/dev/null || echo missing)"
  echo "ginac=$(pkg-config --modversion ginac)"
  echo "benchmark=$(dpkg-query -W -f='${Version}' libbenchmark-dev 2>/dev/null || echo unknown)"
  echo "load_start=$(cut -d' ' -f1-3 /proc/loadavg)"
  echo "build_seconds=$build_seconds"
  echo "quick=$quick"
} > "$results/machine.txt"

# ---- Generation time and peak memory, end to end through the CLI --------------------------------
surfaces=$("$offsetgen" list | awk '/^[a-z]/ {print $1}')
stamp "generation: $(echo $surfaces | wc -w) surfaces x orders 1-8, $gen_reps runs each"
echo -e "surface\torder\trep\twall_s\tuser_s\tsys_s\tmaxrss_kb" > "$results/gen.tsv"
time_generate() {  # surface order runs
  local header="$results/gen/$1_o$2.h"
  # The file is deleted before every run, so every run writes it.
  $py bench/time_cli.py --runs "$3" --prefix "$1\t$2\t" --before "rm -f $header" -- \
    "$offsetgen" generate --surface "$1" --order "$2" --lang c -o "$header" --quiet >> "$results/gen.tsv"
}
for surface in $surfaces; do
  for order in 1 2 3 4 5 6 7 8; do time_generate "$surface" "$order" "$gen_reps"; done
done
stamp "generation: gyroid order 10 (works at all), once"
time_generate gyroid 10 1

# The projection method (issue 10): orders 2-16 through the same CLI path.
stamp "generation, projection method: orders 2, 4, 8, 12, 16, $gen_reps runs each"
time_method_generation projection 2 4 8 12 16

# ---- Naive baseline: plain nested GiNaC diff ---------------------------------------------------------
stamp "naive nested GiNaC diff: orders 1-6, cap ${naive_cap}s"
: > "$results/naive.jsonl"
for surface in gyroid schwarzp neovius diamond; do
  for order in 1 2 3 4 5 6; do
    [ "$surface" != gyroid ] && [ "$order" -gt 5 ] && continue
    reps=$naive_reps
    [ "$order" -ge 6 ] && reps=1
    timed_out=0
    for rep in $(seq "$reps"); do
      if ! timeout "$naive_cap" "$bench/bench_naive_ginac" --surface "$surface" --order "$order" >> "$results/naive.jsonl"; then
        echo "{\"surface\": \"$surface\", \"order\": $order, \"timed_out\": true, \"cap\": $naive_cap}" >> "$results/naive.jsonl"
        timed_out=1
        break
      fi
    done
    [ $timed_out -eq 1 ] && break
  done
done

# ---- SymPy's pipeline ------------------------------------------------------------------------------
stamp "SymPy pipeline: 4 surfaces x orders 1-4, $sympy_reps runs each"
: > "$results/sympy.jsonl"
run_sympy() {  # surface order
  local stem="$results/sympy/sympy_$1_o$2"
  /usr/bin/time -f "%e\t%M" -o "$results/time.tmp" \
    "$py" tools/sympy_baseline.py --surface "$1" --order "$2" --emit-c "$stem.c" --json "$stem.json" --timeout 900 > /dev/null || true
  $py -c "import json,sys; d=json.load(open(sys.argv[1])); w,m=open(sys.argv[2]).read().split(); d['wall_seconds']=float(w); d['maxrss_kb']=int(m); print(json.dumps(d))" \
    "$stem.json" "$results/time.tmp" >> "$results/sympy.jsonl"
}
for surface in gyroid schwarzp neovius diamond; do
  for order in 1 2 3 4; do
    for rep in $(seq "$sympy_reps"); do run_sympy "$surface" "$order"; done
  done
done
if [ $sympy_o5 -eq 1 ]; then
  stamp "SymPy pipeline: gyroid order 5, once"
  run_sympy gyroid 5
fi

# ---- Op counts under SymPy's count_ops rules ---------------------------------------------------------
stamp "op counts under SymPy's rules (tools/count_ops_c.py)"
: > "$results/count_ops.jsonl"
for surface in gyroid schwarzp neovius diamond; do
  for order in 1 2 3 4 5 6; do
    [ "$surface" != gyroid ] && [ "$order" -gt 4 ] && continue
    for function in offset shell; do
      $py tools/count_ops_c.py "$results/gen/${surface}_o${order}.h" "${surface}_o${order}_${function}" |
        $py -c "import json,sys; d=json.load(sys.stdin); d.update(surface='$surface', order=$order, kind='$function'); print(json.dumps(d))" \
        >> "$results/count_ops.jsonl"
    done
  done
done

# ---- ns per point -------------------------------------------------------------------------------------
for flags in O2 O3native O3native_nme; do
  stamp "evaluation benchmarks: $flags ($bench_reps repetitions)"
  "$bench/bench_eval_$flags" --benchmark_repetitions="$bench_reps" --benchmark_report_aggregates_only=true \
    --benchmark_min_time="$min_time" --benchmark_out="$results/eval_$flags.json" --benchmark_out_format=json \
    > "$results/eval_$flags.txt"
done
stamp "offset methods side by side: bench_methods ($bench_reps repetitions)"
run_bench_methods
stamp "batch agreement (tests/batch)"
"$build/tests/batch/batch_tests" --gtest_filter='BatchAgreement.*' > "$results/batch_agreement.txt" 2>&1 ||
  echo "run_benchmarks: batch agreement test FAILED (see $results/batch_agreement.txt)" >&2
echo "load_end=$(cut -d' ' -f1-3 /proc/loadavg)" >> "$results/machine.txt"
echo "total_seconds=$(( $(date +%s) - started ))" >> "$results/machine.txt"

stamp "writing $output"
$py bench/report.py --results "$results" --output "$output"
stamp "done: $output"
