#!/usr/bin/env python3
"""Whole-command wall-clock times of two sphkern builds, side by side: each command is run
through both builds in alternation (so that a loaded machine slows both alike), after a
warm-up run that fills each build's own plugin probe cache. Prints a Markdown table of
medians and means and the ratio after / before.
Usage: python3 share/scripts/compare_builds.py BEFORE_SPHKERN AFTER_SPHKERN [RUNS]"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

before, after = sys.argv[1], sys.argv[2]
runs = int(sys.argv[3]) if len(sys.argv) > 3 else 15
commands = [
    ("`run --no-plots` (the default study)", ["run", "--no-plots", "--force", "-o", "{work}/out"]),
    ("`run` (the default study with its SVG figures)", ["run", "--force", "-o", "{work}/out"]),
    ("`roots all all --json`", ["roots", "all", "all", "--json"]),
    ("`eps cubic_bspline fcc --k 1.2 --json`", ["eps", "cubic_bspline", "fcc", "--k", "1.2", "--json"]),
]
with tempfile.TemporaryDirectory() as work:
    def run(program, words, cache):
        env = dict(os.environ, XDG_CACHE_HOME=cache)
        start = time.perf_counter()
        subprocess.run([program] + [w.format(work=work) for w in words], check=True, env=env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return time.perf_counter() - start

    print(f"| command | before, median [ms] | after, median [ms] | before, mean [ms] | after, mean [ms] | after / before (medians) |")
    print("|---|---:|---:|---:|---:|---:|")
    for title, words in commands:
        times = {before: [], after: []}
        for program in (before, after):
            run(program, words, os.path.join(work, "cache-" + str(program == after)))
        for _ in range(runs):
            for program in (before, after):
                times[program].append(run(program, words, os.path.join(work, "cache-" + str(program == after))))
        b, a = (statistics.median(times[p]) * 1e3 for p in (before, after))
        mb, ma = (statistics.mean(times[p]) * 1e3 for p in (before, after))
        print(f"| {title} | {b:.1f} | {a:.1f} | {mb:.1f} | {ma:.1f} | {a / b:.2f} |")
