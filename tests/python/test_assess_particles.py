"""`assess` on a particle file judges each particle against its own density and tells the
interior from the free surface: lambda_min, the smallest eigenvalue of the first-order
correction matrix L_i = sum_j V_j r_ij (x) grad_i W_ij (Marrone et al. 2010), above 0.75 is
interior. Checked against L, e0 and eps_gradp summed here by brute force with the 2D cubic
spline written out (PySPH's CubicSpline, support 2h), and percentiles as numpy takes them
(linear between order statistics). Run by ctest with SPHKERN_CLI set."""
import json
import os
import subprocess

import numpy as np
import pytest

CLI = os.environ["SPHKERN_CLI"]
H = 1.2  # the stored h, spacing 1


def cubic(r, h):
    """PySPH's 2D CubicSpline: W and dW/dr."""
    q, s = r / h, 10 / (7 * np.pi * h * h)
    w = np.where(q < 1, 1 - 1.5 * q**2 + 0.75 * q**3, np.where(q < 2, 0.25 * (2 - q) ** 3, 0))
    dw = np.where(q < 1, -3 * q + 2.25 * q**2, np.where(q < 2, -0.75 * (2 - q) ** 2, 0))
    return s * w, s * dw / h


def brute(x, volume):
    """e0, eps_gradp (gravity -y) and lambda_min of every particle of a free set."""
    e0, gradp, lam = [], [], []
    for i in range(len(x)):
        r = x - x[i]  # r_ij = x_j - x_i
        d = np.hypot(r[:, 0], r[:, 1])
        w, dw = cubic(d, H)
        e0.append(np.sum(volume * w) - 1)
        near = d > 0
        # grad_i W_ij = -W'(r) r_ij / r
        grad = -(dw[near] / d[near])[:, None] * r[near]
        L = np.einsum("j,ja,jb->ab", volume[near], r[near], grad)
        gradp.append(L[1, 1] - 1)
        lam.append(np.linalg.eigvalsh(L)[0])
    return np.array(e0), np.array(gradp), np.array(lam)


def write_csv(path, x, m, rho):
    with open(path, "w") as f:
        f.write("x,y,h,m,rho\n")
        for p, mm, r in zip(x, m, rho):
            f.write(f"{p[0]!r},{p[1]!r},{H!r},{mm!r},{r!r}\n")


def assess(path, *args):
    done = subprocess.run([CLI, "assess", "cubic_bspline", str(path), "--code", "pysph", *args, "--json"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def square_block(n):
    return np.stack(np.meshgrid(np.arange(n, dtype=float), np.arange(n, dtype=float), indexing="ij"), -1).reshape(-1, 2)


def test_interior_and_free_surface_are_told_apart_by_the_correction_matrix(tmp_path):
    x = square_block(14)
    write_csv(tmp_path / "block.csv", x, np.ones(len(x)), np.ones(len(x)))
    doc = assess(tmp_path / "block.csv")
    e0, gradp, lam = brute(x, np.ones(len(x)))
    inside = lam > 0.75
    assert 0 < inside.sum() < len(x)
    assert doc["interior"]["particles"] == inside.sum() and doc["surface"]["particles"] == (~inside).sum()
    for region, mask in (("interior", inside), ("surface", ~inside)):
        for name, values in (("e0", e0), ("eps_gradp", gradp), ("lambda_min", lam)):
            got = doc[region][name]
            for stat, q in (("p1", 1), ("p50", 50), ("p99", 99)):
                assert abs(got[stat] - np.percentile(values[mask], q)) < 1e-12, (region, name, stat)
            assert abs(got["min"] - values[mask].min()) < 1e-12 and abs(got["max"] - values[mask].max()) < 1e-12
    # The corners are the surface's lowest; the verdict is the interior's.
    assert doc["surface"]["lambda_min"]["min"] < 0.5
    worst = max(abs(np.percentile(v[inside], q)) for v in (e0, gradp) for q in (1, 99))
    assert abs(doc["condition_22"]["margin"] - (0.01 - worst)) < 1e-12


def test_each_particle_is_judged_against_its_own_density(tmp_path):
    """SWIFT's SquareTest: one lattice, masses 4:1 in a central square, each particle's density
    m / V. The global mean density is no particle's: eps_rho against it is large, while the
    verdict (e0, eps_gradp of the interior) is the equal-mass set's."""
    n = 16
    x = square_block(n)
    heavy = (np.abs(x[:, 0] - n / 2 + 0.5) < n / 4) & (np.abs(x[:, 1] - n / 2 + 0.5) < n / 4)
    m = np.where(heavy, 4.0, 1.0)
    write_csv(tmp_path / "square.csv", x, m, m)  # V = m / rho = 1
    write_csv(tmp_path / "equal.csv", x, np.ones(len(x)), np.ones(len(x)))
    box = ("--box", f"{n},{n}")
    two, one = assess(tmp_path / "square.csv", *box), assess(tmp_path / "equal.csv", *box)
    assert two["surface"]["particles"] == 0
    assert max(abs(two["particles"]["statistics"]["eps_rho"][s]) for s in ("p1", "p99")) > 0.3
    assert two["condition_22"] == one["condition_22"] and two["interior"] == one["interior"]


def test_a_sweep_of_the_codes_parameter_finds_the_setting_the_set_needs(tmp_path):
    """On a perfect periodic square lattice each value's interior errors are the lattice's shell
    sums (`eps --code pysph --hdx`, an independent route), and the needed hdx the smallest at
    which both are within epsilon."""
    n = 12
    x = square_block(n)
    write_csv(tmp_path / "square.csv", x, np.ones(len(x)), np.ones(len(x)))
    doc = assess(tmp_path / "square.csv", "--box", f"{n},{n}", "--hdx-range", "1.0", "1.6", "--steps", "6")
    assert doc["code"] == "pysph" and doc["parameter"] == "hdx" and len(doc["points"]) == 7
    holds = []
    for point in doc["points"]:
        lattice = json.loads(subprocess.run([CLI, "eps", "cubic_bspline", "square", "--code", "pysph", "--hdx",
                                             repr(point["value"]), "--json"], capture_output=True, text=True,
                                            check=True).stdout)
        for name, mine in (("eps_rho", "e0"), ("eps_gradp", "eps_gradp")):
            for stat in ("p1", "p99"):
                assert abs(point["interior"][mine][stat] - lattice[name]) < 1e-9, (point["value"], name)
        worst = max(abs(lattice["eps_rho"]), abs(lattice["eps_gradp"]))
        assert point["holds"] == (worst <= 0.01) and abs(point["margin"] - (0.01 - worst)) < 1e-9
        holds.append(point["holds"])
    assert any(holds)
    assert doc["needed"] == doc["points"][holds.index(True)]["value"]
    # A range where it never holds: one line naming it (exit 2).
    done = subprocess.run([CLI, "assess", "cubic_bspline", str(tmp_path / "square.csv"), "--box", f"{n},{n}", "--code", "pysph",
                           "--hdx-range", "0.6", "0.7", "--steps", "2"], capture_output=True, text=True)
    assert done.returncode == 2 and "--hdx-range: [0.6, 0.7]: condition (22)" in done.stderr, done.stderr
    assert len(done.stderr.strip().splitlines()) == 1


def run_json(*args):
    done = subprocess.run([CLI, *args, "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_stability_of_the_same_setting_on_every_lattice_of_the_sets_dimension(tmp_path):
    # A 3D glass-like set: each shipped 3D lattice at the code's own setting (SWIFT: k from eta with
    # the lattice's SPH density, as `eps --code swift` finds it) under SWIFT's model (an ideal gas,
    # adaptive h), each verdict as `stability` gives it at that k.
    rng = np.random.default_rng(3)
    x = rng.uniform(0, 1, (2000, 3))
    with open(tmp_path / "set.csv", "w") as f:
        f.write("x,y,z\n" + "".join(f"{p[0]!r},{p[1]!r},{p[2]!r}\n" for p in x))
    doc = run_json("assess", "wendland_c2", str(tmp_path / "set.csv"), "--box", "1,1,1", "--code", "swift", "--eta", "1.2348")
    lattices = doc["stability"]["lattices"]
    assert [l["lattice"] for l in lattices] == ["bcc", "fcc", "hcp", "hex_prism", "sc"]
    assert "an ideal gas" in doc["stability"]["pressure"]
    for l in lattices:
        k = run_json("eps", "wendland_c2", l["lattice"], "--code", "swift", "--eta", "1.2348")["k"]
        assert abs(l["k"] / k - 1) < 1e-12 and l["h_model"] == "adaptive"
        alone = run_json("stability", "wendland_c2", l["lattice"], "--k", repr(l["k"]), "--h-model", "adaptive")
        assert l["verdict"] == alone["verdict"], (l, alone["verdict"])
    stable = [l["lattice"] for l in lattices if l["verdict"] == "stable"]
    assert stable and len(stable) < len(lattices)  # the lattices disagree at this setting: a real choice
    assert f"stable on {', '.join(stable)}, not on" in doc["verdict"]


def test_a_stored_h_is_carried_to_each_lattice_at_the_same_h_over_l_and_a_tait_codes_pressure(tmp_path):
    # 2D, PySPH (a weakly compressible code: Tait's pressure at rest): the set's mean h over the mean
    # spacing on square and triangular, k = (h/l) a_p^(1/2) with each lattice's Voronoi a_p.
    x = square_block(14)
    write_csv(tmp_path / "block.csv", x, np.ones(len(x)), np.ones(len(x)))
    doc = assess(tmp_path / "block.csv")
    h_over_l = doc["particles"]["h_over_l"]
    lattices = {l["lattice"]: l for l in doc["stability"]["lattices"]}
    assert sorted(lattices) == ["square", "triangular"]
    assert "Tait" in doc["stability"]["pressure"]
    assert abs(lattices["square"]["k"] / h_over_l - 1) < 1e-12
    assert abs(lattices["triangular"]["k"] / (h_over_l * (3**0.5 / 2) ** 0.5) - 1) < 1e-12
    assert all(l["h_model"] == "fixed" for l in lattices.values())


def without_timings(value):
    """A document with its timings and thread counts left out (they differ run to run)."""
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in ("seconds", "cpu_seconds", "phases", "threads")}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def test_python_assesses_a_file_and_sweeps_as_the_command_line(tmp_path):
    import sphkern
    n = 12
    x = square_block(n)
    write_csv(tmp_path / "square.csv", x, np.ones(len(x)), np.ones(len(x)))
    one = sphkern.assess("cubic_bspline", str(tmp_path / "square.csv"), box=[n, n], code="pysph", value=1.3)
    cli = assess(tmp_path / "square.csv", "--box", f"{n},{n}", "--hdx", "1.3")
    del cli["inputs"], cli["provenance"]
    assert without_timings(one) == without_timings(cli)
    sweep = sphkern.assess("cubic_bspline", tmp_path / "square.csv", box=[n, n], code="pysph", hdx_range=[1.0, 1.6], steps=6)
    cli = assess(tmp_path / "square.csv", "--box", f"{n},{n}", "--hdx-range", "1.0", "1.6", "--steps", "6")
    del cli["inputs"], cli["provenance"]
    assert without_timings(sweep) == without_timings(cli)


def test_python_refuses_what_a_file_or_a_lattice_cannot_take(tmp_path):
    import sphkern
    x = square_block(6)
    write_csv(tmp_path / "square.csv", x, np.ones(len(x)), np.ones(len(x)))
    path = str(tmp_path / "square.csv")
    for kwargs, message in ((dict(code="pysph", k=1.2), "are for a lattice; on a particle file"),
                            (dict(code="pysph", eta_range=[1, 2]), "eta_range: sweeps the eta of another code"),
                            (dict(code="pysph", value=1.2, hdx_range=[1, 2]), "hdx_range: sweeps the parameter; expected no value"),
                            (dict(value=1.2), "a code's setting is assessed; expected code")):
        with pytest.raises(sphkern.BadValue, match=message):
            sphkern.assess("cubic_bspline", path, **kwargs)
    with pytest.raises(sphkern.BadValue, match="are for a particle file; fcc is a lattice"):
        sphkern.assess("cubic_bspline", "fcc", k=1.2, box=[1, 1, 1])
