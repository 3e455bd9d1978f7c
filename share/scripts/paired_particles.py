#!/usr/bin/env python3
"""`particles` runs of this build against an earlier one, alternating, for BENCHMARKS.md ("The
measures' records"): fcc 10^6 (k = 1.2) and Poisson 10^6 (N_H 60) on one thread, Poisson
4 x 10^6 on two; the median wall time (with its range), the sums' seconds, pairs per CPU second
of the sums, the sums' share of the wall time and the peak resident set of each. Prints Markdown.
Usage: share/scripts/paired_particles.py THIS_SPHKERN EARLIER_SPHKERN [RUNS]"""
import json
import os
import statistics
import subprocess
import sys
import time

CASES = {
    "fcc 10^6, k 1.2, 1 thread": ["cubic_bspline", "fcc", "--k", "1.2", "--size", "100,100,100", "--threads", "1"],
    "Poisson 10^6, N_H 60, 1 thread": ["cubic_bspline", "poisson", "--count", "1000000", "--nh", "60", "--threads", "1"],
    "Poisson 4x10^6, N_H 60, 2 threads": ["cubic_bspline", "poisson", "--count", "4000000", "--nh", "60", "--threads", "2"],
}


def run(exe, args):
    """Wall seconds, the --json document and the peak resident set in MiB of one process."""
    start = time.perf_counter()
    process = subprocess.Popen([exe, "particles", *args, "--json"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    out = process.stdout.read()
    _, status, usage = os.wait4(process.pid, 0)
    if status != 0:
        sys.exit(f"{exe} particles {' '.join(args)} failed")
    return time.perf_counter() - start, json.loads(out), usage.ru_maxrss / 1024


def main():
    builds = {"this": sys.argv[1], "earlier": sys.argv[2]}
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    results = {}
    for _ in range(runs):
        for case, args in CASES.items():
            for name, exe in builds.items():
                results.setdefault((case, name), []).append(run(exe, args))
    print("| case | build | wall [s] | sums [s] | pairs per CPU second of the sums | sums / wall | peak [MiB] |")
    print("|---|---|---:|---:|---:|---:|---:|")
    spread = lambda v: f"{statistics.median(v):.3f} ({min(v):.3f} to {max(v):.3f})"
    for (case, name), rows in results.items():
        walls = [w for w, _, _ in rows]
        sums = [d["seconds"] for _, d, _ in rows]
        cpu = statistics.median(d["cpu_seconds"] for _, d, _ in rows)
        print(f"| {case} | {name} | {spread(walls)} | {spread(sums)} | {rows[0][1]['pairs'] / cpu:.3e} | "
              f"{spread([s / w for s, w in zip(sums, walls)])} | {max(p for _, _, p in rows):.1f} |")


if __name__ == "__main__":
    main()
