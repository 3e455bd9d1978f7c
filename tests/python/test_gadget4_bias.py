"""GADGET-4's WENDLAND_BIAS_CORRECTION (Dehnen & Aly 2012, eqs. 18-19), as its source does it:
src/sph/kernel.h, get_density_bias, gives eps100 (DesNumNgb / 100)^(-alpha) m W(0, H) with
eps100 and alpha per kernel (get_bias_correction_parameters: C2 0.0294 and 0.977, C4 0.01342 and
1.579, C6 0.0116 and 2.236); src/sph/density.cc subtracts it from Density after each density
pass, before NumNgb = NORM_COEFF H^3 Density / Mass is compared with DesNumNgb. So H_i solves
(4 pi / 3) H^3 (sum_j m_j W(r_ij, H) - bias_i) / m_i = DesNumNgb, checked here against a
bisection of that equation with kernel.h's 3D Wendland C2 and C4 written out (u = r / H,
NORM 21 / (2 pi) and 495 / (32 pi)). kernel.h stops the build for another kernel or 1D/2D, and
DesNumNgb is an int (src/data/allvars.h): those are refused (exit 2). Run by ctest with SPHKERN_CLI set."""
import csv
import json
import os
import subprocess

import numpy as np
import pytest

h5py = pytest.importorskip("h5py")

CLI = os.environ["SPHKERN_CLI"]
N, NNGB = 1000, 40
KERNELS = {  # kernel.h, 2D/3D branch: w(u), NORM; and get_bias_correction_parameters
    "wendland_c2": (lambda u: (1 - u) ** 4 * (1 + 4 * u), 21 / (2 * np.pi), 0.0294, 0.977),
    "wendland_c4": (lambda u: (1 - u) ** 6 * (1 + 6 * u + 35 / 3 * u * u), 495 / (32 * np.pi), 0.01342, 1.579),
}


def points():
    rng = np.random.default_rng(11)
    return rng.uniform(0, 1, (N, 3)), np.where(rng.uniform(size=N) < 0.3, 4.0, 1.0)


def gadget4_H(kernel, x, m, bias):
    """Every particle's H by bisection of its own equation, all particles at once."""
    shape, norm, eps100, alpha = KERNELS[kernel]
    W = lambda r, H: norm * shape(np.minimum(r / H, 1.0)) / H**3  # noqa: E731
    f = eps100 * (NNGB / 100) ** -alpha if bias else 0.0
    d = x[None, :, :] - x[:, None, :]
    d -= np.round(d)  # the unit periodic box
    r = np.sqrt((d * d).sum(2))
    lo, hi = np.full(N, 1e-3), np.full(N, 0.45)
    for _ in range(60):
        H = 0.5 * (lo + hi)
        rho = (m[None, :] * W(r, H[:, None])).sum(1) - f * m * W(0.0, H)
        below = 4 * np.pi / 3 * H**3 * rho / m < NNGB
        lo, hi = np.where(below, H, lo), np.where(below, hi, H)
    return 0.5 * (lo + hi)


def write_set(tmp_path):
    x, m = points()
    with h5py.File(tmp_path / "set.hdf5", "w") as f:
        f.create_group("Header").attrs["BoxSize"] = [1.0, 1.0, 1.0]
        part = f.create_group("PartType0")
        part["Coordinates"] = x
        part["Masses"] = m
    return tmp_path / "set.hdf5"


def sphkern_H(tmp_path, kernel, *args):
    done = subprocess.run([CLI, "particles", kernel, str(write_set(tmp_path)), "--code", "gadget4", "--nngb", str(NNGB),
                           *args, "--csv", str(tmp_path / "h.csv"), "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    doc = json.loads(done.stdout)
    with open(tmp_path / "h.csv") as f:
        return np.array([float(r["h"]) for r in csv.DictReader(f)]) * doc["support"], doc["code"]


@pytest.mark.parametrize("kernel", KERNELS)
def test_the_support_radius_as_gadget4_solves_it_with_the_correction(tmp_path, kernel):
    x, m = points()
    got, code = sphkern_H(tmp_path, kernel, "--bias-correction")
    assert code["bias_correction"] == "WENDLAND_BIAS_CORRECTION"
    want = gadget4_H(kernel, x, m, True)
    assert np.max(np.abs(got / want - 1)) < 1e-9
    # Without it, the other H (the correction lowers each density, so H grows): told apart.
    plain, code = sphkern_H(tmp_path, kernel)
    assert "bias_correction" not in code
    assert np.max(np.abs(plain / gadget4_H(kernel, x, m, False) - 1)) < 1e-9
    assert np.min(got / plain) > 1 and np.max(got / plain - 1) > 1e-3


@pytest.mark.parametrize("args, message", [
    (["particles", "cubic_bspline", "SET", "--code", "gadget4", "--nngb", "40", "--bias-correction"],
     "WENDLAND_BIAS_CORRECTION is for its Wendland C2, C4 and C6 kernels in 3D only (src/sph/kernel.h), not cubic_bspline"),
    (["particles", "wendland_c2", "SET", "--code", "gadget4", "--nngb", "40.5", "--bias-correction"],
     "--nngb: 40.5: GADGET-4's DesNumNgb is an integer"),
    (["particles", "wendland_c2", "SET", "--code", "swift", "--eta", "1.2", "--bias-correction"],
     "--code: swift: SWIFT subtracts no bias from the density; expected a code that does: gadget4 (WENDLAND_BIAS_CORRECTION)"),
    (["particles", "wendland_c2", "SET", "--h-over-l", "1.2", "--bias-correction"],
     "--bias-correction is the code's correction of its density solve; expected --code with its parameter"),
    (["particles", "wendland_c2", "poisson", "--dim", "2", "--count", "200", "--code", "gadget4", "--nngb", "30",
      "--bias-correction"], "in 3D only (src/sph/kernel.h), not wendland_c2 in 2D"),
])
def test_what_gadget4_cannot_build_is_refused(tmp_path, args, message):
    args = [str(write_set(tmp_path)) if a == "SET" else a for a in args]
    done = subprocess.run([CLI, *args], capture_output=True, text=True)
    assert done.returncode == 2 and message in done.stderr and len(done.stderr.strip().splitlines()) == 1, done.stderr


def test_python_corrects_as_the_command_line(tmp_path):
    import sphkern
    x, m = points()
    got, _ = sphkern_H(tmp_path, "wendland_c2", "--bias-correction")
    doc = sphkern.particles("wendland_c2", x, box=[1, 1, 1], masses=m, code="gadget4", value=NNGB, bias_correction=True)
    assert doc["code"]["bias_correction"] == "WENDLAND_BIAS_CORRECTION"
    assert np.array_equal(doc["h"] * doc["support"], got)
