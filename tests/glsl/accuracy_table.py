#!/usr/bin/env python3
"""Turns the "[ measured ]" lines of glsl_generated_tests into the accuracy table of docs/glsl.md.

usage:
  build/tests/glsl/glsl_generated_tests --gtest_filter='*GlslVsDouble*:*CFloatVsDouble*' \\
      | python3 tests/glsl/accuracy_table.py
"""
import re
import sys

LINE = re.compile(
    r"\[ measured \] (\w+)\s+o(\d) (compute|fragment|C float)\s+field (\S+)\s+offset (\S+) "
    r"\(all (\S+)\)\s+zero set (\S+)\s+shell (\S+)\s+normal (\S+)")


def main():
    rows = {}
    order = []
    for line in sys.stdin:
        m = LINE.search(line)
        if not m:
            continue
        surface, m_, where = m.group(1), int(m.group(2)), m.group(3)
        key = (surface, m_)
        if key not in rows:
            rows[key] = {}
            order.append(key)
        rows[key][where] = dict(zip(
            ["field", "offset", "all", "zero", "shell", "normal"],
            [float(m.group(i)) for i in range(4, 10)]))
    if not rows:
        sys.exit("accuracy_table: no '[ measured ]' lines on stdin")

    def f(v):
        return "%.1e" % v

    print("| surface | m | offset, GLSL compute | offset, GLSL ES fragment | offset, C float "
          "| zero set shift (L) | shell | normal | field | offset, all points |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for key in order:
        r = rows[key]
        glsl = [r[w] for w in ("compute", "fragment") if w in r]
        worst = lambda q: max(x[q] for x in glsl + ([r["C float"]] if "C float" in r else []))
        cells = [key[0], str(key[1])]
        for w in ("compute", "fragment", "C float"):
            cells.append(f(r[w]["offset"]) if w in r else "-")
        for q in ("zero", "shell", "normal", "field", "all"):
            cells.append(f(worst(q)))
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
