#!/usr/bin/env python3
"""The disorder table of share/docs/guide-particles.md: RMS e0 and eps_gradp of the cubic
B-spline at h = 1.2 d on a periodic fcc block disturbed by Gaussian noise of growing sigma, and
on a Poisson set with the same neighbour number. Usage: share/scripts/disorder-table.py [build/sphkern]"""
import json
import subprocess
import sys

sphkern = sys.argv[1] if len(sys.argv) > 1 else "build/sphkern"


def stats(*args):
    out = subprocess.run([sphkern, "particles", "cubic_bspline", *args, "--json"], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def rounding(value):
    """A value at the level of the sums' rounding is shown as such: its digits are the machine's."""
    return "< 1e-12" if abs(value) < 1e-12 else f"{value:.2e}"


print("| set | N_H | mean e0 | RMS e0 | RMS eps_gradp | RMS eps_gradp_sum (depth h) | RMS abs(e1) |")
print("|---|---:|---:|---:|---:|---:|---:|")
nh = None
for sigma in (0, 0.01, 0.05, 0.1, 0.2):
    d = stats("fcc", "--size", "20,20,20", "--k", "1.2", "--sigma", str(sigma), "--seed", "7")
    nh = d["nh"]
    s = d["statistics"]
    print(f"| fcc, sigma = {sigma} d | {d['nh']:.1f} | {s['e0']['mean']:.2e} | {s['e0']['rms']:.2e} | "
          f"{s['eps_gradp']['rms']:.2e} | {s['eps_gradp_sum']['rms']:.2e} | {rounding(s['|e1|']['rms'])} |")
d = stats("poisson", "--count", "8000", "--nh", f"{nh}", "--seed", "7")
s = d["statistics"]
print(f"| Poisson, 8000 particles | {d['nh']:.1f} | {s['e0']['mean']:.2e} | {s['e0']['rms']:.2e} | "
      f"{s['eps_gradp']['rms']:.2e} | {s['eps_gradp_sum']['rms']:.2e} | {rounding(s['|e1|']['rms'])} |")
