#!/usr/bin/env python3
"""Areas of the exact Schwarz P, Schwarz D and Schoen G minimal surfaces per cubic cell of edge 1
(docs/density.md), from their Enneper-Weierstrass representation. Needs mpmath (Debian: python3-mpmath,
which python3-sympy pulls in). A few seconds.

usage: tools/weierstrass_areas.py

The three are Bonnet associates: one Weierstrass function R(tau) = (tau^8 - 14 tau^4 + 1)^(-1/2),
Gauss map tau, the point x = Re(e^(i theta) integral of ((1 - tau^2), i (1 + tau^2), 2 tau) R dtau)
with theta = 0 for D, 90 degrees for P and the gyroid's angle for G. The Bonnet transformation is an
isometry, so all three have the same area per sheet of the Gauss map, S; only their lattices differ.
The frame: the flat points (the 8 roots, |tau| = sqrt(2 -+ sqrt 3)) have the normals <111>, so z is a
cube axis and x and y are face diagonals.

- Each primitive cell has genus 3 (chi = -4): the Gauss map covers the sphere twice, area 2 S. A cube
  holds n primitive cells: 1 for P (simple cubic), 2 for G (body-centred), 4 for D (face-centred, the
  Fd-3m cube), so A = 2 n S / a^2.
- The loop around the branch points t1 = sqrt(2 - sqrt 3) and t2 = 1 / t1 has the period
  2 (i a, -b, i c) before the rotation by theta (a = 0 by tau -> 1 / tau), so the lattice vector is
  (0, -2 b cos theta, -2 c sin theta): for P (0, 0, -2c), the cube edge; for D (0, -2b, 0), a face
  diagonal a / sqrt 2; for G it is a body diagonal (a / 2)(1, 1, 1) of the cube frame when its two
  parts are equal, 2 b cos theta / sqrt 2 = 2 c sin theta, which fixes theta (38.0148 degrees).
"""
import mpmath as mp

mp.mp.dps = 15


def main():
    t1 = mp.sqrt(2 - mp.sqrt(3))
    t2 = 1 / t1

    def root(t):  # |tau^8 - 14 tau^4 + 1|^(1/2), the polynomial being negative between t1 and t2
        return mp.sqrt(-(t**8 - 14 * t**4 + 1))

    b = mp.quad(lambda t: (1 + t**2) / root(t), [t1, 1, t2])
    c = mp.quad(lambda t: 2 * t / root(t), [t1, 1, t2])

    # S: the area element |R|^2 (1 + |tau|^2)^2 du dv over the plane. tau -> i tau, conjugation and
    # tau -> 1 / tau leave it unchanged: 16 sectors 0 < arg tau < pi / 4 of the unit disk, split at the
    # branch point t1 (an integrable 1/distance singularity, at a corner of the subdivision).
    def element(r, phi):
        tau = r * mp.expj(phi)
        return r * (1 + r * r) ** 2 / abs(tau**8 - 14 * tau**4 + 1)

    S = 16 * mp.quad(element, [0, t1, 1], [0, mp.pi / 8, mp.pi / 4])

    theta = mp.atan(b / (mp.sqrt(2) * c))
    rows = [
        ("Schwarz P", 90, 1, 2 * c),
        ("Schwarz D", 0, 4, 2 * mp.sqrt(2) * b),
        ("Schoen G", mp.degrees(theta), 2, 2 * mp.sqrt(2) * b * mp.cos(theta)),
    ]
    print("| surface | Bonnet angle | primitive cells per cube | A per cube of edge 1 |")
    print("|---|---|---|---|")
    for name, angle, cells, edge in rows:
        print(f"| {name} | {float(angle):.4f} | {cells} | {float(2 * cells * S / edge**2):.6f} |")


if __name__ == "__main__":
    main()
