#!/usr/bin/env python3
"""Whole-process thread scaling of `sphkern particles` and `sphkern relax` (BENCHMARKS.md,
"Every phase parallel"): each case on 1 thread and on every core, this build and an earlier
one alternating, medians of REPEATS runs. Wall and CPU time come from the process itself,
peak memory from wait4 (maximum resident set), the phases from this build's --json.
Prints Markdown and writes the raw runs to OUT/thread_scaling.json.
Usage: share/scripts/thread_scaling.py OUT "HEAD_COMMAND" ["BASE_COMMAND"] [REPEATS]
  e.g. share/scripts/thread_scaling.py /tmp/scaling "build/sphkern" "/tmp/base/build/sphkern" 3
A command is split on spaces into the program and its first arguments (a wrapper such as
"bundle/sk/run sphkern")."""
import json
import os
import pathlib
import statistics
import subprocess
import sys
import time

out_dir = pathlib.Path(sys.argv[1])
head = sys.argv[2].split()
base = sys.argv[3].split() if len(sys.argv) > 3 and sys.argv[3] else None
repeats = int(sys.argv[4]) if len(sys.argv) > 4 else 3
cores = os.cpu_count() or 1

CASES = [
    ("particles poisson 8e6, N_H 60", ["particles", "cubic_bspline", "poisson", "--count", "8000000", "--nh", "60"], [1, cores]),
    ("particles poisson 4e6, N_H 60", ["particles", "cubic_bspline", "poisson", "--count", "4000000", "--nh", "60"], [2]),
    ("relax poisson 1e5, N_H 100, 20 steps",
     ["relax", "wendland_c2", "poisson", "--count", "100000", "--nh", "100", "--steps", "20"], [1, cores]),
]
LARGE = ("particles poisson 6.4e7, N_H 60", ["particles", "cubic_bspline", "poisson", "--count", "64000000", "--nh", "60"], [cores])


def run_once(command, args, threads):
    """Wall, CPU (user + system, every thread), peak resident MiB and the --json answer."""
    start = time.perf_counter()
    child = subprocess.Popen([*command, *args, "--threads", str(threads), "--json"], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL)
    output = child.stdout.read()
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        raise SystemExit(f"{' '.join(command + args)} --threads {threads}: exit status {status}")
    return {"wall": wall, "cpu": usage.ru_utime + usage.ru_stime, "peak_mib": usage.ru_maxrss / 1024,
            "answer": json.loads(output)}


def median(runs, key):
    return statistics.median(r[key] for r in runs)


def measure(cases, repeats):
    rows = []
    for name, args, thread_counts in cases:
        for threads in thread_counts:
            runs = {"head": [], "base": []}
            for _ in range(repeats):
                runs["head"].append(run_once(head, args, threads))
                if base:
                    runs["base"].append(run_once(base, args, threads))
            rows.append({"case": name, "threads": threads, "runs": runs})
            print(f"{name}, {threads} threads: {median(runs['head'], 'wall'):.3f} s", file=sys.stderr, flush=True)
    return rows


def sums_seconds(answer):
    # particles: the sums' own seconds; relax: none (its steps are all sums and moves)
    return answer.get("seconds")


def table(rows):
    lines = ["| case | threads | wall [s] | CPU [s] | peak [MiB] | sums [s] | sums / wall | base wall [s] | base peak [MiB] | base / head |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for row in rows:
        h = row["runs"]["head"]
        wall = median(h, "wall")
        sums = statistics.median(sums_seconds(r["answer"]) or 0 for r in h)
        b = row["runs"]["base"]
        base_cols = f"{median(b, 'wall'):.3f} | {median(b, 'peak_mib'):.0f} | {median(b, 'wall') / wall:.2f}" if b else "| |"
        lines.append(f"| {row['case']} | {row['threads']} | {wall:.3f} | {median(h, 'cpu'):.2f} | {median(h, 'peak_mib'):.0f} | "
                     f"{sums:.3f} | {sums / wall:.2f} | {base_cols} |")
    # Speed-up of every core over one, per build.
    for name in sorted({r["case"] for r in rows}):
        by_threads = {r["threads"]: r for r in rows if r["case"] == name}
        if 1 in by_threads and cores in by_threads and cores != 1:
            for build in ["head", "base"]:
                one, many = by_threads[1]["runs"][build], by_threads[cores]["runs"][build]
                if one and many:
                    lines.append(f"\n{name}, {build}: {cores} threads {median(one, 'wall') / median(many, 'wall'):.2f}x faster than 1")
    return "\n".join(lines)


def phases(rows):
    lines = []
    for row in rows:
        p = row["runs"]["head"][0]["answer"].get("phases")
        if p:
            lines.append(f"{row['case']}, {row['threads']} threads: " + ", ".join(f"{k} {v:.3f}" for k, v in p.items()))
    return "\n".join(lines)


rows = measure(CASES, repeats)
if os.environ.get("SPHKERN_LARGE"):
    rows += measure([LARGE], 1)
out_dir.mkdir(parents=True, exist_ok=True)
for row in rows:
    for runs in row["runs"].values():
        for r in runs:
            r["answer"] = {k: r["answer"].get(k) for k in ("seconds", "cpu_seconds", "pairs", "threads", "phases", "steps_taken")}
(out_dir / "thread_scaling.json").write_text(json.dumps({"cores": cores, "rows": rows}, indent=1))
report = f"{cores} cores\n\n{table(rows)}\n\nphases (this build, first run)\n{phases(rows)}\n"
(out_dir / "thread_scaling.md").write_text(report)
print(report)
