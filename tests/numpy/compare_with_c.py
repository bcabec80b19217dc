"""Compares a generated NumPy module (<prefix>.py) with the double C header of the same generation
(<prefix>.h) on 10^5 points: half spread over the cell, half next to the offset surfaces (Newton
steps onto F = 0, then h along the normal). The C functions run through a small loop library this
script compiles with the system C compiler and loads with ctypes.

Figures of merit (as `offsetgen check` uses them): the zero-set shift |dphi| / |grad F| for the
field, offset, wall and graded functions, |dPhi| / (|grad F| (|phi+| + |phi-|)) for the shell,
|dn| for the normal, and the relative difference for the density relations (NaN where the C header
returns NaN). Exits 1 when any exceeds its limit, printing every function's maximum.

usage: compare_with_c.py MODULE.py HEADER.h CC WORK_DIR [--points N] [--limit 1e-12]
"""
import argparse
import ctypes
import importlib.util
import inspect
import os
import subprocess
import sys

import numpy as np

parser = argparse.ArgumentParser()
parser.add_argument("module")
parser.add_argument("header")
parser.add_argument("cc")
parser.add_argument("work_dir")
parser.add_argument("--points", type=int, default=100000)
parser.add_argument("--limit", type=float, default=1e-12)
parser.add_argument("--normal-limit", type=float, default=1e-10)
args = parser.parse_args()

prefix = os.path.splitext(os.path.basename(args.module))[0]
spec = importlib.util.spec_from_file_location(prefix, args.module)
module = importlib.util.module_from_spec(spec)
spec.loader.exec_module(module)

# name -> parameter names, from the module (the C header has the same functions and parameters).
functions = {name: list(inspect.signature(getattr(module, name)).parameters) for name in module.__all__}
if f"{prefix}_offset" not in functions:
    sys.exit(f"{args.module}: no {prefix}_offset in __all__")
dims = len([p for p in functions[f"{prefix}_field"] if p in ("x", "y", "z")])

# One loop per function over arrays: run_<name>(n, in0, in1, ..., out) (the normal writes dims outputs).
os.makedirs(args.work_dir, exist_ok=True)
lines = [f'#include "{os.path.abspath(args.header)}"']
for name, params in functions.items():
    ins = ", ".join(f"const double* a{k}" for k in range(len(params)))
    call = ", ".join(f"a{k}[i]" for k in range(len(params)))
    if name.endswith("_normal"):
        body = f"{name}({call}, out + {dims} * i);"
    else:
        body = f"out[i] = {name}({call});"
    lines.append(f"void run_{name}(size_t n, {ins}, double* out) {{ for (size_t i = 0; i < n; ++i) {body} }}")
source = os.path.join(args.work_dir, prefix + "_loops.c")
library = os.path.join(args.work_dir, prefix + "_loops.so")
with open(source, "w") as f:
    f.write("\n".join(lines) + "\n")
subprocess.run([args.cc, "-O1", "-shared", "-fPIC", "-o", library, source, "-lm"], check=True)
c = ctypes.CDLL(library)


def run_c(name, *inputs, components=1):
    arrays = [np.ascontiguousarray(np.broadcast_to(np.asarray(a, np.float64), inputs[0].shape)) for a in inputs]
    out = np.empty(inputs[0].shape[0] * components)
    pointer = ctypes.POINTER(ctypes.c_double)
    getattr(c, "run_" + name)(ctypes.c_size_t(len(arrays[0])), *[a.ctypes.data_as(pointer) for a in arrays],
                              out.ctypes.data_as(pointer))
    return out.reshape(-1, components) if components > 1 else out


def gradient(p):
    """grad F by central differences of the C field (a denominator: 1e-9 relative is plenty)."""
    e = 1e-6
    g = []
    for k in range(dims):
        plus, minus = p.copy(), p.copy()
        plus[k] += e
        minus[k] -= e
        g.append((run_c(f"{prefix}_field", *plus) - run_c(f"{prefix}_field", *minus)) / (2 * e))
    return np.array(g)


rng = np.random.default_rng(20210415)
half = args.points // 2
spread = rng.uniform(0.0, 1.0, (dims, half))
near = rng.uniform(0.0, 1.0, (dims, args.points - half))
for _ in range(4):  # Newton steps onto F = 0
    g = gradient(near)
    near = near - run_c(f"{prefix}_field", *near) * g / np.maximum(np.sum(g * g, axis=0), 1e-6)
h = rng.uniform(-0.1, 0.1, args.points)
g = gradient(near)
near = near + h[half:] * g / np.maximum(np.linalg.norm(g, axis=0), 1e-3)  # next to the offset surface at h
points = np.concatenate([spread, near], axis=1)
t = 2 * np.abs(h)
grad_norm = np.linalg.norm(gradient(points), axis=0)

results = []
failed = False
with np.errstate(all="ignore"):  # np.where's discarded branches
    for name, params in functions.items():
        suffix = name[len(prefix) + 1:]
        extra = {"h": h, "t": t}
        if params[0] == "x":
            inputs = list(points) + [extra[p] for p in params[dims:]]
        else:  # the density relations: one argument, swept over and beyond its range
            inputs = [np.linspace(-0.1, 1.1, args.points)]
        py = getattr(module, name)(*inputs)
        if suffix == "normal":
            cv = run_c(name, *inputs, components=dims)
            py = np.stack(np.broadcast_arrays(*py), axis=-1)
            measure = np.linalg.norm(py - cv, axis=1)
            limit = args.normal_limit
        elif suffix == "shell":
            cv = run_c(name, *inputs)
            plus = run_c(f"{prefix}_offset", *points, t / 2)
            minus = run_c(f"{prefix}_offset", *points, -t / 2)
            measure = np.abs(py - cv) / (grad_norm * (np.abs(plus) + np.abs(minus)))
            limit = args.limit
        elif params[0] == "x":
            cv = run_c(name, *inputs)
            measure = np.abs(py - cv) / grad_norm
            limit = args.limit
        else:
            cv = run_c(name, *inputs)
            if not np.array_equal(np.isnan(py), np.isnan(cv)):
                print(f"{name}: NaN at different arguments than the C header")
                failed = True
            both = ~np.isnan(cv)
            measure = np.abs(py[both] - cv[both]) / np.maximum(1.0, np.abs(cv[both]))
            limit = args.limit
        if np.shape(py) != np.shape(cv):
            print(f"{name}: shape {np.shape(py)} differs from {np.shape(cv)}")
            failed = True
        worst = float(np.max(np.where(np.isnan(measure), np.inf, measure))) if measure.size else 0.0
        ok = worst <= limit
        failed = failed or not ok
        print(f"{name:<40} points {len(measure):>7}  max {worst:.3e}  (limit {limit:.0e}) {'ok' if ok else 'FAIL'}")
sys.exit(1 if failed else 0)
