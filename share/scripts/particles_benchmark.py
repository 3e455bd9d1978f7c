#!/usr/bin/env python3
"""The particle engine's figures in share/docs/BENCHMARKS.md: pairs per second of
`sphkern particles` on fcc blocks and Poisson sets of 10^6 and 8 10^6 particles (cubic
spline, about 80 and 60 neighbours), 1 and 2 threads, against the machine's pair ceiling
(`fused_pair_ceiling` of kernel_call_benchmark), and a 10^6-particle SWIFT file read and
evaluated, whole process. Medians of three runs. Prints Markdown.
Usage: share/scripts/particles_benchmark.py [BUILD]   (needs python3-h5py and numpy)"""
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

build = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build").resolve()
sphkern = str(build / "sphkern")


def ceiling():
    bench = build / "tests" / "kernel_call_benchmark"
    if not bench.exists():
        return None
    out = subprocess.run([str(bench), "--benchmark_filter=fused_pair_ceiling", "--benchmark_repetitions=5",
                          "--benchmark_format=json"], capture_output=True, text=True, check=True).stdout
    rates = [b["items_per_second"] for b in json.loads(out)["benchmarks"] if b.get("run_type") == "iteration"]
    return statistics.median(rates)


def run(args, threads):
    sums, walls, doc = [], [], None
    for _ in range(3):
        start = time.perf_counter()
        out = subprocess.run([sphkern, "particles", "cubic_bspline", *args, "--threads", str(threads), "--json"],
                             capture_output=True, text=True, check=True).stdout
        walls.append(time.perf_counter() - start)
        doc = json.loads(out)
        sums.append(doc["seconds"])
    return doc, statistics.median(sums), statistics.median(walls)


per_core = ceiling()
print("| set | particles | neighbours | threads | pairs | sums [s] | whole process [s] | pairs per second | of the ceiling |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
cases = [("fcc, k = 1.2", ["fcc", "--size", "100,100,100", "--k", "1.2"], (1, 2)),
         ("Poisson, N_H = 60", ["poisson", "--count", "1000000", "--nh", "60"], (1, 2)),
         ("fcc, k = 1.2", ["fcc", "--size", "200,200,200", "--k", "1.2"], (2,)),
         ("Poisson, N_H = 60", ["poisson", "--count", "8000000", "--nh", "60"], (2,))]
with tempfile.TemporaryDirectory() as work:
    import h5py
    import numpy as np
    n = 10**6
    rng = np.random.default_rng(1)
    with h5py.File(f"{work}/snapshot.hdf5", "w") as f:
        header = f.create_group("Header")
        header.attrs["BoxSize"] = [1.0, 1.0, 1.0]
        header.attrs["Dimension"] = 3
        header.attrs["NumPart_Total"] = [n, 0, 0, 0, 0, 0]
        f.create_group("HydroScheme").attrs["Kernel gamma"] = 1.825742
        part = f.create_group("PartType0")
        part["Coordinates"] = rng.uniform(0, 1, (n, 3))
        part["SmoothingLengths"] = np.full(n, 1.2 * n ** (-1 / 3))
        part["Masses"] = np.full(n, 1.0 / n)
        part["Densities"] = np.ones(n)
    cases.append(("SWIFT HDF5 file", [f"{work}/snapshot.hdf5"], (2,)))
    for name, args, threads in cases:
        for t in threads:
            doc, sums, wall = run(args, t)
            rate = doc["pairs"] / sums
            share = f"{rate / (per_core * t):.2f}" if per_core else "-"
            print(f"| {name} | {doc['source']['particles']} | {doc['mean_neighbours']:.1f} | {t} | {doc['pairs']} | "
                  f"{sums:.3f} | {wall:.3f} | {rate:.3g} | {share} |")
if per_core:
    print(f"\nCeiling: fused_pair_ceiling, {per_core:.3g} pairs per second on one core (median of 5).")
