#!/usr/bin/env python3
"""The folders of src/ depend downward only: each may include headers of the folders listed before it
and of no folder after it (docs/architecture.md). Nothing in src/ includes tools/. Prints every
include that breaks the order and exits 1; run from the repository root."""
import pathlib
import re
import sys

# Lowest first. support/ builds what libraries Debian ships only shared (fmt), and holds the interrupt handler. field/ and lowering/ are the machinery the offset constructions lower themselves
# with, so offset/ sits above them; run/ turns generated files into code for check, mesh and step.
LAYERS = ["support", "surfaces", "body", "field", "lowering", "offset", "density", "emit", "validate",
          "pipeline", "run", "check", "mesh", "step", "cli", "dev"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([A-Za-z_]+)/', re.MULTILINE)


def main():
    src = pathlib.Path("src")
    folders = sorted(p.name for p in src.iterdir() if p.is_dir())
    unknown = [f for f in folders if f not in LAYERS]
    if unknown:
        print(f"src/ folders without a layer (add them to LAYERS): {', '.join(unknown)}")
        return 1
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
            elif LAYERS.index(target) > LAYERS.index(folder):
                broken.append(f"{path}: {folder}/ includes {target}/, a later stage")
    for line in broken:
        print(line)
    print(f"{len(broken)} include(s) against the layer order" if broken else "layers: every include points down")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
