"""What a printer's user runs on a part, shared by tools/check_parts.py and tools/sweep_parts.py:
admesh's repairs, PrusaSlicer's --info, bodies rendered from OpenSCAD examples, and the figures of
`offsetgen mesh`'s summary. Standard library only (CI's python3 may lack numpy)."""
import os
import re
import subprocess
import sys
import time

SHAPES = "/usr/share/PrusaSlicer/shapes"
EXAMPLES = "/usr/share/openscad/examples"


def run(cmd, **kw):
    start = time.monotonic()
    result = subprocess.run(cmd, capture_output=True, text=True, **kw)
    print(f"[{time.monotonic() - start:6.1f} s] {' '.join(str(c) for c in cmd[:3])} ...", file=sys.stderr)
    return result


def prusa_info(stl):
    """`prusa-slicer --info`: its key = value lines (manifold, number_of_parts, volume, min_x ...)."""
    out = run(["prusa-slicer", "--info", stl]).stdout
    return dict(re.findall(r"^(\w+) = (.*)$", out, re.M))


def admesh(stl):
    """admesh's default check-and-repair run: what it had to change, and the parts it counts."""
    out = run(["admesh", stl]).stdout

    def first(label):
        m = re.search(label + r"\s*:\s*(-?[0-9.]+)", out)
        return float(m.group(1)) if m else float("nan")

    return {"added": first("Facets added"), "degenerate": first("Degenerate facets"),
            "backwards": first("Backwards edges"), "fixed": first("Edges fixed"),
            "disconnected": first("Total disconnected facets"), "parts": first("Number of parts")}


def admesh_clean(a):
    return all(a[k] == 0 for k in ("added", "degenerate", "backwards", "fixed", "disconnected"))


def body_stl(name, source, out_dir):
    """An STL of the body: the file itself, or an OpenSCAD example rendered once into out_dir."""
    if source.endswith(".stl"):
        return source
    stl = os.path.join(out_dir, name + "_body.stl")
    if not os.path.exists(stl):
        r = run(["openscad", "-o", stl, source])
        if r.returncode != 0:
            raise RuntimeError(f"openscad {source}: {r.stderr}")
    return stl


def box(info):
    return [(float(info[f"min_{a}"]), float(info[f"max_{a}"])) for a in "xyz"]


def summary_figures(summary):
    """The figures of a `mesh --body` summary that the checks read."""
    def number(pattern, default=None):
        m = re.search(pattern, summary)
        return float(m.group(1)) if m else default

    return {
        "volume_error": number(r"rho V_core = [0-9.e+]+ mm\^3 \(([-+0-9.]+)%\)"),
        "thinnest": number(r"measured: thinnest ([0-9.e+-]+) mm"),
        "lattice": number(r"lattice ([0-9.]+) of the core measured"),
        "sampled": number(r"of the core measured, ([0-9.]+) sampled on its voxels"),
        "requested": number(r"sampled on its voxels \([^0-9]*([0-9.]+)\)"),
        "core": number(r"core ([0-9.e+]+) mm\^3"),
        "voxel": number(r"voxel ([0-9.e+-]+) mm"),
        "triangles": int(number(r"mesh:\s+(\d+) triangles", 0)),
        "seconds": number(r"time:\s+([0-9.]+) s"),
        "dropped_volume": number(r"dropped below the volume threshold \(([0-9.e+-]+) mm\^3\)", 0) +
        number(r"small pieces inside single tiles dropped \(([0-9.e+-]+) mm\^3\)", 0),
    }
