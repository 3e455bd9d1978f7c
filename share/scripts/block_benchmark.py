#!/usr/bin/env python3
"""The block's figures in share/docs/BENCHMARKS.md: pairs per second of `sphkern block` on
periodic fcc blocks of 10^6 and 8 10^6 particles (cubic spline, k = 1.2, 78 neighbours), 1
and 2 threads, against the machine's pair ceiling (`fused_pair_ceiling` of
kernel_call_benchmark), medians of three runs. With a second build (an earlier commit built
with the same flags) each case also runs there, alternating, and the table gains its rate.
Usage: share/scripts/block_benchmark.py [BUILD [BASE_BUILD]]"""
import json
import pathlib
import statistics
import subprocess
import sys

build = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build").resolve()
base = str(pathlib.Path(sys.argv[2]).resolve() / "sphkern") if len(sys.argv) > 2 else None


def ceiling():
    out = subprocess.run([str(build / "tests" / "kernel_call_benchmark"), "--benchmark_filter=^fused_pair_ceiling$",
                          "--benchmark_repetitions=5", "--benchmark_format=json"],
                         capture_output=True, text=True, check=True).stdout
    return statistics.median(b["items_per_second"] for b in json.loads(out)["benchmarks"]
                             if b.get("run_type") == "iteration")


def run_once(binary, n, threads):
    out = subprocess.run([binary, "block", "cubic_bspline", "fcc", "--k", "1.2", "--size", f"{n},{n},{n}", "--periodic",
                          "--threads", str(threads), "--json"], capture_output=True, text=True, check=True).stdout
    doc = json.loads(out)
    return doc["pair_interactions_per_pass"], doc["seconds"]["setup"], doc["seconds"]["evaluation"]


limit = ceiling()
print("| particles | threads | pairs | setup [s] | sums [s] | pairs per second | of the ceiling (per core) |"
      + (" base sums [s] | base pairs per second | base of the ceiling | base / this, sums |" if base else ""))
print("|---:|---:|---:|---:|---:|---:|---:|" + ("---:|---:|---:|---:|" if base else ""))
for n, threads in ((100, 1), (100, 2), (200, 2)):
    runs, base_runs = [], []
    for _ in range(3):
        runs.append(run_once(str(build / "sphkern"), n, threads))
        if base:
            base_runs.append(run_once(base, n, threads))
    pairs = runs[0][0]
    setup = statistics.median(r[1] for r in runs)
    sums = statistics.median(r[2] for r in runs)
    row = f"| {n ** 3} | {threads} | {pairs} | {setup:.3f} | {sums:.3f} | {pairs / sums:.3g} | {pairs / sums / threads / limit:.2f} |"
    if base:
        base_sums = statistics.median(r[2] for r in base_runs)
        row += (f" {base_sums:.3f} | {pairs / base_sums:.3g} | {pairs / base_sums / threads / limit:.2f} |"
                f" {base_sums / sums:.2f} |")
    print(row)
print(f"\nCeiling: fused_pair_ceiling, {limit:.3g} pairs per second on one core (median of 5).")
