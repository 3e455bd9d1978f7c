"""SWIFT counts neighbours by number by default and by mass with SPH:use_mass_weighted_num_ngb
(runner_ghost.c, runner_do_ghost: wcount = rho / m_i, then h^D wcount = eta^D): `particles
--code swift --neighbours-by mass` solves h_i^3 sum_j (m_j / m_i) W(r_ij, h_i) = eta^3, the
default h_i^3 sum_j W(r_ij, h_i) = eta^3. Both checked against a bisection of each rule here,
with SWIFT's 3D Wendland C2 written out (kernel_hydro.h: w(q) = 21/(2 pi) (1 - q)^4 (1 + 4q),
H = gamma h, gamma = sqrt(15/4), which SWIFT writes to 7 digits). A code without the switch refuses the other count (exit 2).
Run by ctest with SPHKERN_CLI set."""
import csv
import json
import os
import subprocess

import numpy as np
import pytest

h5py = pytest.importorskip("h5py")

CLI = os.environ["SPHKERN_CLI"]
N, ETA, GAMMA = 300, 1.2348, (15 / 4) ** 0.5  # kernel_hydro.h rounds it to 1.936492


def points():
    rng = np.random.default_rng(5)
    return rng.uniform(0, 1, (N, 3)), np.where(rng.uniform(size=N) < 0.3, 4.0, 1.0)


def w(r, h):
    q = np.minimum(r / (GAMMA * h), 1.0)
    return 21 / (2 * np.pi) * (1 - q) ** 4 * (1 + 4 * q) / (GAMMA * h) ** 3


def solve(x, m, by_mass):
    hs = []
    for i in range(N):
        d = x - x[i]
        d -= np.round(d)  # the unit periodic box
        r = np.sqrt((d * d).sum(1))
        weight = m / m[i] if by_mass else np.ones(N)
        lo, hi = 1e-3, 0.4
        for _ in range(100):
            h = 0.5 * (lo + hi)
            lo, hi = (h, hi) if h**3 * np.sum(weight * w(r, h)) < ETA**3 else (lo, h)
        hs.append(0.5 * (lo + hi))
    return np.array(hs)


def sphkern_h(tmp_path, *args):
    x, m = points()
    with h5py.File(tmp_path / "set.hdf5", "w") as f:
        header = f.create_group("Header")
        header.attrs["BoxSize"] = [1.0, 1.0, 1.0]
        header.attrs["NumPart_Total"] = [N, 0, 0, 0, 0, 0]
        part = f.create_group("PartType0")
        part["Coordinates"] = x
        part["Masses"] = m
    done = subprocess.run([CLI, "particles", "wendland_c2", str(tmp_path / "set.hdf5"), "--code", "swift", "--eta", str(ETA),
                           *args, "--csv", str(tmp_path / "h.csv"), "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    support = json.loads(done.stdout)["support"]
    with open(tmp_path / "h.csv") as f:
        rows = list(csv.DictReader(f))
    # sphkern's h has the support R h; SWIFT's H = gamma h_swift is the same radius.
    return np.array([float(r["h"]) for r in rows]) * support / GAMMA, json.loads(done.stdout)["code"]


@pytest.mark.parametrize("by_mass", [False, True])
def test_swift_h_by_its_count(tmp_path, by_mass):
    x, m = points()
    got, code = sphkern_h(tmp_path, *(["--neighbours-by", "mass"] if by_mass else []))
    assert code["counts"] == ("mass" if by_mass else "number")
    want = solve(x, m, by_mass)
    assert np.max(np.abs(got / want - 1)) < 1e-9
    # The other rule is another h for the heavy and light particles near each other.
    assert np.max(np.abs(solve(x, m, not by_mass) / want - 1)) > 0.05


def test_a_code_without_the_switch_refuses_the_other_count(tmp_path):
    x, m = points()
    sphkern_h(tmp_path)  # writes set.hdf5
    done = subprocess.run([CLI, "particles", "cubic_bspline", str(tmp_path / "set.hdf5"), "--code", "gadget2", "--nngb", "48",
                           "--neighbours-by", "mass"], capture_output=True, text=True)
    assert done.returncode == 2 and "GADGET-2 counts neighbours by number only" in done.stderr, done.stderr
    done = subprocess.run([CLI, "particles", "cubic_bspline", str(tmp_path / "set.hdf5"), "--h-over-l", "1.2",
                           "--neighbours-by", "mass"], capture_output=True, text=True)
    assert done.returncode == 2 and "--neighbours-by chooses what a code's density solve counts" in done.stderr


def test_python_counts_as_the_command_line(tmp_path):
    import sphkern
    x, m = points()
    got, _ = sphkern_h(tmp_path, "--neighbours-by", "mass")
    doc = sphkern.particles("wendland_c2", x, box=[1, 1, 1], masses=m, code="swift", value=ETA, neighbours_by="mass")
    assert doc["code"]["counts"] == "mass"
    assert np.array_equal(doc["h"] * doc["support"] / GAMMA, got)
