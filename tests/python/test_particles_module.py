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
    assert r["volume"].sum() == pytest.approx(4.0, rel=1e-10) and r["volume_model"] == "voronoi"
    assert r["e1"].shape == (2000, 2) and r["E"].shape == (2000, 2, 2)
    same = sphkern.particles("cubic_bspline", x, box=[2, 2], h=r["h"][0], volume=r["volume"])
    assert np.array_equal(same["e0"], r["e0"])


def cubic_bspline_2d(q):
    """The cubic B-spline in 2D, h^2 W(q) (support 2h), written out independently of the plugin."""
    return 10 / (7 * np.pi) * np.where(q < 1, 1 - 1.5 * q**2 + 0.75 * q**3, np.where(q < 2, 0.25 * (2 - q) ** 3, 0))


def brute_force_sums(x, h, weights, box):
    """sum_j weights_j W_ij over every j (the self term included), W with particle i's own h,
    by the minimum image in a periodic box with a corner at the origin."""
    d = x[None, :, :] - x[:, None, :]
    d -= box * np.round(d / box)
    q = np.linalg.norm(d, axis=2) / h[:, None]
    return (cubic_bspline_2d(q) / h[:, None] ** 2 * weights[None, :]).sum(axis=1)


def mass_set():
    rng = np.random.default_rng(11)
    n, box = 300, np.array([1.0, 0.8])
    x = rng.uniform(0, 1, (n, 2)) * box
    h = 0.06 * rng.uniform(0.9, 1.1, n)  # sphkern's h: the support is 2 h
    m = 0.8 / n * rng.uniform(0.8, 1.2, n)
    rho = rng.uniform(0.9, 1.1, n)
    return x, h, m, rho, box


def test_eps_rho_with_masses_is_the_sum_over_the_masses():
    x, h, m, rho, box = mass_set()
    r = sphkern.particles("cubic_bspline", x, box=box, h=h, masses=m, densities=rho)
    volume = m / rho
    assert np.array_equal(r["volume"], volume)  # densities give the volumes m / rho
    rho0 = m.sum() / volume.sum()  # by default, the total mass over the total volume
    assert r["rho0"] == pytest.approx(rho0, rel=1e-14)
    sum_m = brute_force_sums(x, h, m, box)
    assert np.allclose(r["eps_rho"], sum_m / rho0 - 1, rtol=0, atol=1e-12)
    assert np.allclose(r["e0"], brute_force_sums(x, h, volume, box) - 1, rtol=0, atol=1e-12)
    assert np.abs(r["eps_rho"] - r["e0"]).max() > 1e-3  # with these masses, eps_rho is not e0
    # A reference density given, and volumes given instead of densities.
    given = sphkern.particles("cubic_bspline", x, box=box, h=h, masses=m, rho0=0.9, volume="voronoi")
    assert given["rho0"] == 0.9
    assert np.allclose(given["eps_rho"], sum_m / 0.9 - 1, rtol=0, atol=1e-12)
    # One mass for all: eps_rho is sum_j W_ij m / rho0 - 1.
    one = sphkern.particles("cubic_bspline", x, box=box, h=h, masses=0.002, rho0=1.0)
    assert np.allclose(one["eps_rho"], brute_force_sums(x, h, np.full(len(x), 0.002), box) - 1, rtol=0, atol=1e-12)
    # Without masses eps_rho is e0.
    assert np.array_equal(sphkern.particles("cubic_bspline", x, box=box, h=h)["eps_rho"],
                          sphkern.particles("cubic_bspline", x, box=box, h=h)["e0"])


def test_masses_densities_and_a_stored_h_equal_the_command_line(tmp_path):
    x, h, m, rho, box = mass_set()
    stored = 2 * h  # the support radius, as GADGET stores it: support_per_h = 1
    with open(tmp_path / "set.csv", "w") as f:
        f.write("x,y,h,m,rho\n")
        for p, hh, mm, r in zip(x, stored, m, rho):
            f.write(f"{p[0]!r},{p[1]!r},{hh!r},{mm!r},{r!r}\n")
    args = [CLI, "particles", "cubic_bspline", str(tmp_path / "set.csv"), "--support-per-h", "1", "--box", "1,0.8"]
    doc = json.loads(subprocess.run(args + ["--json"], check=True, capture_output=True, text=True).stdout)
    subprocess.run(args + ["--csv", str(tmp_path / "out.csv")], check=True, capture_output=True)
    rows = np.genfromtxt(tmp_path / "out.csv", delimiter=",", names=True)

    r = sphkern.particles("cubic_bspline", x, box=box, h=stored, support_per_h=1, masses=m, densities=rho)
    assert doc["volume"] == "file" and r["rho0"] == doc["rho0"]
    for key in doc["statistics"]:
        for stat, value in doc["statistics"][key].items():
            assert r["statistics"][key][stat] == pytest.approx(value, rel=1e-13, abs=1e-15), (key, stat)
    assert np.array_equal(r["eps_rho"], rows["eps_rho"]) and np.array_equal(r["e0"], rows["e0"])
    # The stored h is mapped to sphkern's: support_per_h times it is the support radius 2 h.
    assert np.array_equal(r["h"], h)
    own = sphkern.particles("cubic_bspline", x, box=box, h=h, masses=m, densities=rho)
    assert np.array_equal(own["eps_rho"], r["eps_rho"])
    swift = sphkern.particles("cubic_bspline", x, box=box, h=h / 0.9, support_per_h=1.8, masses=m, densities=rho)
    assert np.array_equal(swift["h"], 1.8 * (h / 0.9) / 2)


@pytest.mark.parametrize("kwargs, message", [
    ({"positions": np.zeros((4, 1))}, "positions: expected an array of shape (N, 2) or (N, 3)"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "volume": "uniform"},
     "uniform volumes need a periodic box"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h": 0.1, "h_over_l": 1.2},
     "give one of h, h_over_l and nh"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h": -1.0},
     "the smoothing length of particle 0 is -1"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "volume": np.ones(3)},
     "volume: expected a number or an array of 50 numbers"),
    ({"positions": np.array([[0.1, 0.2], [0.1, 0.2], [0.5, 0.5]]), "box": [1, 1], "h": 0.1},
     "particles 0 and 1 are at the same position"),
    ({"positions": np.zeros((4, 2)) + 1j}, "positions: complex numbers; expected real numbers"),
    # Each value is named as Python names it (the command line's text says --h-over-l 0).
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h_over_l": 0},
     "h_over_l = 0: expected a number in (0, 100]"),
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
     "volume: \"cells\" is unknown, expected \"uniform\", \"voronoi\" or an array"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h": 0.1 + 0.5j},
     "h: complex numbers; expected real numbers"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "masses": np.r_[1.0, -1.0, np.ones(48)]},
     "masses: the mass of particle 1 is -1, expected a positive finite number"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "masses": np.ones(3)},
     "masses: expected a number or an array of 50 numbers"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "masses": 1.0,
      "densities": np.r_[np.ones(49), np.nan]}, "densities: the density of particle 49 is nan, expected a positive"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "densities": 1.0},
     "densities: they give the volumes m / rho; expected masses too"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "masses": 1.0, "densities": 1.0,
      "volume": "voronoi"}, "give one of volume and densities"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "masses": 1.0, "rho0": 0},
     "rho0 = 0: expected a positive finite number"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "masses": 1 + 1j},
     "masses: complex numbers; expected real numbers"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h": 0.1, "support_per_h": 0},
     "support_per_h: maps a file's h (a positive finite number); it does not go with h_over_l, nh or k"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h": 0.1,
      "support_per_h": float("inf")}, "support_per_h: maps a file's h (a positive finite number)"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h_over_l": 1.2, "support_per_h": 2},
     "support_per_h: maps a file's h (a positive finite number); it does not go with h_over_l, nh or k"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "h": 0.1, "support_per_h": "two"},
     "support_per_h: expected a number"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "code": "swift"},
     "the set stores no h; with code swift, expected value too (the code's parameter)"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "value": 1.2},
     "value: is a code's parameter; expected code too"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "code": "swift", "value": 1.2,
      "h_over_l": 1.1}, "code: gives h for one setting; expected no h_over_l, nh, k or sweep beside it"),
    ({"positions": np.random.default_rng(1).uniform(0, 1, (50, 2)), "box": [1, 1], "code": "swift", "value": -1},
     "value = -1: expected a number in (0, 100]"),
])
def test_bad_input_raises_value_error(kwargs, message):
    assert "--" not in message  # Python's errors name its arguments, never an option
    with pytest.raises(ValueError, match=re.escape(message)):
        sphkern.particles("cubic_bspline", **kwargs)


def test_a_code_setting_equals_the_command_line(tmp_path):
    """code="swift" with its eta: the same h, particle by particle, as particles --code swift --eta on that file."""
    x = np.random.default_rng(3).uniform(0, 1, (1500, 3))
    path = tmp_path / "set.csv"
    np.savetxt(path, x, delimiter=",", header="x,y,z", comments="")
    r = sphkern.particles("wendland_c2", x, box=[1, 1, 1], code="swift", value=1.2348)
    run = subprocess.run([CLI, "particles", "wendland_c2", str(path), "--box", "1,1,1",
                          "--code", "swift", "--eta", "1.2348", "--json"], capture_output=True, text=True, check=True)
    cli = json.loads(run.stdout)
    assert r["code"] == cli["code"]
    assert abs(r["h_min"] - cli["h_min"]) <= 1e-15 * cli["h_min"] and abs(r["h_max"] - cli["h_max"]) <= 1e-15 * cli["h_max"]


def test_a_code_alone_takes_the_h_given_as_that_code_stores_it(tmp_path):
    """code="pysph" with h: PySPH's h (support R h) and its pair h, as particles --code pysph on that file."""
    rng = np.random.default_rng(4)
    x, h = rng.uniform(0, 1, (800, 2)), 0.06 * rng.uniform(0.8, 1.2, 800)
    path = tmp_path / "set.csv"
    np.savetxt(path, np.column_stack([x, h]), delimiter=",", header="x,y,h", comments="")
    r = sphkern.particles("wendland_c2", x, box=[1, 1], h=h, code="pysph")
    run = subprocess.run([CLI, "particles", "wendland_c2", str(path), "--box", "1,1", "--code", "pysph", "--json"],
                         capture_output=True, text=True, check=True)
    cli = json.loads(run.stdout)
    assert r["code"] == cli["code"] and cli["code"]["pair_h"] == "mean"
    assert r["e0"].mean() == pytest.approx(cli["statistics"]["e0"]["mean"], rel=1e-14, abs=1e-15)
    # The particle's own h in every pair is another answer.
    own = sphkern.particles("wendland_c2", x, box=[1, 1], h=h, support_per_h=2)
    assert np.max(np.abs(own["e0"] - r["e0"])) > 1e-3


def test_complex_k_is_refused():
    with pytest.raises(ValueError, match="k: complex numbers; expected real numbers"):
        sphkern.eps("cubic_bspline", "fcc", 1.2 + 0.1j)


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items()
                if k not in ("seconds", "cpu_seconds", "phases", "threads", "inputs", "provenance")}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


@pytest.mark.parametrize("args, kwargs", [(["--nh-range", "30", "90", "--steps", "2"], dict(nh_range=[30, 90], steps=2)),
                                          (["--h-over-l-range", "1.0", "1.4", "--steps", "3", "--histogram", "6"],
                                           dict(h_over_l_range=(1.0, 1.4), steps=3, histogram=6)),
                                          (["--nh", "40", "--histogram", "4"], dict(nh=40, histogram=4))])
def test_sweeps_and_histograms_as_the_command_line(tmp_path, args, kwargs):
    x = np.random.default_rng(4).uniform(0, 1, (1500, 3))
    np.savetxt(tmp_path / "set.csv", x, delimiter=",", header="x,y,z", comments="")
    cli = json.loads(subprocess.run([CLI, "particles", "cubic_bspline", str(tmp_path / "set.csv"), "--box", "1,1,1", *args,
                                     "--json"], capture_output=True, text=True, check=True).stdout)
    doc = sphkern.particles("cubic_bspline", tmp_path / "set.csv", box=[1, 1, 1], **kwargs)
    if "sweep" in cli:  # a sweep: the document alone, its points those of the command line
        assert without_timings(doc) == without_timings(cli) and len(cli["sweep"]) == kwargs["steps"] + 1
    else:
        assert without_timings(doc["histograms"]) == without_timings(cli["histograms"]) and doc["e0"].shape == (1500,)


def test_a_sweep_range_needs_two_numbers():
    with pytest.raises(sphkern.BadValue, match="nh_range: expected two numbers"):
        sphkern.particles("cubic_bspline", np.random.default_rng(1).uniform(0, 1, (200, 3)), box=[1, 1, 1], nh_range=[30])
