#!/usr/bin/env python3
"""The folders of src/ depend downward only, and peers stay peers (docs/architecture.md): each folder
may include headers of the folders before it in LAYERS, except its peers (the commands that sit side
by side on the evaluation layer include none of each other). Nothing in src/ includes tools/.

    tests/tools/check_layers.py [--root DIR]          prints every include that breaks the graph; exit 1 if any
    tests/tools/check_layers.py --markdown            the graph as docs/architecture.md shows it
    tests/tools/check_layers.py --check-doc FILE      exit 1 unless FILE holds that text between its markers

Run from the repository root (or give --root)."""
import argparse
import pathlib
import re
import sys

# Lowest first. support/ builds what libraries Debian ships only shared (fmt), and holds the interrupt
# handler. field/ and lowering/ are the machinery the offset constructions lower themselves with, so
# offset/ sits above them; run/ turns generated files into code; numeric/ and wall/ are the evaluation
# layer below the commands.
LAYERS = ["support", "surfaces", "body", "field", "lowering", "offset", "density", "emit", "validate",
          "pipeline", "run", "numeric", "wall", "check", "mesh", "step", "slice", "cli", "dev"]
# Folders side by side: none includes another of its group.
PEERS = [["check", "mesh", "step", "slice"]]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([A-Za-z_]+)/', re.MULTILINE)
DOC_BEGIN = "<!-- layers: written by tests/tools/check_layers.py --markdown -->"
DOC_END = "<!-- end of layers -->"


def peers_of(folder):
    return {p for group in PEERS if folder in group for p in group if p != folder}


def allowed(folder):
    """The folders `folder` may include."""
    return [f for f in LAYERS[:LAYERS.index(folder)] if f not in peers_of(folder)]


def markdown():
    lines = [DOC_BEGIN, "", "| folder | may include |", "|---|---|"]
    for folder in LAYERS:
        below = allowed(folder)
        text = ", ".join(f"`{f}`" for f in below) if below else "nothing of src/"
        peers = sorted(peers_of(folder))
        if peers:
            text += " (not its peers " + ", ".join(f"`{p}`" for p in peers) + ")"
        lines.append(f"| `{folder}` | {text} |")
    lines += ["", DOC_END]
    return "\n".join(lines)


def broken_includes(src):
    folders = sorted(p.name for p in src.iterdir() if p.is_dir())
    unknown = [f for f in folders if f not in LAYERS]
    if unknown:
        return [f"src/ folders without a layer (add them to LAYERS): {', '.join(unknown)}"]
    broken = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".h", ".cpp", ".inc"):
            continue
        folder = path.relative_to(src).parts[0]
        for target in INCLUDE.findall(path.read_text(encoding="utf-8")):
            if target == folder:
                continue
            if target not in LAYERS:
                broken.append(f"{path}: includes {target}/, which is not a folder of src/")
            elif target in peers_of(folder):
                broken.append(f"{path}: {folder}/ includes {target}/, a peer")
            elif target not in allowed(folder):
                broken.append(f"{path}: {folder}/ includes {target}/, a later stage")
    return broken


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", default=".")
    parser.add_argument("--markdown", action="store_true")
    parser.add_argument("--check-doc")
    a = parser.parse_args()
    if a.markdown:
        print(markdown())
        return 0
    if a.check_doc:
        text = pathlib.Path(a.check_doc).read_text(encoding="utf-8")
        if markdown() not in text:
            print(f"{a.check_doc} does not hold the layers as check_layers.py --markdown writes them; paste its output "
                  "between the markers")
            return 1
        print(f"{a.check_doc}: the layers table matches")
        return 0
    broken = broken_includes(pathlib.Path(a.root) / "src")
    for line in broken:
        print(line)
    print(f"{len(broken)} include(s) against the layer graph" if broken else "layers: every include points down, "
          "and no peer includes another")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
