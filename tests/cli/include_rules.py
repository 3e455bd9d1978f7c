#!/usr/bin/env python3
"""Every heavy header is included only where internals.md ("Build time") allows it: each row
of its table names the includes it governs (`<pattern>`, the first row that matches wins) and
where under core/ they may appear (`glob`, `*.cpp` meaning any source). A header that pulls
CLI11 or Eigen's solvers into units that do not need them builds and runs: this test is what
stops it. Usage: include_rules.py SOURCE_DIR"""
import fnmatch
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
text = (root / "share/docs/internals.md").read_text()
section = text.split("\n## Build time\n", 1)[1].split("\n## ", 1)[0]
rules = []
for line in section.splitlines():
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) == 3 and cells[0].startswith("`<"):
        pattern = re.match(r"`<([^>]+)>`", cells[0]).group(1)
        rules.append((pattern, re.findall(r"`([^`<>]+)`", cells[2])))
problems = [] if len(rules) >= 8 else [f"internals.md, Build time: found only {len(rules)} include rules"]

core = root / "core"
for path in sorted(p for p in core.rglob("*") if p.suffix in (".cpp", ".hpp", ".h")):
    where = str(path.relative_to(core))
    for number, line in enumerate(path.read_text().splitlines(), 1):
        match = re.match(r"\s*#\s*include\s+<([^>]+)>", line)
        if not match:
            continue
        rule = next((r for r in rules if fnmatch.fnmatchcase(match.group(1), r[0])), None)
        if rule and not any(fnmatch.fnmatchcase(where, place) for place in rule[1]):
            problems.append(f"core/{where}:{number}: <{match.group(1)}> may be included only by "
                            f"{', '.join(rule[1])} (internals.md, Build time)")
print("\n".join(problems) if problems else f"{len(rules)} include rules hold in core/")
sys.exit(1 if problems else 0)
