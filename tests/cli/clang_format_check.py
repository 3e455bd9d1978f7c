#!/usr/bin/python3
"""Every C++ source and header of core/, plugins/ and tests/ is as clang-format (the
repository's .clang-format) writes it: one line per file that is not, exit 1.
Usage: clang_format_check.py REPOSITORY"""
import os
import subprocess
import sys


def sources(root):
    for top in ("core", "plugins", "tests"):
        for folder, _, names in os.walk(os.path.join(root, top)):
            yield from (os.path.join(folder, n) for n in sorted(names) if n.endswith((".cpp", ".hpp")))


def main():
    root = sys.argv[1]
    files = sorted(sources(root))
    unformatted = []
    for start in range(0, len(files), 200):
        batch = files[start:start + 200]
        run = subprocess.run(["clang-format", "--dry-run", "--Werror", *batch], cwd=root, capture_output=True, text=True)
        unformatted += sorted({line.split(":", 1)[0] for line in run.stderr.splitlines() if ": error: " in line})
    for path in unformatted:
        print(f"{os.path.relpath(path, root)}: not as clang-format writes it; expected `clang-format -i` on it")
    print(f"{len(files)} files checked, {len(unformatted)} not formatted")
    return 1 if unformatted else 0


if __name__ == "__main__":
    sys.exit(main())
