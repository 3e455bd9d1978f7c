#!/usr/bin/python3
"""Whole-process times of a command, alone or paired with another, run in turn (A B A B ...)
after a warm-up each, so that a shared machine's load falls on both alike. Each run is
accounted by the operating system (wait4: user and system CPU seconds, the peak resident
memory), its wall time by the clock; printed: each figure's minimum, median and maximum, and
with --vs the ratios A/B pair by pair. The commands run without a shell.

Usage: /usr/bin/python3 share/scripts/paired_runs.py [-n RUNS] [--warmup N] [--timeout S]
       [--vs 'COMMAND B'] -- COMMAND A ..."""
import argparse
import os
import shlex
import statistics
import subprocess
import sys
import time


def run_once(argv, deadline):
    start = time.perf_counter()
    process = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    while True:
        pid, status, usage = os.wait4(process.pid, os.WNOHANG)
        if pid:
            break
        if time.monotonic() > deadline:
            process.kill()
            raise TimeoutError(f"paired_runs: {shlex.join(argv)} ran past the time bound")
        time.sleep(0.002)
    wall = time.perf_counter() - start
    return {"user": usage.ru_utime, "sys": usage.ru_stime, "cpu": usage.ru_utime + usage.ru_stime, "wall": wall,
            "peak MiB": usage.ru_maxrss / 1024, "exit": os.waitstatus_to_exitcode(status)}


def spread(values):
    return f"{min(values):.4g} / {statistics.median(values):.4g} / {max(values):.4g}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-n", type=int, default=5, help="counted runs of each command")
    parser.add_argument("--warmup", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=100, help="a bound on the whole call, in seconds")
    parser.add_argument("--vs", help="command B, split as a shell splits words (no shell runs it)")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    a = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not a:
        parser.error("expected a command after --")
    commands = [a] + ([shlex.split(args.vs)] if args.vs else [])
    deadline = time.monotonic() + args.timeout
    for _ in range(args.warmup):
        for argv in commands:
            run_once(argv, deadline)
    runs = [[] for _ in commands]
    for _ in range(args.n):
        for k, argv in enumerate(commands):
            runs[k].append(run_once(argv, deadline))
    print(f"{os.cpu_count()} processors; {args.n} counted runs each, min / median / max")
    for name, k in zip("AB", range(len(commands))):
        print(f"{name}: {shlex.join(commands[k])} (exit codes {sorted({r['exit'] for r in runs[k]})})")
        for figure in ("user", "sys", "cpu", "wall", "peak MiB"):
            print(f"  {figure:9} {spread([r[figure] for r in runs[k]])}")
    if args.vs:
        print("A/B, pair by pair:")
        for figure in ("cpu", "wall", "peak MiB"):
            print(f"  {figure:9} {spread([x[figure] / y[figure] for x, y in zip(*runs) if y[figure] > 0])}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
