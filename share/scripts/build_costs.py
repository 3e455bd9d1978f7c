#!/usr/bin/env python3
"""What compiling sphkern costs.
  build_costs.py units TIMES [N]   the N slowest units (default 10) and the total CPU time, from
                                   the file compile_timer.py wrote
  build_costs.py headers           the CPU time of one unit that only includes each heavy header
                                   of internals.md's table, at the release build's flags"""
import pathlib
import re
import resource
import subprocess
import sysconfig
import sys
import tempfile

root = pathlib.Path(__file__).resolve().parents[2]


def units(times, count):
    rows = []
    for line in pathlib.Path(times).read_text().splitlines():
        wall, cpu, output = line.split(maxsplit=2)
        rows.append((float(cpu), output))
    rows.sort(reverse=True)
    print(f"{len(rows)} units, {sum(c for c, _ in rows):.1f} s of CPU")
    print("| unit | CPU seconds |\n|---|---:|")
    for cpu, output in rows[:count]:
        name = re.sub(r".*CMakeFiles/", "", output).removesuffix(".o")
        print(f"| {name} | {cpu:.2f} |")


def heavy_headers():
    text = (root / "share/docs/internals.md").read_text()
    # The header measured is the last <...> of a row's first cell (its pattern, or the one in brackets).
    section = text.split("\n## Build time\n", 1)[1].split("\n## ", 1)[0]
    return [re.findall(r"`<([^>]+)>`", line.split("|")[1])[-1] for line in section.splitlines()
            if line.startswith("| `<")]


def headers():
    flags = ["g++", "-std=c++20", "-O3", "-DNDEBUG", "-DSPDLOG_COMPILED_LIB", "-DSPDLOG_FMT_EXTERNAL",
             "-isystem", "/usr/include/eigen3", "-isystem", "/usr/include/hdf5/serial",
             "-isystem", sysconfig.get_paths()["include"]]
    with tempfile.TemporaryDirectory() as folder:
        unit = pathlib.Path(folder) / "unit.cpp"
        print("| header | CPU seconds |\n|---|---:|")
        for header in heavy_headers():
            unit.write_text(f"#include <{header}>\n")
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run(flags + ["-c", str(unit), "-o", "/dev/null"], check=True)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
            print(f"| `<{header}>` | {cpu:.2f} |")


if len(sys.argv) >= 3 and sys.argv[1] == "units":
    units(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 10)
elif len(sys.argv) == 2 and sys.argv[1] == "headers":
    headers()
else:
    sys.exit(__doc__)
