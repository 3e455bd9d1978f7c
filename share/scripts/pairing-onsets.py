#!/usr/bin/env python3
"""Onsets of instability and of pairing against N_H on fcc, fixed and adaptive h side by side.
For each kernel and h model: `sphkern stability KERNEL fcc --kmin A --kmax B --steps N
--h-model M --json` over the k whose N_H (Dehnen & Aly: N_H = 4 pi/3 (R h)^3 n, n the number
density) runs from 20 to 600. Reported: the first k that is not stable (and the kind of its
fastest mode) and the first k whose fastest growing mode is longitudinal (pairing), as N_H;
each is the bisected edge of the stable interval below it where one exists, else the sample.
Usage: python3 share/scripts/pairing-onsets.py [build/sphkern] [steps] > table.md"""
import json
import math
import subprocess
import sys

sphkern = sys.argv[1] if len(sys.argv) > 1 else "build/sphkern"
steps = sys.argv[2] if len(sys.argv) > 2 else "120"
kernels = ["cubic_bspline", "quartic_bspline", "morris_quintic", "wendland_c2", "wendland_c4", "wendland_c6"]
nh_range = (20.0, 600.0)
volume = 1 / math.sqrt(2)  # fcc, nearest neighbours at d = 1: the volume per particle in d^3
support = {k["name"]: k["support"] for k in json.loads(
    subprocess.run([sphkern, "kernels", "--json"], check=True, capture_output=True, text=True).stdout)}


def nh(k, R):
    return 4 * math.pi / 3 * (R * k) ** 3 / volume


def k_of(n, R):
    return (n * volume * 3 / (4 * math.pi)) ** (1 / 3) / R


def onsets(kernel, model):
    R = support[kernel]
    args = [sphkern, "stability", kernel, "fcc", "--kmin", f"{k_of(nh_range[0], R):.6f}", "--kmax",
            f"{k_of(nh_range[1], R):.6f}", "--steps", steps, "--h-model", model, "--threads", "2", "--json"]
    d = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    samples = sorted(d["samples"] + d["between"], key=lambda s: s["k"])
    edges = [i[1] for i in d["stable_intervals"]]

    def onset(test):
        first = next((s for s in samples if test(s)), None)
        if first is None:
            return None, None
        below = [e for e in edges if e <= first["k"]]
        k = below[-1] if below else first["k"]
        return nh(k, R), first

    grows = lambda s: s["verdict"] != "stable"
    pairs = lambda s: grows(s) and s.get("mode", {}).get("kind") == "longitudinal"
    (n_any, s_any), (n_pair, _) = onset(grows), onset(pairs)
    kind = s_any["mode"]["kind"] if s_any and "mode" in s_any else "long waves"
    return n_any, kind, n_pair


def cell(n):
    return f"{n:.1f}" if n is not None else f"none up to {nh_range[1]:g}"


print("| kernel | R | fixed h: first instability (N_H, kind) | fixed h: pairing from N_H | "
      "adaptive h: first instability (N_H, kind) | adaptive h: pairing from N_H |")
print("|---|---|---|---|---|---|")
for kernel in kernels:
    row = [kernel, f"{support[kernel]:g}"]
    for model in ("fixed", "adaptive"):
        n_any, kind, n_pair = onsets(kernel, model)
        row += [f"{cell(n_any)}" + (f" ({kind})" if n_any is not None else ""), cell(n_pair)]
    print("| " + " | ".join(row) + " |")
