#!/usr/bin/env python3
"""A SWIFT snapshot of N Poisson particles in a periodic unit box, for the slab benchmarks
(BENCHMARKS.md, "Sets larger than memory: slabs"): h = 1.2348 l varying by +-10% (l the mean
spacing), one mass in the MassTable, SWIFT's kernel gamma of Wendland C2. Written ten million
rows at a time, so that a file larger than memory can be made.
Usage: big_snapshot.py FILE N"""
import sys

import h5py
import numpy as np

path, n = sys.argv[1], int(float(sys.argv[2]))
rng = np.random.default_rng(11)
spacing = (1.0 / n) ** (1 / 3)
with h5py.File(path, "w") as f:
    header = f.create_group("Header")
    header.attrs["BoxSize"] = [1.0, 1.0, 1.0]
    header.attrs["Dimension"] = 3
    header.attrs["NumPart_Total"] = np.array([n % 2**32, 0, 0, 0, 0, 0], dtype=np.uint32)
    header.attrs["NumPart_Total_HighWord"] = np.array([n >> 32, 0, 0, 0, 0, 0], dtype=np.uint32)
    header.attrs["NumPart_ThisFile"] = np.array([n, 0, 0, 0, 0, 0], dtype=np.uint64)
    header.attrs["MassTable"] = [1.0 / n, 0, 0, 0, 0, 0]
    f.create_group("HydroScheme").attrs["Kernel gamma"] = 1.936492
    part = f.create_group("PartType0")
    coordinates = part.create_dataset("Coordinates", (n, 3), dtype="f8")
    h = part.create_dataset("SmoothingLengths", (n,), dtype="f8")
    step = 10**7
    for a in range(0, n, step):
        b = min(n, a + step)
        coordinates[a:b] = rng.random((b - a, 3))
        h[a:b] = 1.2348 * spacing * rng.uniform(0.9, 1.1, b - a)
