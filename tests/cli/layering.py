#!/usr/bin/env python3
"""Every #include "LAYER/..." in core/ points to the layer itself or one it links (the DEPENDS
of sphkern_layer in core/CMakeLists.txt, transitively). A static library can use a header of a
layer above it and still build; this test is what stops it. Usage: layering.py SOURCE_DIR"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1]) / "core"
cmake = (root / "CMakeLists.txt").read_text()
depends = {}
for name, args in re.findall(r"^sphkern_layer\((\w+)(.*?)\)\s*$", cmake, re.M | re.S):
    depends[name] = set(re.findall(r"sphkern_(\w+)", args))
layers = set(depends)


def below(layer, seen=None):
    seen = set() if seen is None else seen
    for d in depends.get(layer, ()):
        if d in layers and d not in seen:
            seen.add(d)
            below(d, seen)
    return seen


problems = []
for layer in sorted(layers):
    allowed = below(layer) | {layer}
    for path in sorted((root / layer).rglob("*")):
        if path.suffix not in (".cpp", ".hpp"):
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = re.match(r'\s*#\s*include\s+"(\w+)/', line)
            if match and match.group(1) in layers and match.group(1) not in allowed:
                problems.append(f"{path.relative_to(root.parent)}:{number}: {layer} includes {match.group(1)}, "
                                f"a layer it does not link (it links {', '.join(sorted(allowed - {layer})) or 'nothing'})")
if len(layers) < 8:
    problems.append(f"found only the layers {sorted(layers)} in core/CMakeLists.txt")
print("\n".join(problems) if problems else f"{len(layers)} layers, every include points down")
sys.exit(1 if problems else 0)
