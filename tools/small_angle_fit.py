#!/usr/bin/env python3
"""Coefficients of the small-angle sin/cos polynomials of src/lowering/lower.cpp.

sin(d) = d * S(d^2) and cos(d) = C(d^2) for |d| <= 1, with S and C of degree 7 in z = d^2 and
constant term 1. The rest (S(z) - 1)/z and (C(z) - 1)/z is interpolated at Chebyshev nodes on
[0, 1] in 50-digit arithmetic (near-minimax), and the error of the double coefficients is measured
on 4001 points. Prints C++ initialisers. Needs python3-mpmath (Debian).
"""
import mpmath as mp

mp.mp.dps = 50


def chebyshev_fit(f, degree):
    nodes = [mp.mpf(1) / 2 + mp.cos(mp.pi * (2 * k + 1) / (2 * (degree + 1))) / 2 for k in range(degree + 1)]
    vandermonde = mp.matrix([[z ** j for j in range(degree + 1)] for z in nodes])
    c = mp.lu_solve(vandermonde, mp.matrix([f(z) for z in nodes]))
    return [c[j] for j in range(degree + 1)]


def sin_rest(z):
    return mp.mpf(-1) / 6 if z == 0 else (mp.sin(mp.sqrt(z)) / mp.sqrt(z) - 1) / z


def cos_rest(z):
    return mp.mpf(-1) / 2 if z == 0 else (mp.cos(mp.sqrt(z)) - 1) / z


for name, rest, exact in (("sin", sin_rest, mp.sin), ("cos", cos_rest, mp.cos)):
    coefficients = [1.0] + [float(c) for c in chebyshev_fit(rest, 6)]
    worst = 0
    for k in range(4001):
        d = mp.mpf(k) / 4000
        p = sum(mp.mpf(c) * (d * d) ** j for j, c in enumerate(coefficients))
        worst = max(worst, abs((p * d if name == "sin" else p) - exact(d)))
    print(f"// {name}: max |error| {mp.nstr(worst, 3)} for |d| <= 1")
    print("{" + ", ".join(repr(c) for c in coefficients) + "}")
