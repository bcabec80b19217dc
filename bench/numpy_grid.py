#!/usr/bin/env python3
"""Times gyroid_o4_offset of the NumPy module (offsetgen generate --lang numpy) on a 128^3 grid:
plain NumPy, numba.njit over the same arrays, and numba.vectorize (one compiled loop, no
temporaries). Each is the median of --runs calls after one warm-up call (numba's compile time is
reported apart). With --update FILE it replaces the NumPy section of BENCHMARKS.md (between its
markers; bench/report.py keeps it when it rewrites the file).

usage: bench/numpy_grid.py --offsetgen build/offsetgen [--runs 7] [--n 128] [--update BENCHMARKS.md]
"""
import argparse
import datetime
import importlib.util
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

BEGIN = "<!-- numpy section: bench/numpy_grid.py --update BENCHMARKS.md replaces it -->"
END = "<!-- end of numpy section -->"


def load(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def median_seconds(call, runs):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def cpu_name():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--offsetgen", required=True)
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--n", type=int, default=128)
    parser.add_argument("--update")
    args = parser.parse_args()

    import numba

    work = tempfile.mkdtemp(prefix="offsetgen-numpy-bench-")
    subprocess.run([args.offsetgen, "generate", "--surface", "gyroid", "--order", "4", "--lang", "numpy",
                    "--out-dir", work, "-q"], check=True)
    module = load(os.path.join(work, "gyroid_o4.py"), "gyroid_o4")
    offset = module.gyroid_o4_offset

    axis = np.linspace(0.0, 1.0, args.n)
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    h = 0.05
    points = x.size
    load_start = os.getloadavg()

    with np.errstate(all="ignore"):
        reference = offset(x, y, z, h)
        t_numpy = median_seconds(lambda: offset(x, y, z, h), args.runs)

        jitted = numba.njit(offset)
        start = time.perf_counter()
        jit_value = jitted(x, y, z, h)
        compile_njit = time.perf_counter() - start
        t_njit = median_seconds(lambda: jitted(x, y, z, h), args.runs)

        start = time.perf_counter()
        ufunc = numba.vectorize(["float64(float64, float64, float64, float64)"])(offset)
        vec_value = ufunc(x, y, z, h)
        compile_vec = time.perf_counter() - start
        t_vec = median_seconds(lambda: ufunc(x, y, z, h), args.runs)

    diff_njit = float(np.max(np.abs(jit_value - reference)))
    diff_vec = float(np.max(np.abs(vec_value - reference)))
    load_end = os.getloadavg()
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                            cwd=os.path.dirname(os.path.abspath(__file__))).stdout.strip() or "unknown"

    def ns(t):
        return f"{t * 1e9 / points:.1f}"

    lines = [
        BEGIN,
        "## NumPy module: numpy against numba (issue 15)",
        "",
        f"From a run of its own (`bench/numpy_grid.py --offsetgen {args.offsetgen} --runs {args.runs}`): "
        f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC, commit {commit}, {cpu_name()}, {os.cpu_count()} cores, "
        f"load average {' '.join(f'{v:.2f}' for v in load_start)} at the start and "
        f"{' '.join(f'{v:.2f}' for v in load_end)} at the end; Python {platform.python_version()}, "
        f"NumPy {np.__version__}, numba {numba.__version__} (Debian 12 packages).",
        "",
        f"`gyroid_o4_offset(x, y, z, 0.05)` of `gyroid_o4.py` (586 ops) on a {args.n}^3 grid ({points:,} points, "
        f"float64, `np.meshgrid(..., indexing=\"ij\")` arrays), median of {args.runs} calls after a warm-up call. "
        "numba.njit runs the module's function unchanged over the same arrays (numba's array expressions: "
        "one temporary per line, as NumPy); numba.vectorize compiles it per element into a ufunc.",
        "",
        "| implementation | median time | ns per point | speed-up over NumPy | max difference to NumPy | compile time |",
        "|---|---|---|---|---|---|",
        f"| NumPy | {t_numpy * 1e3:.0f} ms | {ns(t_numpy)} | 1x | - | - |",
        f"| numba.njit | {t_njit * 1e3:.0f} ms | {ns(t_njit)} | {t_numpy / t_njit:.2f}x | {diff_njit:.1e} | "
        f"{compile_njit:.1f} s |",
        f"| numba.vectorize | {t_vec * 1e3:.0f} ms | {ns(t_vec)} | {t_numpy / t_vec:.2f}x | {diff_vec:.1e} | "
        f"{compile_vec:.1f} s |",
        "",
        END,
    ]
    section = "\n".join(lines)
    print(section)
    if args.update:
        text = open(args.update).read() if os.path.exists(args.update) else "# Benchmarks\n\n"
        if BEGIN in text and END in text:
            text = text[:text.index(BEGIN)] + section + text[text.index(END) + len(END):]
        elif "## How to reproduce" in text:
            at = text.index("## How to reproduce")
            text = text[:at] + section + "\n\n" + text[at:]
        else:
            text += "\n" + section + "\n"
        with open(args.update, "w") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
