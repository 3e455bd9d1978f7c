#!/usr/bin/env python3
"""A table a document shows, made by a script: the script runs again with the program under
test (in place of build/sphkern, and the built Python module on PYTHONPATH), and every table
row it prints must be a row of the document as written. The document marks such a table with
the comment <!-- table: python3 share/scripts/NAME.py build/sphkern --> on the line before it.
Usage: docs_table.py SOURCE_DIR SPHKERN DOCUMENT SCRIPT [PYTHON_MODULE_DIR] [-- SCRIPT_ARGS...]"""
import os
import subprocess
import sys
from pathlib import Path

args, extra = (sys.argv[1:sys.argv.index("--")], sys.argv[sys.argv.index("--") + 1:]) if "--" in sys.argv \
    else (sys.argv[1:], [])
root, sphkern, document, script = Path(args[0]), args[1], Path(args[2]), args[3]
env = dict(os.environ, PYTHONPATH=args[4]) if len(args) > 4 else dict(os.environ)
text = document.read_text()
marker = f"<!-- table: python3 {script} build/sphkern -->"
if marker not in text:
    sys.exit(f"{document.name}: no table marked {marker}")
done = subprocess.run([sys.executable, str(root / script), sphkern, *extra], capture_output=True, text=True,
                      env=env, cwd=root, timeout=300)
if done.returncode != 0:
    sys.exit(f"{script}: exit {done.returncode}\n{done.stderr[-2000:]}")
rows = [row for row in done.stdout.splitlines() if row.startswith("|")]
table = text.split(marker, 1)[1].lstrip("\n").split("\n\n", 1)[0].splitlines()
stale = [row for row in rows if row not in table]
if not rows or stale:
    sys.exit(f"{document.name}: the table after {marker} differs from what the script prints now:\n  "
             + "\n  ".join(stale or ["(no rows printed)"]))
print(f"{document.name}: {len(rows)} rows of {script} as shown")
