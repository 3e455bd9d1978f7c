#!/usr/bin/env python3
"""The particle engine's figures in share/docs/BENCHMARKS.md: pairs per second of
`sphkern particles` on fcc blocks and Poisson sets of 10^6 and 8 10^6 particles (cubic
spline, about 80 and 60 neighbours), 1 and 2 threads, against the machine's pair ceiling
(`fused_pair_ceiling` of kernel_call_benchmark), and a 10^6-particle SWIFT file read and
evaluated, whole process. Also against the measures' own floor (`measures_pair_floor`: the
engine's per-pair arithmetic on data in L1, without the search). Medians of three runs. Prints Markdown. With a second build
(an earlier commit built with the same flags), each case also runs there, alternating
with this build, and the table gains the earlier sums and the ratio of the two.
Usage: share/scripts/particles_benchmark.py [BUILD [BASE_BUILD]]   (needs python3-h5py and numpy)"""
import json
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile
import time

build = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build").resolve()
sphkern = str(build / "sphkern")
base = str(pathlib.Path(sys.argv[2]).resolve() / "sphkern") if len(sys.argv) > 2 else None


def ceiling(name):
    """Pairs per second of one core in the benchmark `name` of kernel_call_benchmark."""
    bench = build / "tests" / "kernel_call_benchmark"
    if not bench.exists():
        return None
    out = subprocess.run([str(bench), f"--benchmark_filter=^{name}$", "--benchmark_repetitions=5",
                          "--benchmark_format=json"], capture_output=True, text=True, check=True).stdout
    rates = [b["items_per_second"] for b in json.loads(out)["benchmarks"] if b.get("run_type") == "iteration"]
    return statistics.median(rates)


def run_once(binary, args, threads):
    """The answer, the wall time and the CPU time (all threads) of one whole process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    out = subprocess.run([binary, "particles", "cubic_bspline", *args, "--threads", str(threads), "--json"],
                         capture_output=True, text=True, check=True).stdout
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return json.loads(out), wall, cpu


def run(args, threads):
    """Medians of three runs of this build (and of the base, alternating with it)."""
    runs, base_runs, doc = [], [], None
    for _ in range(3):
        doc, wall, cpu = run_once(sphkern, args, threads)
        runs.append((doc["seconds"], doc.get("cpu_seconds", 0), wall, cpu))
        if base:
            base_doc, base_wall, base_cpu = run_once(base, args, threads)
            assert base_doc["pairs"] == doc["pairs"], (base_doc["pairs"], doc["pairs"])
            base_runs.append((base_doc["seconds"], base_cpu))
    median = [statistics.median(column) for column in zip(*runs)]
    return doc, median, [statistics.median(column) for column in zip(*base_runs)] if base else None


per_core = ceiling("fused_pair_ceiling")
floor = ceiling("measures_pair_floor")  # the measures' own arithmetic, no search
extra = " base sums [s] | base / this, sums | base / this, process CPU |" if base else ""
print("| set | particles | neighbours | threads | pairs | sums [s] | sums, CPU [s] | whole process [s] | "
      "pairs per second | of the ceiling | pairs per CPU second | of the ceiling (CPU) | of the floor (CPU) |" + extra)
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|" + ("---:|---:|---:|" if base else ""))
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
            doc, (sums, sums_cpu, wall, cpu), base_median = run(args, t)
            rate, cpu_rate = doc["pairs"] / sums, doc["pairs"] / sums_cpu
            share = f"{rate / (per_core * t):.2f}" if per_core else "-"
            cpu_share = f"{cpu_rate / per_core:.2f}" if per_core else "-"
            floor_share = f"{cpu_rate / floor:.2f}" if floor else "-"
            row = (f"| {name} | {doc['source']['particles']} | {doc['mean_neighbours']:.1f} | {t} | {doc['pairs']} | "
                   f"{sums:.3f} | {sums_cpu:.3f} | {wall:.3f} | {rate:.3g} | {share} | {cpu_rate:.3g} | {cpu_share} | "
                   f"{floor_share} |")
            if base:
                base_sums, base_cpu = base_median
                row += f" {base_sums:.3f} | {base_sums / sums:.2f} | {base_cpu / cpu:.2f} |"
            print(row, flush=True)
if per_core:
    print(f"\nCeiling: fused_pair_ceiling, {per_core:.3g} pairs per second of CPU time on one core (median of 5).")
if floor:
    print(f"Floor of the measures: measures_pair_floor, {floor:.3g} pairs per second on one core (median of 5), "
          f"{floor / per_core:.2f} of the ceiling.")
print(f"Load average at the end: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores.")
