#!/usr/bin/env python3
"""Two figures of BENCHMARKS.md, "Every phase on every core", in one run: `particles` on one
thread in pairs per CPU second against `measures_pair_floor` (the measures' per-pair work on
data in L1, kernel_call_benchmark), on fcc 10^6 (k = 1.2) and Poisson 10^6 (N_H 60), three runs
each; the block's sums at the floor of their own arithmetic (block_pair_floor, each pair
once) against this build's on one thread; and `block cubic_bspline fcc --k 1.2 --size
100,100,100 --periodic` as a whole process, this build and earlier ones alternating, five runs
on every core and five on one thread, median wall time and peak resident set. Prints Markdown.
Usage: share/scripts/floor_and_block.py BUILD [NAME=EARLIER_BUILD ...]
  e.g. share/scripts/floor_and_block.py build dd93a0d=<dd93a0d's tree>/build b38e52e=<b38e52e's tree>/build"""
import json
import os
import pathlib
import statistics
import subprocess
import sys
import time

build = pathlib.Path(sys.argv[1]).resolve()
earlier = [arg.split("=", 1) for arg in sys.argv[2:]]


def floor(name):
    out = subprocess.run([str(build / "tests" / "kernel_call_benchmark"), f"--benchmark_filter=^{name}$",
                          "--benchmark_repetitions=3", "--benchmark_format=json"],
                         capture_output=True, text=True, check=True).stdout
    rates = [b["items_per_second"] for b in json.loads(out)["benchmarks"] if b.get("run_type") == "iteration"]
    return statistics.median(rates)


def pairs_per_cpu_second(args):
    out = subprocess.run([str(build / "sphkern"), "particles", "cubic_bspline", *args, "--threads", "1", "--json"],
                         capture_output=True, text=True, check=True).stdout
    answer = json.loads(out)
    return answer["pairs"] / answer["cpu_seconds"]


def whole_process(binary, args):
    start = time.perf_counter()
    child = subprocess.Popen([binary, *args], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    if status != 0:
        raise SystemExit(f"{binary} {' '.join(args)}: exit status {status}")
    return time.perf_counter() - start, usage.ru_maxrss / 1024


with open("/proc/cpuinfo") as f:
    cpu = next((line.split(":", 1)[1].strip() for line in f if line.startswith("model name")), "unknown")
    f.seek(0)
    avx512 = "avx512f" in f.read()
print(f"{cpu}, {os.cpu_count()} cores{', AVX-512' if avx512 else ''}\n")

ceiling = floor("measures_pair_floor")
print(f"measures_pair_floor: {ceiling:.3g} pairs per second (median of 3)\n")
print("| set | pairs per CPU second (3 runs) | of the floor |\n|---|---|---|")
for name, args in [("fcc 10^6, k = 1.2", ["fcc", "--size", "100,100,100", "--k", "1.2"]),
                   ("Poisson 10^6, N_H 60", ["poisson", "--count", "1000000", "--nh", "60"])]:
    rates = [pairs_per_cpu_second(args) for _ in range(3)]
    print(f"| {name} | {', '.join(f'{r:.3g}' for r in rates)} | "
          f"{min(rates) / ceiling:.2f} to {max(rates) / ceiling:.2f} |")

block = ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "100,100,100", "--periodic", "--json"]
# The block's own arithmetic at its floor: each pair evaluated once (at least half its pairs as
# a gather counts them), at block_pair_floor's rate per pair, on one thread.
block_floor = floor("block_pair_floor")
one = json.loads(subprocess.run([str(build / "sphkern"), *block, "--threads", "1"], capture_output=True, text=True,
                                check=True).stdout)
pairs, sums = one["pair_interactions_per_pass"], one["seconds"]["evaluation"]
print(f"\nblock_pair_floor: {block_floor:.3g} pairs per second. The block's {pairs} pairs, each once, are at least "
      f"{pairs / 2 / block_floor:.3f} s of that arithmetic on one thread; this build's sums on one thread took "
      f"{sums:.3f} s ({pairs / 2 / block_floor / sums:.2f} of the floor's speed), its setup {one['seconds']['setup']:.3f} s.")

builds = [("this build", str(build / "sphkern"))] + [(name, str(pathlib.Path(path).resolve() / "sphkern")) for name, path in earlier]
for threads in ([], ["--threads", "1"]):
    command = block + threads
    runs = {name: [] for name, _ in builds}
    for _ in range(5):
        for name, binary in builds:
            runs[name].append(whole_process(binary, command))
    print(f"\n`{' '.join(command)}`, five alternating runs, medians:\n")
    print("| build | wall [s] | peak [MiB] | this build / it (wall) |\n|---|---:|---:|---:|")
    mine = statistics.median(r[0] for r in runs["this build"])
    for name, _ in builds:
        wall = statistics.median(r[0] for r in runs[name])
        print(f"| {name} | {wall:.3f} | {statistics.median(r[1] for r in runs[name]):.0f} | {mine / wall:.2f} |")
