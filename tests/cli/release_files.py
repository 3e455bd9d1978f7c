#!/usr/bin/env python3
"""The files that make sphkern citable and versioned agree with each other and with the build.
CITATION.cff against the required keys of the Citation File Format 1.2.0 (cff-version,
message, title, authors; each author a person with family-names or an entity with name),
its version and the changelog's against the one in CMakeLists.txt, --version against it,
the licence against the README.
Usage: release_files.py SOURCE_DIR SPHKERN"""
import re
import subprocess
import sys
from pathlib import Path

import yaml

root, sphkern = Path(sys.argv[1]), sys.argv[2]
version = re.search(r"project\(sphkern VERSION ([0-9.]+)", (root / "CMakeLists.txt").read_text()).group(1)

cff = yaml.safe_load((root / "CITATION.cff").read_text())
for key in ("cff-version", "message", "title", "authors"):
    assert key in cff and cff[key], f"CITATION.cff: the required key {key} is missing or empty"
assert str(cff["cff-version"]).startswith("1.2"), cff["cff-version"]
assert isinstance(cff["authors"], list)
for author in cff["authors"]:
    assert "family-names" in author or "name" in author, f"CITATION.cff: an author without a name: {author}"
assert str(cff["version"]) == version, (cff["version"], version)
assert cff["license"] == "MIT"

assert (root / "LICENSE").read_text().startswith("MIT License")
assert re.search(r"MIT licen[cs]e", (root / "README.md").read_text()), "the README does not state the licence"
changelog = (root / "CHANGELOG.md").read_text()
assert re.search(rf"^## {re.escape(version)} - \d{{4}}-\d\d-\d\d$", changelog, re.M), "no changelog entry for " + version

out = subprocess.run([sphkern, "--version"], check=True, capture_output=True, text=True).stdout
assert out.splitlines()[0].startswith(f"sphkern {version}"), out
print("release files agree with version", version)
