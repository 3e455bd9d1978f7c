#!/usr/bin/env python3
"""Onsets of pairing against N_H on fcc, fixed and adaptive h side by side (README, "Adaptive h").
N_H = 4 pi/3 (R h)^3 n (Dehnen & Aly 2012), n the number density. Pairing: the longitudinal
mode (|kappa^ . xi|^2 > 1/2) has omega^2 < -1e-9 somewhere on the lines from Γ to the zone
boundary along the high-symmetry directions (Γ-X, Γ-W, Γ-L, Γ-K; 25 wave vectors each, where
a one-site lattice's modes are longitudinal or transverse by symmetry). The onset is the
first of 25 N_H from 20 to 600 (geometric) with pairing, bisected to 1e-4 in k against the
sample before it. Also the N_H where no mode at all grows faster than 100 d/c, from
`sphkern stability KERNEL fcc --kmin A --kmax B --steps 40 --h-model M --json`.
Usage: PYTHONPATH=build/python python3 share/scripts/pairing-onsets.py [build/sphkern [KERNEL]] > table.md
(with KERNEL, that kernel's row only: the documentation's test runs one kernel at a time)."""
import json
import math
import subprocess
import sys

import numpy as np
import sphkern

cli = sys.argv[1] if len(sys.argv) > 1 else "build/sphkern"
kernels = ["cubic_bspline", "quartic_bspline", "morris_quintic", "wendland_c2", "wendland_c4", "wendland_c6"]
kernels = sys.argv[2:3] or kernels
nh_min, nh_max = 20.0, 600.0
volume = 1 / math.sqrt(2)  # fcc with nearest neighbours at d = 1: the volume per particle in d^3
support = {k["name"]: k["support"] for k in sphkern.kernels()}


def nh(k, R):
    return 4 * math.pi / 3 * (R * k) ** 3 / volume


def k_of(n, R):
    return (n * volume * 3 / (4 * math.pi)) ** (1 / 3) / R


def symmetry_lines(kernel):
    """The wave vectors on each line from Γ to the zone boundary along the symmetry directions."""
    d = sphkern.stability(kernel, "fcc", 1.0, grid=2)
    b = np.array(d["reciprocal_vectors"]).T
    G = [g for g in (b @ (np.array(n) - 2) for n in np.ndindex(5, 5, 5)) if np.linalg.norm(g) > 0]
    lines = []
    for s in d["sound_speed"]:
        u = np.array(s["unit_vector"])
        edge = min(g @ g / (2 * (u @ g)) for g in G if u @ g > 1e-9)
        lines += [t * edge * u for t in np.linspace(0.04, 1, 25)]
    return lines


def pairs(kernel, k, model, lines):
    for kappa in lines:
        modes = sphkern.stability(kernel, "fcc", k, wavevector=list(kappa), h_model=model)["modes"]
        if any(m["longitudinal"] > 0.5 and m["omega2"] < -1e-9 for m in modes):
            return True
    return False


def onset(kernel, model, lines):
    R = support[kernel]
    ks = [k_of(n, R) for n in np.geomspace(nh_min, nh_max, 25)]
    before = None
    for k in ks:
        if pairs(kernel, k, model, lines):
            if before is None:
                return f"below {nh_min:g}"
            lo, hi = before, k
            while hi - lo > 1e-4:
                mid = 0.5 * (lo + hi)
                lo, hi = (lo, mid) if pairs(kernel, mid, model, lines) else (mid, hi)
            return f"{nh(hi, R):.1f}"
        before = k
    return f"none up to {nh_max:g}"


def stable_nh(kernel, model):
    R = support[kernel]
    args = [cli, "stability", kernel, "fcc", "--kmin", f"{k_of(nh_min, R):.6f}", "--kmax", f"{k_of(nh_max, R):.6f}",
            "--steps", "40", "--h-model", model, "--threads", "2", "--json"]
    d = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    spans = [f"[{nh(a, R):.0f}, {nh(b, R):.0f}]" for a, b in d["stable_at_horizon"]]
    return " ".join(spans) if spans else "none"


print("| kernel | R | pairing from N_H, fixed h | pairing from N_H, adaptive h | "
      "no mode faster than 100 d/c, fixed h (N_H) | the same, adaptive h (N_H) |")
print("|---|---|---|---|---|---|")
for kernel in kernels:
    lines = symmetry_lines(kernel)
    row = [kernel, f"{support[kernel]:g}", onset(kernel, "fixed", lines), onset(kernel, "adaptive", lines),
           stable_nh(kernel, "fixed"), stable_nh(kernel, "adaptive")]
    print("| " + " | ".join(row) + " |")
