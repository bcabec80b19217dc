#!/usr/bin/python3
"""Log-log convergence figure (offset error vs h/L), in the style of Figure 3 of
Geier & Alihussein 2021: one marked line per Richardson order, and a small
slope triangle per series showing the ideal slope (= the order), so a reader
can see at a glance whether order m really converges like h^m.

Usage:
    /usr/bin/python3 tools/plot_convergence.py convergence.json convergence.png

Input (JSON):
    {"title": "...", "xlabel": "h/L", "ylabel": "mean relative error",
     "series": [{"label": "order 1", "order": 1, "x": [...], "y": [...]}, ...],
     "slope_triangles": true,
     "hline": [{"y": 1e-6, "label": "1e-6"}]}
Points with y missing/null/<= 0 (machine-precision floor) or x <= 0 are skipped.
Exit codes: 0 ok, 2 bad usage or bad input.
"""

import argparse
import json
import math
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")  # headless: no display on build/CI machines
import matplotlib.pyplot as plt  # noqa: E402  (must follow matplotlib.use)

EXIT_INPUT = 2
TRIANGLE_DROP = 3.0      # triangle sits this factor below the line's first point
TRIANGLE_SPAN_DECADES = 0.5


class InputError(Exception):
    """Malformed input JSON; reported with exit status 2."""


def is_number(v):
    """JSON number (bool excluded) that is finite."""
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def optional_str(spec, key, default):
    """String field with a default; anything else is an input error."""
    v = spec.get(key, default)
    if not isinstance(v, str):
        raise InputError("%r must be a string" % key)
    return v


def valid_points(xs, ys):
    """(x, y) pairs that can go on log-log axes; the rest (floor, gaps) are dropped."""
    return [(x, y) for x, y in zip(xs, ys)
            if is_number(x) and is_number(y) and x > 0 and y > 0]


def parse_series(i, s):
    """Validate one series and return (label, order or None, points)."""
    if not isinstance(s, dict):
        raise InputError("series[%d] must be an object" % i)
    xs, ys = s.get("x"), s.get("y")
    if not isinstance(xs, list) or not isinstance(ys, list):
        raise InputError("series[%d] needs lists 'x' and 'y'" % i)
    if len(xs) != len(ys):
        raise InputError("series[%d]: 'x' has %d values but 'y' has %d"
                         % (i, len(xs), len(ys)))
    order = s.get("order")
    if order is not None and not (is_number(order) and order > 0):
        raise InputError("series[%d]: 'order' must be a positive number" % i)
    label = optional_str(s, "label", "order %g" % order if order else "series %d" % (i + 1))
    return label, order, valid_points(xs, ys)


def parse_hlines(spec):
    """Optional horizontal reference lines, e.g. the paper's 1e-6 target."""
    hl = spec.get("hline", [])
    if not isinstance(hl, list):
        raise InputError("'hline' must be a list of {\"y\": ..., \"label\": ...}")
    out = []
    for i, h in enumerate(hl):
        if not isinstance(h, dict) or not is_number(h.get("y")) or h["y"] <= 0:
            raise InputError("hline[%d] needs a positive number 'y'" % i)
        out.append((h["y"], optional_str(h, "label", "")))
    return out


def load_spec(path):
    """Read and validate the whole input file."""
    try:
        with open(path, encoding="utf-8") as f:
            spec = json.load(f)
    except OSError as exc:
        raise InputError("cannot read %s: %s" % (path, exc.strerror))
    except json.JSONDecodeError as exc:
        raise InputError("%s is not valid JSON: %s" % (path, exc))
    if not isinstance(spec, dict):
        raise InputError("top level must be a JSON object")
    series = spec.get("series")
    if not isinstance(series, list) or not series:
        raise InputError("'series' must be a non-empty list")
    parsed = [parse_series(i, s) for i, s in enumerate(series)]
    if not any(pts for _, _, pts in parsed):
        raise InputError("no series has a plottable point (need x > 0 and y > 0)")
    tri = spec.get("slope_triangles", False)
    if not isinstance(tri, bool):
        raise InputError("'slope_triangles' must be true or false")
    return {"title": optional_str(spec, "title", ""),
            "xlabel": optional_str(spec, "xlabel", "h/L"),
            "ylabel": optional_str(spec, "ylabel", "error"),
            "series": parsed, "slope_triangles": tri, "hlines": parse_hlines(spec)}


def slope_triangle(ax, points, order, color):
    """Right-angled triangle of slope `order` just below the line's small-x end."""
    x0, y0 = min(points)
    x_max = max(p[0] for p in points)
    span = min(10 ** TRIANGLE_SPAN_DECADES, max(x_max / x0, 10 ** 0.2))
    x1 = x0 * span
    ya = y0 / TRIANGLE_DROP
    yb = ya * span ** order
    ax.plot([x0, x1, x1, x0], [ya, ya, yb, ya], color=color, linewidth=0.9)
    ax.annotate("%g" % order, xy=(x1, math.sqrt(ya * yb)), xytext=(4, 0),
                textcoords="offset points", va="center", ha="left",
                color=color, fontsize=9)


def render(spec):
    """Build the figure; returns it so the caller decides where it goes."""
    fig, ax = plt.subplots(figsize=(6.4, 4.8), dpi=150)
    markers = "osD^vp*hX<>"
    for i, (label, order, pts) in enumerate(spec["series"]):
        if not pts:
            print("plot_convergence: warning: series %r has no plottable points, skipped"
                  % label, file=sys.stderr)
            continue
        pts = sorted(pts)
        line, = ax.plot([p[0] for p in pts], [p[1] for p in pts],
                        marker=markers[i % len(markers)], markersize=4, label=label)
        if spec["slope_triangles"] and order:
            slope_triangle(ax, pts, order, line.get_color())
    for y, label in spec["hlines"]:
        ax.axhline(y, color="0.3", linestyle="--", linewidth=0.8, label=label or None)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_title(spec["title"])
    ax.set_xlabel(spec["xlabel"])
    ax.set_ylabel(spec["ylabel"])
    ax.grid(True, which="major", alpha=0.5)
    ax.grid(True, which="minor", alpha=0.15)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    return fig


def save_atomic(fig, path):
    """Write to a temp file in the target directory, then rename over the target."""
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=directory, prefix=".tmp_", suffix=".png")
    os.close(fd)
    try:
        fig.savefig(tmp, format="png")
        # mkstemp creates 0600; a picture gets the mode of any new file (0666 less the umask),
        # or keeps the mode of the file it replaces.
        if os.path.isfile(path):
            os.chmod(tmp, os.stat(path).st_mode & 0o7777)
        else:
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def parse_args(argv):
    p = argparse.ArgumentParser(
        description="Render a log-log convergence plot (error vs h/L) with slope triangles.")
    p.add_argument("input", help="input JSON (see module docstring for the schema)")
    p.add_argument("output", help="output PNG path")
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    try:
        spec = load_spec(args.input)
    except InputError as exc:
        print("plot_convergence: %s" % exc, file=sys.stderr)
        return EXIT_INPUT
    if not os.path.isdir(os.path.dirname(os.path.abspath(args.output))):
        print("plot_convergence: output directory of %s does not exist" % args.output,
              file=sys.stderr)
        return EXIT_INPUT
    fig = render(spec)
    save_atomic(fig, args.output)
    plt.close(fig)
    print("plot_convergence: wrote %s" % args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
