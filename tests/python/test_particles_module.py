"""sphkern.particles against the command line: the same statistics and the same per-particle
values (written by `sphkern particles --csv`) for the same positions, h and volumes; arrays
of the right shapes; bad input as ValueError naming the argument as Python names it."""
import json
import os
import re
import subprocess

import numpy as np
import pytest

import sphkern

CLI = os.environ["SPHKERN_CLI"]


def test_the_module_equals_the_command_line(tmp_path):
    rng = np.random.default_rng(7)
    x = rng.uniform(0, 1, (3000, 3))
    h = 0.08 * rng.uniform(0.9, 1.1, len(x))
    with open(tmp_path / "set.csv", "w") as f:
        f.write("x,y,z,h\n")
        for p, hh in zip(x, h):
            f.write(f"{p[0]!r},{p[1]!r},{p[2]!r},{hh!r}\n")
    # The CSV's h is sphkern's: its support is R h, R = 2 for Wendland C2.
    args = [CLI, "particles", "wendland_c2", str(tmp_path / "set.csv"), "--support-per-h", "2", "--box", "1,1,1"]
    doc = json.loads(subprocess.run(args + ["--json"], check=True, capture_output=True, text=True).stdout)
    subprocess.run(args + ["--csv", str(tmp_path / "out.csv")], check=True, capture_output=True)
    rows = np.genfromtxt(tmp_path / "out.csv", delimiter=",", names=True)

    r = sphkern.particles("wendland_c2", x, box=[1, 1, 1], h=h)
    for key in doc["statistics"]:
        for stat, value in doc["statistics"][key].items():
            assert r["statistics"][key][stat] == pytest.approx(value, rel=1e-13, abs=1e-15), (key, stat)
    assert np.array_equal(r["e0"], rows["e0"])
    assert np.array_equal(r["eps_gradp"], rows["eps_gradp"])
    assert np.array_equal(r["e1"][:, 2], rows["e1_z"])
    assert np.array_equal(r["neighbours"], rows["neighbours"].astype(int))
    assert r["E"].shape == (3000, 3, 3) and np.allclose(r["E"], r["E"].transpose(0, 2, 1))
    # eps_gradp is g.E.g with g = -z.
    assert np.allclose(r["eps_gradp"], r["E"][:, 2, 2], rtol=0, atol=1e-15)


def test_volumes_and_h_as_arrays_and_2d():
    rng = np.random.default_rng(3)
    x = rng.uniform(0, 2, (2000, 2))
    r = sphkern.particles("cubic_bspline", x, box=[2, 2], nh=40, volume="voronoi")
    assert r["volume"].sum() == pytest.approx(4.0, rel=1e-10)
    assert r["e1"].shape == (2000, 2) and r["E"].shape == (2000, 2, 2)
    same = sphkern.particles("cubic_bspline", x, box=[2, 2], h=r["h"][0], volume=r["volume"])
    assert np.array_equal(same["e0"], r["e0"])


@pytest.mark.parametrize("kwargs, message", [
    ({"positions": np.zeros((4, 1))}, "positions: expected an array of shape (N, 2) or (N, 3)"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "volume": "uniform"},
     "uniform volumes need a periodic box"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h": 0.1, "eta": 1.2},
     "give one of h, eta and nh"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h": -1.0},
     "the smoothing length of particle 0 is -1"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "volume": np.ones(3)},
     "volume: expected a number or an array of 50 numbers"),
    ({"positions": np.array([[0.1, 0.2], [0.1, 0.2], [0.5, 0.5]]), "box": [1, 1], "h": 0.1},
     "particles 0 and 1 are at the same position"),
    ({"positions": np.zeros((4, 2)) + 1j}, "positions: complex numbers; expected real numbers"),
    # Each value is named as Python names it (the command line's text says --eta 0).
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "eta": 0},
     "eta = 0: expected a number in (0, 100]"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "nh": 0.5},
     "nh = 0.5: expected a number in [1, 100000]"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "gravity": [0, 0]},
     "gravity: expected a direction: finite components, not all zero"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "gravity": [0, 0, 1]},
     "gravity: 3 components, expected 2 (one per dimension)"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "depth": -1.0},
     "depth = -1: expected a number in [0, 1000000] (units of h)"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "threads": 5000},
     "threads = 5000, expected 0 to 1024"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "volume": "cells"},
     "volume: expected \"uniform\", \"voronoi\" or an array"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h": 0.1 + 0.5j},
     "h: complex numbers; expected real numbers"),
])
def test_bad_input_raises_value_error(kwargs, message):
    assert "--" not in message  # Python's errors name its arguments, never an option
    with pytest.raises(ValueError, match=re.escape(message)):
        sphkern.particles("cubic_bspline", **kwargs)


def test_complex_k_is_refused():
    with pytest.raises(ValueError, match="k: complex numbers; expected real numbers"):
        sphkern.eps("cubic_bspline", "fcc", 1.2 + 0.1j)
