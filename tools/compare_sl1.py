#!/usr/bin/env python3
"""Compares two SL1/SL1S archives layer by layer, as a printer would expose them: each layer's PNG
binarised at 128, the pixels that differ counted inside the box both parts cover (the union of their
lit pixels, grown by one pixel). Prints one line per layer below --report (and a summary line:
layers, the lowest and median agreement). Needs nothing but Python's standard library.

  tools/compare_sl1.py ours.sl1 theirs.sl1 [--report 99.5]
"""
import argparse
import re
import statistics
import struct
import sys
import zipfile
import zlib


def read_png(data):
    """An 8-bit greyscale PNG (as SL1 archives hold) as a list of rows of bytes."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour != 0:
                raise ValueError(f"PNG of depth {depth}, colour type {colour}: only 8-bit grey is read")
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width + 1
    if all(raw[r * stride] == 0 for r in range(height)):  # no filter on any row: the rows as they are
        return [raw[r * stride + 1:(r + 1) * stride] for r in range(height)]
    rows, prev = [], bytearray(width)
    for r in range(height):
        f, line = raw[r * stride], bytearray(raw[r * stride + 1:(r + 1) * stride])
        for i in range(width):
            a = line[i - 1] if i else 0
            b, c = prev[i], prev[i - 1] if i else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return rows


def layers(path):
    z = zipfile.ZipFile(path)
    return [z.read(n) for n in sorted(n for n in z.namelist() if n.endswith(".png") and "/" not in n and
                                       not n.startswith("thumbnail"))]


LIT = re.compile(rb"[\x80-\xff]")


def agreement(a, b):
    r0 = c0 = 1 << 30
    r1 = c1 = -1
    for rows in (a, b):
        for r, row in enumerate(rows):
            first = LIT.search(row)
            if not first:
                continue
            last = len(row) - 1 - LIT.search(row[::-1]).start()
            r0, r1, c0, c1 = min(r0, r), max(r1, r), min(c0, first.start()), max(c1, last)
    if r1 < 0:
        return 100.0, 0
    r0, r1, c0, c1 = r0 - 1, r1 + 1, c0 - 1, c1 + 1
    total = differ = 0
    for r in range(max(r0, 0), min(r1, len(a) - 1) + 1):
        ra, rb = a[r], b[r]
        for c in range(max(c0, 0), min(c1, len(ra) - 1) + 1):
            total += 1
            differ += (ra[c] >= 128) != (rb[c] >= 128)
    return 100.0 * (total - differ) / total, differ


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("ours")
    p.add_argument("theirs")
    p.add_argument("--report", type=float, default=99.5, help="print the layers that agree less (percent)")
    o = p.parse_args()
    ours, theirs = layers(o.ours), layers(o.theirs)
    if len(ours) != len(theirs):
        print(f"layer counts differ: {len(ours)} against {len(theirs)}; the first {min(len(ours), len(theirs))} "
              f"are compared")
    scores = []
    for k, (x, y) in enumerate(zip(ours, theirs)):
        score, differ = agreement(read_png(x), read_png(y))
        scores.append(score)
        if score < o.report:
            print(f"layer {k}: {score:.2f}% agree ({differ} pixels differ)")
    print(f"{len(scores)} layers: lowest {min(scores):.2f}%, median {statistics.median(scores):.2f}% of the pixels "
          f"in the parts' box agree")
    return 0 if min(scores) >= o.report else 1


if __name__ == "__main__":
    sys.exit(main())
