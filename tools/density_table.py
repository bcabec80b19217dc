#!/usr/bin/env python3
"""Prints the table of surface constants (docs/density.md) for every catalog surface.

usage: tools/density_table.py [path/to/offsetgen]     (default: build/offsetgen)

Runs `offsetgen density --surface S --density R --json` once per surface (R: a density every surface
allows) and formats A, chi (with the Gauss-Bonnet residual), V_0, integral(H dA), the largest
principal curvature, t_max, rho_max and the network's density range as a Markdown table.
"""
import json
import subprocess
import sys

SURFACES = ["gyroid", "schwarzp", "diamond", "neovius", "iwp", "fischerkoch", "lidinoid", "splitp", "frd"]


def constants(offsetgen, surface):
    out = subprocess.run([offsetgen, "density", "--surface", surface, "--density", "0.05", "--json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def main():
    offsetgen = sys.argv[1] if len(sys.argv) > 1 else "build/offsetgen"
    print("| surface | A | chi (residual) | V_0 | integral H dA | k_max | t_max | rho_max (sheet) | network rho |")
    print("|---|---|---|---|---|---|---|---|---|")
    for s in SURFACES:
        k = constants(offsetgen, s)
        mean = k["mean_integral"] if abs(k["mean_integral"]) >= 5e-7 else 0.0
        lo, hi = k["network_density_range"]
        print(f"| {s} | {k['area']:.6f} | {k['chi']} ({k['chi_residual']:.0e}) | {k['volume_inside']:.6f} | "
              f"{mean:.6f} | {k['max_curvature']:.4f} | {k['thickness_limit']:.4f} | {k['density_limit']:.4f} | "
              f"{lo:.4f} - {hi:.4f} |")


if __name__ == "__main__":
    main()
