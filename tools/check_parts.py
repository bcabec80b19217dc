#!/usr/bin/env python3
"""Fills real parts that nobody on this project drew with a lattice inside a skin, and checks each
result as a printer's user would (issue 23, docs/parts.md):

- admesh: 0 holes (facets added), 0 disconnected facets, 0 backwards edges;
- `prusa-slicer --info`: manifold = yes; one `prusa-slicer --export-gcode` run slices all parts;
- the part's bounding box equals the body's within one voxel on every side;
- its volume within 1% of V_skin + rho V_core (from the body's level set, as offsetgen reports it);
- the skin, measured on the written mesh, at least --skin minus one voxel.

The bodies: PrusaSlicer's sample shapes (Debian prusa-slicer) and OpenSCAD examples rendered to STL
(Debian openscad), one of them with holes through it. Prints a Markdown table; exits 1 on a failure.

    tools/check_parts.py BUILD_DIR OUT_DIR
"""
import os
import re
import sys

from part_checks import EXAMPLES, SHAPES, admesh, body_stl, box, prusa_info, run, summary_figures

# name, source, skin (mm), cell (mm), voxel (mm), what it is
BODIES = [
    ("sphere", f"{SHAPES}/sphere.stl", 1.2, 6, 0.2, "PrusaSlicer's sphere, 31 mm"),
    ("torus", f"{SHAPES}/torus.stl", 0.6, 3, 0.1, "PrusaSlicer's torus, 28.5 x 5.7 mm: a hole through it"),
    ("example001", f"{EXAMPLES}/Old/example001.scad", 1.2, 6, 0.2,
     "OpenSCAD example001: a sphere with three holes through it, 43 mm"),
    ("CSG", f"{EXAMPLES}/Basics/CSG.scad", 1.0, 6, 0.2, "OpenSCAD CSG: cube, sphere, cylinders, 65 x 20 x 20 mm"),
]
DENSITY = 0.3


def main():
    build, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    offsetgen = os.path.join(build, "offsetgen")
    failures = []
    rows = []
    parts = []
    for name, source, skin, cell, voxel, what in BODIES:
        if not os.path.exists(source):
            failures.append(f"{name}: {source} is missing (apt-get install prusa-slicer openscad)")
            continue
        body = body_stl(name, source, out_dir)
        part = os.path.join(out_dir, name + "_part.stl")
        r = run([offsetgen, "mesh", "--surface", "gyroid", "--density", str(DENSITY), "--body", body, "--skin",
                 str(skin), "--cell-size", str(cell), "--voxel", str(voxel), "-o", part])
        if r.returncode != 0:
            failures.append(f"{name}: offsetgen mesh exited {r.returncode}: {r.stdout}{r.stderr}")
            continue
        summary = r.stdout
        print(summary, file=sys.stderr)
        parts.append(part)
        a = admesh(part)
        info, body_info = prusa_info(part), prusa_info(body)
        side = max(max(abs(p[0] - b[0]), abs(p[1] - b[1])) for p, b in zip(box(info), box(body_info)))
        f = summary_figures(summary)
        volume_error, thinnest, lattice = f["volume_error"], f["thinnest"], f["lattice"]
        triangles, seconds = f["triangles"], f["seconds"]
        checks = {
            "admesh clean": a["added"] == 0 and a["disconnected"] == 0 and a["backwards"] == 0,
            "manifold": info.get("manifold") == "yes",
            "box within a voxel": side <= voxel,
            "volume within 1%": abs(volume_error) <= 1.0,
            "skin": thinnest >= skin - voxel,
        }
        for check, ok in checks.items():
            if not ok:
                failures.append(f"{name}: {check} failed (admesh {a}, manifold {info.get('manifold')}, box "
                                f"{side:.3g} mm, volume {volume_error:+.2f}%, skin {thinnest:.3g} mm)")
        rows.append(f"| {what} | {skin} | {cell} | {voxel} | {triangles} | {a['added']:.0f} / {a['disconnected']:.0f}"
                    f" / {a['backwards']:.0f} / {a['parts']:.0f} | {info.get('manifold')} | {side:.3f} | "
                    f"{lattice:.4f} | {volume_error:+.2f}% | {thinnest:.3f} | {seconds:.1f} |")
    gcode = os.path.join(out_dir, "parts.gcode")
    if parts:
        r = run(["prusa-slicer", "--loglevel", "2", "--export-gcode", *parts, "-o", gcode])
        # Complaints about the mesh (its own log lines about toolpaths, such as Arachne's "Reversing
        # even wall line", are the slicer's business and vary from run to run).
        log = (r.stdout + r.stderr).splitlines()
        complaints = [line for line in log
                      if re.search(r"manifold|repair|open edge|facet|degenerate|self-intersect|hole|mesh|broken",
                                   line, re.I) and re.search(r"\[(error|warning)\]|error|warning", line, re.I)]
        for line in log:
            if re.search(r"\[(error|warning)\]", line) and line not in complaints:
                print(f"prusa-slicer said (not about the mesh): {line}", file=sys.stderr)
        if r.returncode != 0 or not os.path.exists(gcode) or complaints:
            failures.append(f"prusa-slicer --export-gcode: exit {r.returncode}: {complaints}")
    print(f"Gyroid, --density {DENSITY}; one `prusa-slicer --export-gcode` run sliced all {len(parts)} parts"
          f"{' without an error or warning about the mesh' if parts and not any('prusa' in f for f in failures) else ''}.\n")
    print("| body | skin mm | cell mm | voxel mm | triangles | admesh holes / disconnected / backwards / parts |"
          " manifold | box vs body, mm | lattice density in the core | volume vs V_skin + rho V_core |"
          " thinnest skin mm | time s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))
    for f in failures:
        print("FAIL:", f, file=sys.stderr)
    failed = {f.split(":")[0] for f in failures}
    print(f"{len(BODIES) - len(failed & {b[0] for b in BODIES})} passed, {len(failed)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
