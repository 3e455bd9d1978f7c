#!/usr/bin/python3
"""eps over 10^6 values of k three ways, side by side in one run: the Python module (one
call), the command line (one process per k: measured on a sample, the 10^6 figure is
that per-call time times 10^6), and a plain numpy brute-force sum over explicit lattice
points (the same numbers, computed independently).

Usage: PYTHONPATH=build/python /usr/bin/python3 share/scripts/python_benchmark.py --sphkern build/sphkern
Prints JSON."""
import argparse
import json
import subprocess
import time

import numpy as np

import sphkern


def fcc_points(radius):
    """Every fcc lattice point within `radius` of the origin (nearest-neighbour distance 1),
    origin excluded: the conventional cube of side sqrt(2) with its four sites."""
    a = np.sqrt(2.0)
    n = int(np.ceil(radius / a)) + 1
    r = np.arange(-n, n + 1)
    cells = np.stack(np.meshgrid(r, r, r, indexing="ij"), axis=-1).reshape(-1, 3)
    motif = np.array([[0, 0, 0], [0, 0.5, 0.5], [0.5, 0, 0.5], [0.5, 0.5, 0]])
    points = (cells[:, None, :] + motif[None, :, :]).reshape(-1, 3) * a
    d = np.linalg.norm(points, axis=1)
    return points[(d > 1e-12) & (d <= radius * (1 + 1e-12))]


def cubic_spline(q):
    sigma = 3 / (2 * np.pi)
    return sigma * np.where(q <= 1, 2 / 3 - q**2 + 0.5 * q**3, np.where(q <= 2, (2 - q) ** 3 / 6, 0.0))


def numpy_eps_rho(ks, chunk=20000):
    """eps_rho = a_p sum_j W(r_j / k) / k^3 - 1 (self term included), brute force."""
    a_p = 1 / np.sqrt(2)
    r = np.linalg.norm(fcc_points(2 * ks.max()), axis=1)
    out = np.empty_like(ks)
    for start in range(0, len(ks), chunk):
        k = ks[start:start + chunk, None]
        out[start:start + chunk] = a_p * (cubic_spline(0.0) + cubic_spline(r[None, :] / k).sum(axis=1)) / k[:, 0] ** 3 - 1
    return out, len(r)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sphkern", default="build/sphkern")
    parser.add_argument("--cli-sample", type=int, default=200)
    args = parser.parse_args()
    ks = np.linspace(0.75, 1.25, 10**6)

    sphkern.eps("cubic_bspline", "fcc", 1.0)  # plugins loaded and probed once, as a notebook's first cell would
    start = time.perf_counter()
    module = sphkern.eps("cubic_bspline", "fcc", ks)
    module_seconds = time.perf_counter() - start

    start = time.perf_counter()
    brute, points = numpy_eps_rho(ks)
    numpy_seconds = time.perf_counter() - start

    sample = ks[:: len(ks) // args.cli_sample][: args.cli_sample]
    cli = []
    start = time.perf_counter()
    for k in sample:
        done = subprocess.run([args.sphkern, "eps", "cubic_bspline", "fcc", "--k", repr(float(k)), "--json"],
                              capture_output=True, text=True, check=True)
        cli.append(json.loads(done.stdout)["eps_rho"])
    cli_per_call = (time.perf_counter() - start) / len(sample)
    index = np.searchsorted(ks, sample)
    print(json.dumps({
        "k_values": len(ks),
        "module_seconds": module_seconds,
        "numpy_seconds": numpy_seconds,
        "numpy_lattice_points": points,
        "cli_sample": len(sample),
        "cli_seconds_per_call": cli_per_call,
        "cli_seconds_for_all": cli_per_call * len(ks),
        "max_difference_module_numpy": float(np.max(np.abs(module["eps_rho"] - brute))),
        "max_difference_module_cli": float(np.max(np.abs(module["eps_rho"][index] - np.array(cli)))),
    }, indent=2))


if __name__ == "__main__":
    main()
