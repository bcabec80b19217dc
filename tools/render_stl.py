#!/usr/bin/env python3
"""Renders a binary STL to a PNG, headless, with matplotlib (Debian's python3-matplotlib).

Orthographic view along (--azimuth, --elevation), Lambert shading of the facet normals with a fixed
key and fill light, painter's order (far facets first). Deterministic for the same inputs.

usage: tools/render_stl.py part.stl part.png [--size 900] [--azimuth 35] [--elevation 28] [--title TEXT]
                          [--cut-above Z]

--cut-above Z drops the facets whose centre lies above the plane z = Z (the file's coordinates), so a
part is seen cut open; the inner sides of the surfaces then show through the cut, drawn in grey.
"""
import argparse
import sys

import numpy as np


def fail(message):
    print(f"render_stl: {message}", file=sys.stderr)
    sys.exit(2)


def read_binary_stl(path):
    try:
        data = open(path, "rb").read()
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    if len(data) < 84:
        fail(f"{path}: too short for a binary STL")
    count = int(np.frombuffer(data, dtype="<u4", count=1, offset=80)[0])
    if len(data) != 84 + 50 * count:
        fail(f"{path}: {len(data)} bytes do not hold {count} binary STL facets")
    record = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    return np.frombuffer(data, dtype=record, count=count, offset=84)["v"].astype(np.float64)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("stl")
    parser.add_argument("png")
    parser.add_argument("--size", type=int, default=900, help="image width and height in pixels")
    parser.add_argument("--azimuth", type=float, default=35.0, help="degrees about z")
    parser.add_argument("--elevation", type=float, default=28.0, help="degrees above the xy plane")
    parser.add_argument("--title", default="")
    parser.add_argument("--cut-above", type=float, default=None, help="drop facets above the plane z = Z")
    args = parser.parse_args()

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    tri = read_binary_stl(args.stl)
    if len(tri) == 0:
        fail(f"{args.stl}: no facets")
    if args.cut_above is not None:
        tri = tri[tri[:, :, 2].mean(axis=1) <= args.cut_above]
        if len(tri) == 0:
            fail(f"no facet lies below z = {args.cut_above}")
    tri -= tri.reshape(-1, 3).mean(axis=0)
    az, el = np.radians(args.azimuth), np.radians(args.elevation)
    # Camera frame: `forward` points from the viewer into the scene.
    forward = -np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])
    right = np.cross(forward, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)

    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    length = np.linalg.norm(normal, axis=1)
    keep = length > 0
    tri, normal = tri[keep], normal[keep] / length[keep, None]
    facing = normal @ -forward
    if args.cut_above is None:
        tri, normal = tri[facing > 0], normal[facing > 0]  # back faces of a closed solid are hidden
        inner = np.zeros(len(tri), dtype=bool)
    else:
        inner = facing <= 0  # seen through the cut: the inside of the material
        normal[inner] = -normal[inner]

    key = np.array([0.4, -0.3, 0.85]) - 0.8 * forward
    key /= np.linalg.norm(key)
    fill = -forward
    shade = 0.18 + 0.62 * np.clip(normal @ key, 0, 1) + 0.25 * np.clip(normal @ fill, 0, 1)
    base = np.array([0.80, 0.55, 0.25])  # a warm resin colour
    colours = np.clip(base[None, :] * shade[:, None], 0, 1)
    colours[inner] = np.clip(np.array([0.45, 0.45, 0.47])[None, :] * shade[inner, None], 0, 1)

    depth = (tri @ forward).mean(axis=1)
    order = np.argsort(-depth, kind="stable")
    xy = np.stack([tri @ right, tri @ up], axis=-1)[order]

    fig = plt.figure(figsize=(args.size / 100, args.size / 100), dpi=100)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.add_collection(PolyCollection(xy, facecolors=colours[order], edgecolors="none", antialiased=False))
    lo, hi = xy.reshape(-1, 2).min(axis=0), xy.reshape(-1, 2).max(axis=0)
    pad = 0.04 * (hi - lo).max()
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal")
    ax.axis("off")
    if args.title:
        ax.text(0.02, 0.02, args.title, transform=ax.transAxes, fontsize=11, color="0.25")
    fig.savefig(args.png, dpi=100, facecolor="white", metadata={"Software": None})
    print(f"render_stl: {args.png} ({len(xy)} visible facets of {int(keep.sum())})")


if __name__ == "__main__":
    main()
