#!/usr/bin/python3
"""Benchmarks `offsetgen mesh` in tiles (issue 24): gyroid --thickness 0.1, 8 mm cells, 40 voxels per
cell, blocks of N^3 cells, binary STL; time, peak memory, triangles and throughput per block size, the
untiled single-grid path (--tile 0) beside it where it fits, and the 8^3 block split into 4 shares and
merged, compared byte for byte with the single run. Prints a Markdown section for BENCHMARKS.md.

    bench/tiles_bench.py BUILD_DIR SCRATCH_DIR [--sizes 4,8,12] [--untiled 4,8] [--runs 1]
"""
import argparse
import filecmp
import os
import platform
import re
import statistics
import subprocess
import sys
import time

ARGS = ["--surface", "gyroid", "--thickness", "0.1", "--cell-size", "8", "--resolution", "40"]


def run(cmd):
    """wall s, user+sys s, peak RSS MB, stdout (offsetgen execs offsetgen-mesh in the same process)."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    out, err = proc.stdout.read(), proc.stderr.read()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{out}{err}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, out


def number(text, pattern):
    return float(re.search(pattern, text).group(1))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("build")
    p.add_argument("scratch")
    p.add_argument("--sizes", default="4,8,12")
    p.add_argument("--untiled", default="4,8")
    p.add_argument("--runs", type=int, default=1)
    a = p.parse_args()
    offsetgen = os.path.join(a.build, "offsetgen")
    os.makedirs(a.scratch, exist_ok=True)
    stl = os.path.join(a.scratch, "block.stl")
    load = os.getloadavg()
    rows = []
    cases = [(int(n), "256 (default)") for n in a.sizes.split(",")] + [(int(n), "0 (untiled)") for n in a.untiled.split(",") if n]
    for n, tile in cases:
        cmd = [offsetgen, "mesh", *ARGS, "--cells", str(n), "--tile", tile.split()[0], "-o", stl]
        runs = [run(cmd) for _ in range(a.runs)]
        wall = statistics.median(r[0] for r in runs)
        cpu = statistics.median(r[1] for r in runs)
        rss = max(r[2] for r in runs)
        out = runs[-1][3]
        triangles = int(number(out, r"mesh:\s+(\d+) triangles"))
        samples = number(out, r"evaluation: (\d+) wall samples")
        sample_s = number(out, r"sample ([0-9.]+) s")
        admesh = subprocess.run(["admesh", stl], capture_output=True, text=True).stdout if n <= 8 else ""
        clean = ""
        if admesh:
            holes = number(admesh, r"Facets added\s*:\s*(\d+)")
            disc = number(admesh, r"Total disconnected facets\s*:\s*(\d+)")
            parts = number(admesh, r"Number of parts\s*:\s*(\d+)")
            clean = f"{holes:.0f} / {disc:.0f} / {parts:.0f}"
        rows.append(f"| {n}^3 | {tile} | {wall:.1f} | {cpu:.1f} | {rss:.0f} | {wall / n**3 * 1000:.0f} | {triangles} | "
                    f"{os.path.getsize(stl) / 1e6:.0f} | {samples / sample_s:.3g} | {triangles / wall:.3g} | {clean or 'not run'} |")
        print(rows[-1], file=sys.stderr)
    # The 8^3 block in 4 shares, merged, against the single run.
    single = os.path.join(a.scratch, "single.stl")
    run([offsetgen, "mesh", *ARGS, "--cells", "8", "-o", single])
    parts = []
    for i in range(4):
        part = os.path.join(a.scratch, f"part{i}.stl")
        run([offsetgen, "mesh", *ARGS, "--cells", "8", "--tile-range", f"{i}/4", "-o", part])
        parts.append(part)
    merged = os.path.join(a.scratch, "merged.stl")
    run([offsetgen, "mesh", "--merge", *parts, "-o", merged])
    same = filecmp.cmp(single, merged, shallow=False)
    for f in [stl, single, merged, *parts]:
        if os.path.exists(f):
            os.remove(f)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    cpu_name = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")),
                    platform.processor())
    print("## Tiles (issue 24): `offsetgen mesh` of gyroid blocks in tiles, STL streamed\n")
    print(f"`offsetgen mesh {' '.join(ARGS)} --cells N --tile T -o block.stl` (8 mm cells, 40 voxels per cell), "
          f"run by `bench/tiles_bench.py`; {'median of ' + str(a.runs) + ' runs' if a.runs > 1 else 'one run each'}. "
          f"{cpu_name}, {os.cpu_count()} cores, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, commit {commit}, "
          f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} at start. Peak RSS of the process (offsetgen "
          "execs offsetgen-mesh; the C compiler that builds the header is a child and not included).\n")
    print("| block | --tile | wall s | user + sys s | peak RSS MB | ms per cell | triangles | STL MB | samples/s "
          "(sample stage) | triangles/s (end to end) | admesh holes / disconnected / parts |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))
    print(f"\nThe 8^3 block meshed in 4 shares (`--tile-range 0/4` ... `3/4`, one after another here) and joined "
          f"with `--merge`: {'the same bytes as' if same else 'DIFFERENT bytes from'} the single run.\n")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
