#!/usr/bin/env python3
"""A compiler launcher that times each compilation: configure with
-DCMAKE_CXX_COMPILER_LAUNCHER=share/scripts/compile_timer.py (and _C_ likewise) and every
compile appends "wall_seconds cpu_seconds output" to $SPHKERN_COMPILE_TIMES
(default: compile-times.txt in the working folder). build_costs.py summarises the file."""
import os
import resource
import subprocess
import sys
import time

started = time.monotonic()
status = subprocess.call(sys.argv[1:])
wall = time.monotonic() - started
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
output = sys.argv[sys.argv.index("-o") + 1] if "-o" in sys.argv else "?"
with open(os.environ.get("SPHKERN_COMPILE_TIMES", "compile-times.txt"), "a") as log:
    log.write(f"{wall:.2f} {usage.ru_utime + usage.ru_stime:.2f} {output}\n")
sys.exit(status)
