#!/usr/bin/env python3
"""Every #include "LAYER/..." in core/ points to the layer itself or one it links (the DEPENDS
of sphkern_layer in core/CMakeLists.txt, transitively). A static library can use a header of a
layer above it and still build; this test is what stops it. It also holds the picture of the
house in share/docs/internals.md to the code: each layer's links, the table of study sections
(each with its folder) and the request files (one per command but run). Usage: layering.py SOURCE_DIR"""
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


def check_picture():
    """The fenced block after the marker in internals.md against CMake, the section table and requests/."""
    text = (root.parent / "share" / "docs" / "internals.md").read_text()
    marker = text.find("<!-- house: checked by tests/cli/layering.py -->")
    if marker < 0:
        return ["share/docs/internals.md: the picture of the house (its marker) is missing"]
    start = text.index("```text\n", marker) + len("```text\n")
    picture = text[start:text.index("```", start)]
    found = []
    drawn = {}
    for line in picture.splitlines():
        link = re.match(r"^(\w+)\s+->\s+([\w ]+)$", line)
        if link:
            drawn[link.group(1)] = set(link.group(2).split())
        elif re.match(r"^(\w+)\s*$", line):
            drawn[line.strip()] = set()
    for layer in sorted(layers | set(drawn)):
        links = depends.get(layer, set()) & layers
        if drawn.get(layer) != links:
            found.append(f"internals.md: the picture draws {layer} -> {sorted(drawn.get(layer, [])) if layer in drawn else 'nothing'}, "
                         f"core/CMakeLists.txt says {sorted(links) if layer in layers else 'no such layer'}")
    table = (root / "study" / "sections" / "section_table.cpp").read_text()
    keys = re.findall(r'\{"(\w+)", read_\w+\}', table)
    sections = re.search(r"sections: ([\w ]+)", picture)
    if not sections or sections.group(1).split() != keys:
        found.append(f"internals.md: the picture's sections differ from section_table.cpp's rows {keys}")
    for key in keys:
        if not (root / "study" / "sections" / key).is_dir():
            found.append(f"core/study/sections/{key}/: the section {key} has no folder")
    requests = re.search(r"requests: ([\w ]+)", picture)
    commands = sorted(p.stem[len("command_"):] for p in (root / "cli").glob("command_*.cpp"))
    files = sorted(p.stem[: -len("_request")] for p in (root / "requests").glob("*_request.hpp"))
    drawn_requests = sorted(requests.group(1).split()) if requests else []
    if drawn_requests != sorted(set(commands) - {"run"}):
        found.append(f"internals.md: the picture's requests {drawn_requests} are not the commands but run {commands}")
    for name in drawn_requests:
        if name not in files:
            found.append(f"core/requests/{name}_request.hpp: the command {name} has no request")
    return found


problems += check_picture()
if len(layers) < 8:
    problems.append(f"found only the layers {sorted(layers)} in core/CMakeLists.txt")
print("\n".join(problems) if problems else f"{len(layers)} layers, every include points down")
sys.exit(1 if problems else 0)
