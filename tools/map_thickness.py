#!/usr/bin/python3
"""Measures the wall thickness of a mapped lattice in physical space, ours against the usual way.

Ours: `offsetgen generate --map ...` offsets G = F o M^-1 itself, so its walls should lie h from the
mid-surface G = 0 along the physical normal. The usual way (what CAD lattice tools do): offset F in
cell space by h / A (A the nominal cell size) and evaluate that shell at M^-1(x): its walls follow
the map's local stretch. For points on G = 0 (Newton from a fixed random sample of the domain), each
wall is found along the physical normal by bisection; the thickness is the distance between them.

usage: map_thickness.py OFFSETGEN N A C X0,Y0,Z0:X1,Y1,Z1 T   (cylindrical:N,A,C gyroid, total wall T mm)
"""
import importlib.util
import os
import subprocess
import sys
import tempfile

import numpy as np


def load(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def generate(offsetgen, out, extra):
    subprocess.run([offsetgen, "generate", "--surface", "gyroid", "--lang", "numpy", "-q", "-o", out] + extra,
                   check=True)


def root_along(f, p, n, guess, span):
    """The root of s -> f(p + s n) nearest `guess`, within guess +- span (None if none)."""
    s = np.linspace(guess - span, guess + span, 121)
    v = np.array([f(*(p + si * n)) for si in s])
    best = None
    for i in range(len(s) - 1):
        if v[i] == 0 or v[i] * v[i + 1] < 0:
            a, b, fa = s[i], s[i + 1], v[i]
            for _ in range(60):
                m = 0.5 * (a + b)
                fm = f(*(p + m * n))
                if fa * fm <= 0:
                    b = m
                else:
                    a, fa = m, fm
            r = 0.5 * (a + b)
            if best is None or abs(r - guess) < abs(best - guess):
                best = r
    return best


def main():
    offsetgen, N, A, C, domain, T = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), \
        sys.argv[5], float(sys.argv[6])
    lo, hi = [np.array([float(v) for v in c.split(",")]) for c in domain.split(":")]
    h = T / 2
    with tempfile.TemporaryDirectory() as tmp:
        ours_path, cell_path = os.path.join(tmp, "ours.py"), os.path.join(tmp, "cell.py")
        generate(offsetgen, ours_path, ["--map", f"cylindrical:{N},{A},{C}", "--domain", domain])
        generate(offsetgen, cell_path, [])
        ours, cell = load(ours_path, "ours"), load(cell_path, "cell")
    field = ours.gyroid_cylindrical_o4_field
    ours_offset = ours.gyroid_cylindrical_o4_offset

    def to_cells(x, y, z):
        return np.sqrt(x * x + y * y) / A, N * np.arctan2(y, x) / (2 * np.pi), z / C

    def usual_offset(x, y, z, hh):
        u, v, w = to_cells(x, y, z)
        return cell.gyroid_o4_offset(u, v, w, hh / A)

    def gradient(p, e=1e-6):
        return np.array([(field(*(p + e * d)) - field(*(p - e * d))) / (2 * e) for d in np.eye(3)])

    rng = np.random.default_rng(7)
    ours_t, usual_t, ours_err = [], [], []
    while len(ours_t) < 300:
        p = lo + (hi - lo) * rng.random(3)
        for _ in range(30):  # Newton onto G = 0 along the gradient
            g = gradient(p)
            p = p - field(*p) * g / g.dot(g)
        if abs(field(*p)) > 1e-12 or np.any(p < lo + 2 * T) or np.any(p > hi - 2 * T):
            continue
        n = gradient(p)
        n /= np.linalg.norm(n)
        walls = {}
        for name, f in (("ours", ours_offset), ("usual", usual_offset)):
            plus = root_along(lambda *q: f(*q, h), p, n, h, 1.5 * h)
            minus = root_along(lambda *q: f(*q, -h), p, n, -h, 1.5 * h)
            walls[name] = (plus, minus)
        if any(w is None for pair in walls.values() for w in pair):
            continue
        ours_t.append(walls["ours"][0] - walls["ours"][1])
        usual_t.append(walls["usual"][0] - walls["usual"][1])
        ours_err.append(max(abs(abs(walls["ours"][0]) - h), abs(abs(walls["ours"][1]) - h)))
    ours_t, usual_t = np.abs(ours_t), np.abs(usual_t)
    print(f"cylindrical:{N},{A},{C} gyroid, domain {domain}, requested wall {T} mm, {len(ours_t)} points on G = 0")
    print(f"  ours (offset of G = F o M^-1): thickness {ours_t.min():.5f} to {ours_t.max():.5f} mm, "
          f"median {np.median(ours_t):.5f}; each wall within {max(ours_err):.2e} mm of h")
    print(f"  usual (cell-space shell of t/A mapped): thickness {usual_t.min():.4f} to {usual_t.max():.4f} mm, "
          f"median {np.median(usual_t):.4f} ({100 * (usual_t.min() / T - 1):+.1f}% to {100 * (usual_t.max() / T - 1):+.1f}%)")


if __name__ == "__main__":
    main()
