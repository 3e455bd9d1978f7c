"""`sphkern particles --code pysph` against PySPH itself: a fluid above a wall, written by
PySPH's own dump, with h varying by +-20%; PySPH's SPHEvaluator sums the same particles
with its WendlandQuintic kernel, its neighbour search and its pair h HIJ = (h_i + h_j) / 2.
Run by ctest with SPHKERN_CLI set; python3-pysph is installed by the setup's test step."""
import json
import os
import subprocess

import fluid_tanks
import numpy as np
from pysph.base.kernels import WendlandQuintic
from pysph.base.utils import get_particle_array
from pysph.solver.utils import dump
from pysph.sph.basic_equations import SummationDensity
from pysph.sph.equation import Equation, Group
from pysph.tools.sph_evaluator import SPHEvaluator

CLI = os.environ["SPHKERN_CLI"]


class VolumeSums(Equation):
    """sum_j V_j W_ij and sum_j V_j grad_i W_ij at PySPH's pair h, V_j = m_j / rho_j."""

    def initialize(self, d_idx, d_s0, d_gx, d_gy):
        d_s0[d_idx] = 0.0
        d_gx[d_idx] = 0.0
        d_gy[d_idx] = 0.0

    def loop(self, d_idx, s_idx, s_vol, d_s0, d_gx, d_gy, WIJ, DWIJ):
        d_s0[d_idx] += s_vol[s_idx] * WIJ
        d_gx[d_idx] += s_vol[s_idx] * DWIJ[0]
        d_gy[d_idx] += s_vol[s_idx] * DWIJ[1]


def tank():
    """A fluid over a wall, h varying by +-20% in both (PySPH keeps z, zero, itself)."""
    return fluid_tanks.wall_and_fluid(35, 16, 0.15, 0.2, h_wall_spread=0.2, mass_spread=0.05, with_z=False)


def pysph_sums(fluid, solid):
    """PySPH's summation density of the fluid, and the volume sums of the test's equation."""
    arrays = [get_particle_array(name=name, **props) for name, props in (("fluid", fluid), ("solid", solid))]
    for pa in arrays:
        for prop in ("s0", "gx", "gy", "vol"):
            pa.add_property(prop)
        pa.vol[:] = pa.m / pa.rho
    equations = [Group(equations=[VolumeSums(dest="fluid", sources=["fluid", "solid"]),
                                  SummationDensity(dest="fluid", sources=["fluid", "solid"])])]
    SPHEvaluator(arrays, equations, dim=2, kernel=WendlandQuintic(dim=2)).evaluate()
    return arrays[0]


def sphkern(path, *args):
    out = path.parent / (path.stem + "-sphkern.csv")
    done = subprocess.run([CLI, "particles", "wendland_c2", str(path), "--array", "fluid,solid", "--csv", str(out),
                           "--json", *args], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout), np.genfromtxt(out, delimiter=",", names=True)


def test_the_pysph_profile_gives_pysphs_own_sums(tmp_path):
    fluid, solid = tank()
    dump(str(tmp_path / "tank.hdf5"), [get_particle_array(name=n, **p) for n, p in (("fluid", fluid), ("solid", solid))],
         {"dt": 1e-4, "t": 0.0, "count": 0})
    doc, rows = sphkern(tmp_path / "tank.hdf5", "--code", "pysph")
    assert doc["code"] == {"name": "pysph", "parameter": "hdx", "h_from": "file", "support_per_h": 2.0, "pair_h": "mean"}
    peer = pysph_sums(fluid, solid)
    assert np.array_equal(rows["x"], fluid["x"]) and np.array_equal(rows["h"], fluid["h"])
    # The stored h is PySPH's and the support 2 h is sphkern's R h for Wendland C2: the same h.
    assert np.max(np.abs(rows["e0"] - (peer.s0 - 1))) < 1e-12
    assert np.max(np.abs((rows["eps_rho"] + 1) * doc["rho0"] - peer.rho) / peer.rho) < 1e-12
    # e1 = h_i sum_j V_j grad_i W_ij, in units of the particle's own h.
    assert np.max(np.abs(rows["e1_x"] - fluid["h"] * peer.gx)) < 1e-12
    assert np.max(np.abs(rows["e1_y"] - fluid["h"] * peer.gy)) < 1e-12
    # The neighbours are those inside the pair's support 2 HIJ.
    xs, ys = np.concatenate([fluid["x"], solid["x"]]), np.concatenate([fluid["y"], solid["y"]])
    hs = np.concatenate([fluid["h"], solid["h"]])
    for i in range(len(fluid["x"])):
        r = np.hypot(xs - fluid["x"][i], ys - fluid["y"][i])
        assert rows["neighbours"][i] == np.sum((r > 0) & (r < (fluid["h"][i] + hs)))
    # Each particle's own h in every pair (the gather form) differs from PySPH by far more.
    own, own_rows = sphkern(tmp_path / "tank.hdf5", "--support-per-h", "2")
    assert "code" not in own
    assert np.sqrt(np.mean((own_rows["e0"] - rows["e0"]) ** 2)) > 0.01


def test_a_code_alone_needs_a_stored_h(tmp_path):
    fluid, _ = tank()
    with open(tmp_path / "no-h.csv", "w") as f:
        f.write("x,y\n" + "".join(f"{x},{y}\n" for x, y in zip(fluid["x"], fluid["y"])))
    done = subprocess.run([CLI, "particles", "wendland_c2", str(tmp_path / "no-h.csv"), "--code", "pysph"],
                          capture_output=True, text=True)
    assert done.returncode == 3 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "the set stores no h; with --code pysph, expected --hdx too" in done.stderr
