#!/usr/bin/env python3
"""Fills real bodies at many settings and judges every part as a printer's user would (issue 39,
docs/parts.md "Sound at every setting"). The factors:

- bodies: PrusaSlicer's sphere (31 mm) and torus (28.5 mm, a hole through it), its bunny at --scale
  0.5, and OpenSCAD's example001 (three holes through a sphere);
- cell size 4, 6 and 10 mm; voxel automatic or 0.1 mm; skin 0.8 or 1.5 mm;
- walls: gyroid and diamond sheets at --density 0.25, and a gyroid network at --density 0.3.

Each part must be left unchanged by admesh (0 facets added, 0 degenerate, 0 backwards, 0 edges fixed,
0 disconnected), be manifold for `prusa-slicer --info` (one call per file, no slicing), have its skin
at least --skin less one voxel, and drop no solid piece of a voxel's volume or more (a speck that the
voxels cut off the walls where they meet the skin is smaller). The lattice's share of the core, measured
on the mesh, must be within 0.02 of the same share sampled on the voxels (no mesh involved), and, where
the core holds at least MIN_CORE_CELLS cells, of the requested density: a smaller core holds too few
cells for its share of the lattice to be the lattice's density (a network's struts, a few millimetres
thick, least of all).

By default 12 parts: every body at every cell size, the other three factors spread so that every
pair of levels of any two factors meets at least once (ctest mesh_parts_sweep_is_sound, label slow).
--full runs all 144 combinations (the table in docs/parts.md). Prints a Markdown table; exits 1 on
a failure.

    tools/sweep_parts.py BUILD_DIR OUT_DIR [--full]
"""
import itertools
import os
import sys

from part_checks import EXAMPLES, SHAPES, admesh, admesh_clean, body_stl, prusa_info, run, summary_figures

BODIES = [  # name, source, --scale
    ("sphere", f"{SHAPES}/sphere.stl", 1),
    ("torus", f"{SHAPES}/torus.stl", 1),
    ("bunny", f"{SHAPES}/bunny.stl", 0.5),
    ("example001", f"{EXAMPLES}/Old/example001.scad", 1),
]
CELLS = [4, 6, 10]
VOXELS = ["auto", "0.1"]
SKINS = [0.8, 1.5]
WALLS = [  # name, arguments, density
    ("gyroid sheet", ["--surface", "gyroid", "--density", "0.25"], 0.25),
    ("diamond sheet", ["--surface", "diamond", "--density", "0.25"], 0.25),
    ("gyroid network", ["--surface", "gyroid", "--network", "--density", "0.3"], 0.3),
]
MIN_CORE_CELLS = {"sheet": 4, "network": 30}
# The pairwise design: for (body, cell) in order, the voxel and skin indices; the wall is
# (body + cell) mod 3. Every pair of levels of any two factors meets at least once.
PAIRWISE_VOXEL = [0, 0, 1, 0, 0, 1, 0, 0, 1, 1, 1, 0]
PAIRWISE_SKIN = [0, 0, 1, 0, 0, 1, 0, 1, 0, 1, 1, 0]


def settings(full):
    if full:
        yield from itertools.product(range(len(BODIES)), range(len(CELLS)), range(len(VOXELS)), range(len(SKINS)),
                                     range(len(WALLS)))
        return
    for row, (b, c) in enumerate(itertools.product(range(len(BODIES)), range(len(CELLS)))):
        yield b, c, PAIRWISE_VOXEL[row], PAIRWISE_SKIN[row], (b + c) % len(WALLS)


def main():
    build, out_dir = sys.argv[1], sys.argv[2]
    full = "--full" in sys.argv[3:]
    os.makedirs(out_dir, exist_ok=True)
    offsetgen = os.path.join(build, "offsetgen")
    failures, rows = [], []
    for b, c, v, s, w in settings(full):
        name, source, scale = BODIES[b]
        cell, voxel, skin = CELLS[c], VOXELS[v], SKINS[s]
        wall, wall_args, density = WALLS[w]
        label = f"{name}, cell {cell}, voxel {voxel}, skin {skin}, {wall}"
        if not os.path.exists(source):
            failures.append(f"{label}: {source} is missing (apt-get install prusa-slicer openscad)")
            continue
        body = body_stl(name, source, out_dir)
        part = os.path.join(out_dir, "part.stl")
        cmd = [offsetgen, "mesh", *wall_args, "--body", body, "--scale", str(scale), "--skin", str(skin),
               "--cell-size", str(cell), "-o", part]
        if voxel != "auto":
            cmd[-2:-2] = ["--voxel", voxel]
        r = run(cmd)
        if r.returncode != 0:
            failures.append(f"{label}: offsetgen mesh exited {r.returncode}: {r.stdout}{r.stderr}")
            rows.append(f"| {name} | {cell} | {voxel} | {skin} | {wall} | exit {r.returncode} | | | | | |")
            continue
        f = summary_figures(r.stdout)
        a = admesh(part)
        manifold = prusa_info(part).get("manifold")
        os.remove(part)  # up to half a gigabyte each
        core_cells = f["core"] / cell ** 3
        large_core = core_cells >= MIN_CORE_CELLS[wall.split()[-1]]
        checks = {
            "admesh left it unchanged": admesh_clean(a),
            "PrusaSlicer calls it manifold": manifold == "yes",
            "skin at least --skin less a voxel": f["thinnest"] >= skin - f["voxel"],
            "no solid piece of a voxel dropped": f["dropped_volume"] < f["voxel"] ** 3,
            "core density on the mesh within 0.02 of the voxels'": abs(f["lattice"] - f["sampled"]) <= 0.02,
        }
        if large_core:
            checks["core density within 0.02 of the request"] = abs(f["lattice"] - density) <= 0.02
        for check, ok in checks.items():
            if not ok:
                failures.append(f"{label}: {check} failed (admesh {a}, manifold {manifold}, figures {f})")
        density_text = f"{f['lattice']:.4f} / {f['sampled']:.4f}" + ("" if large_core else f" ({core_cells:.1f} cells)")
        rows.append(f"| {name} | {cell} | {f['voxel']:.4g} | {skin} | {wall} | {f['triangles']} | "
                    f"{a['added']:.0f} / {a['degenerate']:.0f} / {a['backwards']:.0f} / {a['fixed']:.0f} | {manifold} | "
                    f"{f['thinnest']:.3f} | {density_text} | {f['seconds']:.1f} |")
    print(f"{len(rows)} parts ({'all combinations' if full else 'pairwise'}); the core density against the request "
          f"where the core holds at least {MIN_CORE_CELLS['sheet']} cells (sheets) or {MIN_CORE_CELLS['network']} "
          f"(networks), else the number of cells in brackets.\n")
    print("| body | cell mm | voxel mm | skin mm | walls | triangles | admesh added / degenerate / backwards / fixed |"
          " manifold | thinnest skin mm | core density, mesh / voxels | time s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))
    for f in failures:
        print("FAIL:", f, file=sys.stderr)
    print(f"{len(rows) - len({f.split(':')[0] for f in failures})} passed, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
