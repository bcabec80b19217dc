#!/usr/bin/env bash
# Self-test of the Python helper tools (tools/sympy_baseline.py, tools/count_ops_c.py,
# tools/plot_convergence.py, tools/render_stl.py, tools/weierstrass_areas.py). Needs Debian's
# /usr/bin/python3 (sympy, mpmath, matplotlib) and gcc.
# Prints "N passed, M failed" last; exits non-zero if anything failed. Runs in ~10 s.
#
#   bash tests/tools/test_python_tools.sh
set -u

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PY=/usr/bin/python3
CC="${CC:-gcc}"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
PASS=0
FAIL=0

ok()   { PASS=$((PASS + 1)); echo "PASS: $1"; }
bad()  { FAIL=$((FAIL + 1)); echo "FAIL: $1"; }
# check "description" command...: pass when the command succeeds.
check() { local d="$1"; shift; if "$@"; then ok "$d"; else bad "$d"; fi; }
# json_get FILE KEY: print one top-level field of a JSON file.
json_get() { "$PY" -c 'import json,sys; v=json.load(open(sys.argv[1]))[sys.argv[2]]; print(json.dumps(v))' "$1" "$2"; }

# ------------------------------------------------------------ sympy_baseline.py
test_sympy_baseline() {
  local j="$TMP/g2.json" c="$TMP/g2.c"
  if ! "$PY" "$ROOT/tools/sympy_baseline.py" --surface gyroid --order 2 \
       --emit-c "$c" --json "$j" --eval 0.1 0.2 0.3 0.01 >"$TMP/g2.out" 2>&1; then
    bad "sympy_baseline gyroid order 2 runs"; cat "$TMP/g2.out"; return
  fi
  ok "sympy_baseline gyroid order 2 runs"
  check "json surface/order" [ "$(json_get "$j" surface)$(json_get "$j" order)" = '"gyroid"2' ]
  check "json cse_count_ops == 98" [ "$(json_get "$j" cse_count_ops)" = 98 ]
  check "json gen_cpu_seconds > 0" "$PY" -c \
    'import json,sys; v=json.load(open(sys.argv[1]))["gen_cpu_seconds"]; sys.exit(not (isinstance(v,float) and v > 0))' "$j"
  check "json pow_calls matches C text" [ "$(json_get "$j" pow_calls)" = "$(grep -o 'pow(' "$c" | wc -l)" ]
  check "json c_bytes matches file size" [ "$(json_get "$j" c_bytes)" = "$(wc -c <"$c")" ]
  check "emitted C compiles (gcc -std=c99 -O2 -c)" \
    "$CC" -std=c99 -O2 -Wall -Werror -c "$c" -o "$TMP/g2.o"

  cat >"$TMP/main.c" <<'EOF'
#include <stdio.h>
double sympy_gyroid_o2_offset(double x, double y, double z, double h);
int main(void) { printf("%.17g\n", sympy_gyroid_o2_offset(0.1, 0.2, 0.3, 0.01)); return 0; }
EOF
  if "$CC" -std=c99 -O2 "$TMP/main.c" "$TMP/g2.o" -lm -o "$TMP/g2eval"; then
    local got want
    got="$("$TMP/g2eval")"
    want="$("$PY" -c 'import json,sys; print(repr(json.load(open(sys.argv[1]))["eval"]["value"]))' "$j")"
    check "C value $got == SymPy value $want (1e-12)" "$PY" -c \
      'import sys; a,b=float(sys.argv[1]),float(sys.argv[2]); sys.exit(not abs(a-b) <= 1e-12*max(1,abs(b)))' "$got" "$want"
  else
    bad "C evaluation harness links"
  fi

  "$PY" "$ROOT/tools/sympy_baseline.py" --surface gyroid --order 5 --timeout 1 \
    --json "$TMP/t.json" >/dev/null 2>&1
  check "timeout exits 3" [ $? -eq 3 ]
  check "timeout json has timed_out=true" [ "$(json_get "$TMP/t.json" timed_out 2>/dev/null)" = true ]
  "$PY" "$ROOT/tools/sympy_baseline.py" --surface nosuch --order 2 >/dev/null 2>&1
  check "unknown surface exits 2" [ $? -eq 2 ]
}

# ------------------------------------------------------------ count_ops_c.py
write_sample_header() {
  # Counts by hand with SymPy's rules (x*x is POW, a/b is DIV, -a is NEG, sqrt is POW+DIV):
  cat >"$1" <<'EOF'
#pragma once
#include <math.h>
/* a prototype first: must be skipped */
static inline double sample_o1_offset(double x, double y, double z, double h);

static inline double sample_o1_offset(double x, double y, double z, double h)
{
    const double _t0 = 6.2831853071795862 * x;          /* MUL             = 1 */
    const double _t1 = sin(_t0);                         /* SIN             = 1 */
    const double _t2 = cos(_t0) * _t1 + 2.0 * y;         /* COS MUL MUL ADD = 4 */
    const double _t3 = fabs(_t2 - z) / h;                /* ABS SUB DIV     = 3 */
    // a comment with ; and { braces } must be ignored
    const double _t4 = (_t3 > -12.3 && _t3 < 12.3) ? _t3 : (_t3 >= 12.3 ? 12.3 : -12.3); /* 6 */
    return _t1 - _t2 * _t4;                              /* SUB MUL         = 2 */
}                                                        /* total 17, 6 lines */

static inline float samplef(float x, float y, float z, float h)
{
    const float _t0 = 6.28318531f * x;                   /* MUL               = 1 */
    const float _t1 = sinf(_t0) * cosf((float)y);        /* SIN COS MUL       = 3 */
    const float _t2 = -_t1 + 1.5e-3f * h;                /* MUL SUB           = 2 */
    return fmaxf(_t2, 0.0f) * (z > 0.0f ? 1.0f : -1.0f); /* MAX MUL CMP SEL   = 4 */
}                                                        /* total 10, 4 lines */

static inline void sample_normal(double x, double y, double z, double n[3])
{
    const double _t0 = x * x + y * y + z * z;            /* 3 POW 2 ADD       = 5 */
    const double _t1 = 1.0 / sqrt(_t0);                  /* POW DIV DIV       = 3 */
    n[0] = x * _t1;                                      /* MUL               = 1 */
    n[1] = y * _t1;
    n[2] = z * _t1;
}                                                        /* total 11, 5 lines */
EOF
}

expect_count() {  # expect_count HEADER FUNCTION OPS LINES
  local out
  out="$("$PY" "$ROOT/tools/count_ops_c.py" "$1" "$2" 2>&1)"
  check "count_ops_c $2 == $3 ops / $4 lines (got: $out)" "$PY" -c \
    'import json,sys; d=json.loads(sys.argv[1]); sys.exit(not (d["function"]==sys.argv[2] and d["sympy_count_ops"]==int(sys.argv[3]) and d["lines"]==int(sys.argv[4])))' \
    "$out" "$2" "$3" "$4"
}

test_count_ops_c() {
  local h="$TMP/sample.h"
  write_sample_header "$h"
  expect_count "$h" sample_o1_offset 17 6
  expect_count "$h" samplef 10 4
  expect_count "$h" sample_normal 11 5
  "$PY" "$ROOT/tools/count_ops_c.py" "$h" no_such_function >/dev/null 2>&1
  check "count_ops_c missing function exits 2" [ $? -eq 2 ]
  # Cross-check against SymPy itself: the baseline's own C counts the same as its cse output.
  if [ -f "$TMP/g2.c" ]; then
    expect_count "$TMP/g2.c" sympy_gyroid_o2_offset 98 34
  fi
}

# ------------------------------------------------------------ plot_convergence.py
file_larger_than() { [ -f "$1" ] && [ "$(wc -c <"$1")" -gt "$2" ]; }

test_plot_convergence() {
  cat >"$TMP/conv.json" <<'EOF'
{"title": "sample: offset error vs h/L", "xlabel": "h/L", "ylabel": "mean relative error",
 "series": [
  {"label": "order 1", "order": 1, "x": [0.001, 0.003, 0.01, 0.03, 0.1], "y": [3e-4, 9e-4, 3e-3, 9e-3, 3e-2]},
  {"label": "order 2", "order": 2, "x": [0.001, 0.003, 0.01, 0.03, 0.1], "y": [5e-7, 4.5e-6, 5e-5, 4.5e-4, 5e-3]},
  {"label": "order 4", "order": 4, "x": [0.001, 0.003, 0.01, 0.03, 0.1], "y": [0, null, 2e-8, 1.6e-6, 2e-4]}],
 "slope_triangles": true,
 "hline": [{"y": 1e-6, "label": "1e-6"}]}
EOF
  "$PY" "$ROOT/tools/plot_convergence.py" "$TMP/conv.json" "$TMP/conv.png" >/dev/null 2>&1
  check "plot_convergence exits 0" [ $? -eq 0 ]
  check "PNG exists and > 5 kB" file_larger_than "$TMP/conv.png" 5120
  check "PNG signature" [ "$(head -c 4 "$TMP/conv.png" | tail -c 3)" = PNG ]
  check "a new PNG gets 0666 less the umask (0644 under umask 022), not mkstemp's 0600" \
    [ "$(umask 022; "$PY" "$ROOT/tools/plot_convergence.py" "$TMP/conv.json" "$TMP/mode.png" >/dev/null 2>&1; stat -c %a "$TMP/mode.png")" = 644 ]
  chmod 0640 "$TMP/conv.png"
  "$PY" "$ROOT/tools/plot_convergence.py" "$TMP/conv.json" "$TMP/conv.png" >/dev/null 2>&1
  check "a replaced PNG keeps its mode" [ "$(stat -c %a "$TMP/conv.png")" = 640 ]
  echo '{"series": [{"x": [1, 2], "y": [1]}]}' >"$TMP/bad.json"
  "$PY" "$ROOT/tools/plot_convergence.py" "$TMP/bad.json" "$TMP/bad.png" >/dev/null 2>&1
  check "bad plot input exits 2" [ $? -eq 2 ]
  check "bad plot input leaves no file" [ ! -e "$TMP/bad.png" ]
}

# ------------------------------------------------------------ render_stl.py
test_render_stl() {
  # A unit cube as 12 outward facets of binary STL.
  "$PY" - "$TMP/cube.stl" <<'PYEOF'
import struct, sys
v = [(i & 1, (i >> 1) & 1, (i >> 2) & 1) for i in range(8)]
faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
tris = [t for a, b, c, d in faces for t in ((a, b, c), (a, c, d))]
with open(sys.argv[1], "wb") as f:
    f.write(b"binary STL: cube".ljust(80) + struct.pack("<I", len(tris)))
    for t in tris:
        f.write(struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *v[i]) for i in t) + b"\0\0")
PYEOF
  "$PY" "$ROOT/tools/render_stl.py" "$TMP/cube.stl" "$TMP/cube.png" --size 200 >"$TMP/render.out" 2>&1
  check "render_stl exits 0" [ $? -eq 0 ]
  check "render_stl draws the 6 facets facing the viewer" grep -q "(6 visible facets of 12)" "$TMP/render.out"
  check "render_stl PNG signature" [ "$(head -c 4 "$TMP/cube.png" | tail -c 3)" = PNG ]
  head -c 300 "$TMP/cube.stl" >"$TMP/cut.stl"
  "$PY" "$ROOT/tools/render_stl.py" "$TMP/cut.stl" "$TMP/cut.png" >/dev/null 2>&1
  check "render_stl: a truncated STL exits 2" [ $? -eq 2 ]
  check "render_stl: a truncated STL leaves no file" [ ! -e "$TMP/cut.png" ]
}

# ------------------------------------------------------------ weierstrass_areas.py
# The exact areas it computes are the ones docs/density.md quotes, and match issue 26's own
# Weierstrass computation (G 3.091444, P 2.3451, D 3.8378).
test_weierstrass_areas() {
  local out="$TMP/weierstrass.md"
  if ! "$PY" "$ROOT/tools/weierstrass_areas.py" >"$out" 2>&1; then
    bad "weierstrass_areas runs"; cat "$out"; return
  fi
  ok "weierstrass_areas runs"
  check "Bonnet angle of G 38.0148" grep -q "^| Schoen G | 38.0148 |" "$out"
  local name value
  for name in "Schwarz P:2.345103" "Schwarz D:3.837785" "Schoen G:3.091444"; do
    value="${name#*:}"
    check "${name%%:*} A = $value" grep -q "^| ${name%%:*} |.*| $value |$" "$out"
    check "docs/density.md quotes ${name%%:*} $value" grep -q "| $value | our Weierstrass computation |" \
      "$ROOT/docs/density.md"
  done
}

test_sympy_baseline
test_count_ops_c
test_plot_convergence
test_render_stl
test_weierstrass_areas
echo "$PASS passed, $FAIL failed"
[ "$FAIL" -eq 0 ]
