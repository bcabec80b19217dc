#!/usr/bin/env python3
"""Enclosed voids and drain holes (issue 43), judged apart from the mesher: `offsetgen mesh --body`
reports the enclosed void regions on its level set; stl_voids (tests/support/stl_voids.cpp) voxelises
the written STL (0.08 mm), flood-fills the outside and labels what is left. Without --drain their
trapped volumes must agree within 5% + 5 mm^3 and their counts of regions of 1 mm^3 or more must
agree; with --drain 2 (--drain 1.5 in --quick) no region of 1 mm^3 or more is left, and admesh and PrusaSlicer find the part
clean and manifold.

  tools/check_voids.py BUILD_DIR OUT_DIR [--quick]

--quick (ctest mesh_voids_found_and_drained, label mesh): a 15.5 mm sphere, one gyroid sheet; prints
nothing but failures. Without it: PrusaSlicer's sphere and bunny (scaled 0.5) with gyroid and diamond
sheets and a diamond network at the README's settings, before and after --drain 2, as a table.
Standard library only."""
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import part_checks  # noqa: E402
from part_checks import SHAPES, admesh, admesh_clean, prusa_info  # noqa: E402

SHEET = ["--density", "0.25", "--skin", "1.5", "--cell-size", "6"]
NETWORK = ["--network", "--density", "0.3", "--skin", "1.2", "--cell-size", "6"]
FULL = [("sphere", [], "gyroid", SHEET), ("sphere", [], "diamond", SHEET), ("sphere", [], "diamond", NETWORK),
        ("bunny", ["--scale", "0.5"], "gyroid", SHEET), ("bunny", ["--scale", "0.5"], "diamond", SHEET),
        ("bunny", ["--scale", "0.5"], "diamond", NETWORK)]
QUICK = [("sphere", ["--scale", "0.5"], "gyroid", ["--density", "0.25", "--skin", "1", "--cell-size", "4",
                                                    "--voxel", "0.12"])]
QUICK_DRAIN = ["--drain", "1.5", "--fill-pockets", "0.5", "-j", "2"]

VOIDS = re.compile(r"^  voids: (\d+) enclosed regions, ([0-9.]+) mm\^3 trapped \(largest ([0-9.]+) mm\^3\)\n"
                   r"\s+(\d+) of 1 mm\^3 or more", re.M)
CHECKED = re.compile(r"^stl_voids: (\d+) enclosed regions, ([0-9.]+) mm\^3 trapped \(largest ([0-9.]+) mm\^3\); "
                     r"(\d+) of 1 mm\^3 or more", re.M)


def mesh(build, out, body, extra, surface, walls, drain):
    cmd = [os.path.join(build, "offsetgen"), "mesh", "--surface", surface, "--body",
           os.path.join(SHAPES, body + ".stl")] + extra + walls + drain + ["-o", out]
    start = time.monotonic()
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {r.returncode}: {r.stderr}")
    m = VOIDS.search(r.stdout)
    if not m:
        raise RuntimeError(f"{' '.join(cmd)}: no voids line in\n{r.stdout}")
    seconds = float(re.search(r"time:\s+([0-9.]+) s", r.stdout).group(1))
    voids_stage = re.search(r"voids ([0-9.]+) s", r.stdout)
    return {"regions": int(m.group(1)), "trapped": float(m.group(2)), "largest": float(m.group(3)),
            "large": int(m.group(4)), "summary": r.stdout, "seconds": seconds, "wall": time.monotonic() - start,
            "voids_seconds": float(voids_stage.group(1)) if voids_stage else 0.0}


def flood(checker, stl):
    r = subprocess.run([checker, stl, "0.08"], capture_output=True, text=True)
    m = CHECKED.search(r.stdout)
    if r.returncode != 0 or not m:
        raise RuntimeError(f"stl_voids {stl}: exit {r.returncode}: {r.stdout}{r.stderr}")
    return {"regions": int(m.group(1)), "trapped": float(m.group(2)), "largest": float(m.group(3)),
            "large": int(m.group(4))}


def refused(build, out_dir, failures):
    """Bad requests exit 2 with a reason and write nothing."""
    sphere = ["--body", os.path.join(SHAPES, "sphere.stl"), "--scale", "0.5"] + QUICK[0][3]
    cases = {
        "a diameter under two voxels": ["--drain", "0.2"] + sphere,
        "a diameter of half the body or more": ["--drain", "9"] + sphere,
        "a --drain-at point outside the body": ["--drain", "1.5", "--drain-at", "0,0,0"] + sphere,
        "--drain without --body": ["--drain", "2", "--cells", "2", "--cell-size", "4", "--density", "0.25"],
        "--drain-at without --drain": ["--drain-at", "8,8,8"] + sphere,
        "a bad --up": ["--drain", "1.5", "--up", "W"] + sphere,
    }
    for what, options in cases.items():
        out = os.path.join(out_dir, "refused.stl")
        if os.path.exists(out):
            os.remove(out)
        r = subprocess.run([os.path.join(build, "offsetgen"), "mesh", "--surface", "gyroid"] + options + ["-o", out],
                           capture_output=True, text=True)
        if r.returncode != 2 or os.path.exists(out) or "error" not in r.stderr:
            failures.append(f"{what}: exit {r.returncode}, file written: {os.path.exists(out)}, stderr {r.stderr!r}")


def deterministic(build, out_dir, drained, failures):
    """The same holes and bytes on one thread as on two (`drained`: the two threads' run)."""
    body, extra, surface, walls = QUICK[0]
    out = os.path.join(out_dir, "one_thread.stl")
    one = mesh(build, out, body, extra, surface, walls, QUICK_DRAIN[:-1] + ["1"])

    def holes(summary):
        return [line for line in summary.splitlines() if " at (" in line or "pockets:" in line]

    with open(out, "rb") as f, open(drained[0], "rb") as g:
        same_bytes = f.read() == g.read()
    if not holes(one["summary"]) or holes(one["summary"]) != holes(drained[1]["summary"]) or not same_bytes:
        failures.append(f"{' '.join(QUICK_DRAIN)}: holes or bytes differ between one thread and two")


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    quick = "--quick" in sys.argv
    if quick:  # a test prints only its failures
        part_checks.run = lambda cmd, **kw: subprocess.run(cmd, capture_output=True, text=True, **kw)
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    build, out_dir = args
    checker = os.path.join(build, "tests", "mesh", "stl_voids")
    os.makedirs(out_dir, exist_ok=True)
    failures, rows = [], []
    for body, extra, surface, walls in QUICK if quick else FULL:
        label = f"{body} {surface} {'network' if '--network' in walls else 'sheet'}"
        stem = os.path.join(out_dir, label.replace(" ", "_"))
        before = mesh(build, stem + ".stl", body, extra, surface, walls, [])
        judged = flood(checker, stem + ".stl")
        if abs(before["trapped"] - judged["trapped"]) > 0.05 * judged["trapped"] + 5:
            failures.append(f"{label}: {before['trapped']} mm^3 trapped reported, {judged['trapped']} by flood fill")
        if before["large"] != judged["large"]:
            failures.append(f"{label}: {before['large']} regions of 1 mm^3 or more reported, "
                            f"{judged['large']} by flood fill")
        after = mesh(build, stem + "_drained.stl", body, extra, surface, walls,
                     QUICK_DRAIN if quick else ["--drain", "2"])
        drained = flood(checker, stem + "_drained.stl")
        a = admesh(stem + "_drained.stl")
        manifold = prusa_info(stem + "_drained.stl").get("manifold")
        holes = after["summary"].count(" at (")
        if after["large"] != 0 or drained["large"] != 0:
            failures.append(f"{label} drained: {after['large']} regions of 1 mm^3 or more reported, "
                            f"{drained['large']} by flood fill")
        if not admesh_clean(a) or manifold != "yes":
            failures.append(f"{label} drained: admesh {a}, manifold {manifold}")
        rows.append((label, before, judged, after, drained, holes, a, manifold))
    if quick:
        refused(build, out_dir, failures)
        deterministic(build, out_dir, (stem + "_drained.stl", after), failures)
    else:
        print("| part | reported: regions / >= 1 mm^3 / trapped mm^3 (largest) | flood fill 0.08 mm: same | "
              "--drain 2: holes | after, reported: regions / >= 1 mm^3 / trapped | after, flood fill: same | "
              "admesh clean | manifold | time s (voids s) |")
        print("|---|---|---|---|---|---|---|---|---|")
        for label, b, j, a, d, holes, adm, manifold in rows:
            print(f"| {label} | {b['regions']} / {b['large']} / {b['trapped']:.1f} ({b['largest']:.1f}) | "
                  f"{j['regions']} / {j['large']} / {j['trapped']:.1f} ({j['largest']:.1f}) | {holes} | "
                  f"{a['regions']} / {a['large']} / {a['trapped']:.1f} | {d['regions']} / {d['large']} / "
                  f"{d['trapped']:.1f} | {'yes' if admesh_clean(adm) else adm} | {manifold} | "
                  f"{b['seconds']:.1f} ({b['voids_seconds']:.2f}) |")
    for f in failures:
        print("FAILED:", f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
