"""The Python module against the command line: the same values (to 1e-13), the same
errors (as ValueError or RuntimeError with the command line's one-line message), and
arrays of any shape. Run by ctest with PYTHONPATH=<build>/python and SPHKERN_CLI set."""
import json
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import sphkern

CLI = os.environ["SPHKERN_CLI"]
BROKEN = os.environ["SPHKERN_BROKEN_PLUGINS"]
KERNELS = ["cubic_bspline", "wendland_c4", "liu_quartic", "super_gaussian"]
LATTICES = [entry["name"] for entry in sphkern.lattices()]


def cli_json(*args):
    """The command's document without its provenance and inputs (the module's have neither)."""
    done = subprocess.run([CLI, *args, "--json"], capture_output=True, text=True, check=True)
    document = json.loads(done.stdout)
    for item in document if isinstance(document, list) else [document]:
        assert item.pop("provenance")["sphkern_version"] == sphkern.__version__
        item.pop("inputs", None)
    return document


def cli_error(*args):
    done = subprocess.run([CLI, *args], capture_output=True, text=True)
    assert done.returncode != 0
    line = done.stderr.strip()
    assert line.startswith("sphkern: error: ")
    return done.returncode, line[len("sphkern: error: "):]


def close(a, b):
    """Equal numbers to 1e-13 (relative to 1 + |b|) inside any JSON-like structure."""
    if isinstance(b, dict):
        assert a.keys() == b.keys()
        for key in b:
            close(a[key], b[key])
    elif isinstance(b, list):
        assert len(a) == len(b)
        for x, y in zip(a, b):
            close(x, y)
    elif isinstance(b, float) or isinstance(a, float):
        assert abs(a - b) <= 1e-13 * (1 + abs(b)), (a, b)
    else:
        assert a == b


def test_every_shipped_lattice_and_four_kernels_match_the_command_line():
    assert len(LATTICES) == 7
    compared = 0
    for lattice in LATTICES:
        for kernel in KERNELS:
            ks = np.array([0.8, 1.0, 1.2])
            got = sphkern.eps(kernel, lattice, ks)
            for i, k in enumerate(ks):
                want = cli_json("eps", kernel, lattice, "--k", repr(float(k)))
                close(float(got["eps_rho"][i]), want["eps_rho"])
                close(float(got["eps_gradp"][i]), want["eps_gradp"])
                close(float(got["eps_lateral"][i]), want["lateral"])
                assert int(got["nh"][i]) == want["neighbours"]
                compared += 1
    assert compared == 7 * 4 * 3


def test_options_mirror_the_command_line():
    got = sphkern.eps("wendland_c2_shape", "hcp", 1.1, a_p="ball", gravity=[1, 0, 0], site=1, params={"beta": 1.5})
    want = cli_json("eps", "wendland_c2_shape", "hcp", "--k", "1.1", "--ap", "ball", "--gravity", "1,0,0", "--site", "1",
                    "--set", "beta=1.5")
    close(float(got["eps_rho"]), want["eps_rho"])
    close(float(got["eps_gradp"]), want["eps_gradp"])
    got = sphkern.eps("cubic_bspline", "triangular", 1.0, a_p=0.9)
    close(float(got["eps_rho"]), cli_json("eps", "cubic_bspline", "triangular", "--k", "1", "--ap", "0.9")["eps_rho"])


def test_documents_equal_the_command_lines():
    close(sphkern.kernels(), cli_json("kernels"))
    close(sphkern.lattices(), cli_json("lattices"))
    close(sphkern.roots("cubic_bspline", "triangular"), cli_json("roots", "cubic_bspline", "triangular")[0])
    close(sphkern.roots("morris_quintic", "fcc", kmin=0.8, kmax=1.3),
          cli_json("roots", "morris_quintic", "fcc", "--kmin", "0.8", "--kmax", "1.3")[0])
    close(sphkern.roots("wendland_c4", "hcp", axis="h_over_l", kmin=1.0, kmax=1.6, lateral=True),
          cli_json("roots", "wendland_c4", "hcp", "--axis", "h_over_l", "--kmin", "1.0", "--kmax", "1.6", "--lateral")[0])
    close(sphkern.shells("bcc", 3, site=1), cli_json("shells", "bcc", "--radius", "3", "--site", "1"))
    close(sphkern.surface("cubic_bspline", "fcc", 1.2, form="monaghan", layers=6),
          cli_json("surface", "cubic_bspline", "fcc", "--k", "1.2", "--form", "monaghan", "--layers", "6"))
    close(sphkern.surface("wendland_c2", "fcc", code="swift", value=1.2348),
          cli_json("surface", "wendland_c2", "fcc", "--code", "swift", "--eta", "1.2348"))
    close(sphkern.design("cubic_bspline+desbrun_spiky", "triangular", "alpha"),
          cli_json("design", "cubic_bspline+desbrun_spiky", "triangular", "--param", "alpha"))


@pytest.mark.parametrize("kwargs, message", [
    ({}, "k: expected a number, or code and value"),
    ({"k": 1.2, "code": "swift", "value": 1.2}, "give one of k and code"),
    ({"code": "swift"}, "code = swift: expected value, the code's parameter, too"),
    ({"value": 1.2}, "value: is a code's parameter; expected code too"),
    ({"code": "swift", "value": -1}, "value = -1: expected a number in (0, 100]"),
])
def test_surface_takes_k_or_a_code_setting(kwargs, message):
    with pytest.raises(ValueError, match=re.escape(message)):
        sphkern.surface("wendland_c2", "fcc", **kwargs)


def test_stability_documents_equal_the_command_lines():
    close(sphkern.stability("cubic_bspline", "fcc", 1.2),
          cli_json("stability", "cubic_bspline", "fcc", "--k", "1.2"))
    close(sphkern.stability("wendland_c2", "hcp", 1.1, wavevector=[0.3, 0.1, 0.5]),
          cli_json("stability", "wendland_c2", "hcp", "--k", "1.1", "--wavevector", "0.3,0.1,0.5"))
    close(sphkern.stability("cubic_bspline", "triangular", kmin=0.8, kmax=1.2, steps=10),
          cli_json("stability", "cubic_bspline", "triangular", "--kmin", "0.8", "--kmax", "1.2", "--steps", "10"))
    close(sphkern.stability("cubic_bspline", "sc", 1.2, path=30),
          cli_json("stability", "cubic_bspline", "sc", "--k", "1.2", "--path", "30"))
    with pytest.raises(ValueError):
        sphkern.stability("cubic_bspline", "fcc", 1.2, gamma=0)
    with pytest.raises(ValueError):
        sphkern.stability("cubic_bspline", "fcc", 1.2, wavevector=[0, 0, 0])
    for kwargs, message in [({"wavevector": [1, 0]}, "wavevector: 2 components, expected 3 for a 3D lattice"),
                            ({"kmin": 0.8}, "kmin and kmax go together, without k, wavevector or path"),
                            ({"wavevector": [1, 0, 0], "path": 10}, "wavevector and path: give one of them"),
                            ({"gamma": -1}, "gamma -1 is not allowed, expected a number in [1e-06, 1e+06]"),
                            ({"horizon": -1}, "horizon -1 is not allowed, expected a growth time in (0, 1e12] (in d/c)")]:
        with pytest.raises(ValueError) as raised:
            sphkern.stability("cubic_bspline", "fcc", 1.2, **kwargs)
        assert str(raised.value) == message


def test_stability_verdicts_horizon_and_window_edge():
    # morris_quintic on fcc at k = 0.892: a transverse mode grows in about 330 d/c.
    slow = sphkern.stability("morris_quintic", "fcc", 0.892)
    assert slow["verdict"] == "weak" and slow["mode"]["kind"] == "transverse" and 300 < slow["growth_time"] < 360
    assert sphkern.stability("morris_quintic", "fcc", 0.892, horizon=1000)["verdict"] == "unstable"
    close(sphkern.stability("morris_quintic", "fcc", kmin=0.88, kmax=0.9, steps=4, horizon=50),
          cli_json("stability", "morris_quintic", "fcc", "--kmin", "0.88", "--kmax", "0.9", "--steps", "4", "--horizon", "50"))
    # The best k of condition (22) on the window's edge is flagged.
    assert sphkern.roots("wendland_c2", "hcp")["best_k_note"] == "at the window edge; widen the k window"


def test_roots_with_stability_code_and_adaptive_h_equal_the_command_line():
    for model in ("fixed", "adaptive"):
        document = sphkern.roots("cubic_bspline", "fcc", stability=True, steps=20, h_model=model, code="swift")
        cli = cli_json("roots", "cubic_bspline", "fcc", "--stability", "--steps", "20", "--h-model", model,
                       "--code", "swift")[0]
        close(document["stability"], cli["stability"])
        close(document["code"], cli["code"])
        # convention is code's old name: the same answer.
        close(sphkern.roots("cubic_bspline", "fcc", stability=True, steps=20, h_model=model, convention="swift")["code"],
              document["code"])
        assert document["stability"]["h_model"] == model
        assert document["best_k_at_window_edge"] is False
    # The recommended k on the window's edge is flagged, in Python too.
    edge = sphkern.roots("cubic_bspline", "fcc", kmin=0.99, kmax=1.0, stability=True, steps=4)["stability"]["recommended"]
    assert edge["at_window_edge"] and edge["note"] == "at the window edge; widen the k window"
    assert sphkern.roots("wendland_c2", "hcp")["best_k_at_window_edge"] is True
    close(sphkern.stability("cubic_bspline", "fcc", 1.1, h_model="adaptive"),
          cli_json("stability", "cubic_bspline", "fcc", "--k", "1.1", "--h-model", "adaptive"))
    with pytest.raises(ValueError) as raised:
        sphkern.stability("cubic_bspline", "fcc", 1.1, h_model="grad-h")
    assert str(raised.value) == 'h_model "grad-h" is not a smoothing-length model, expected fixed or adaptive'
    with pytest.raises(ValueError) as raised:
        sphkern.roots("cubic_bspline", "fcc", convention="gadget")
    assert str(raised.value).startswith('convention: "gadget" is unknown, expected one of swift, phantom, gadget2')
    with pytest.raises(ValueError) as raised:
        sphkern.roots("cubic_bspline", "fcc", code="swift", convention="swift")
    assert str(raised.value) == "give one of code and convention (its old name)"


def test_roots_returns_one_dict_whatever_the_options():
    plain = sphkern.roots("cubic_bspline", "fcc")
    assert type(plain) is dict and type(plain["roots"]) is list and len(plain["roots"]) > 0
    assert {"roots", "jumps", "acceptance", "acceptance_every_direction", "sites", "all_sites",
            "best_k_at_window_edge", "window"} <= plain.keys()
    close(plain["roots"], cli_json("roots", "cubic_bspline", "fcc")[0]["roots"])
    for options, added in [({"lateral": True}, set()), ({"axis": "h_over_l", "kmin": 1.0, "kmax": 1.6}, set()),
                           ({"stability": True, "steps": 10}, {"stability"}), ({"code": "swift"}, {"code"}),
                           ({"stability": True, "steps": 10, "convention": "gadget2"}, {"stability", "code"})]:
        document = sphkern.roots("cubic_bspline", "fcc", **options)
        assert type(document) is dict and type(document["roots"]) is list, options
        # The same keys, but for those the options add (and the note of a best k on the window's edge).
        assert document.keys() - {"best_k_note"} == plain.keys() | added, options
    with pytest.raises(TypeError):
        sphkern.roots("cubic_bspline", "fcc", details=True)  # the whole document is always returned


def test_kernel_functions_are_vectorised_and_equal_the_plugin():
    kernel = sphkern.kernel("cubic_bspline")
    q = np.linspace(0, 2.5, 11).reshape(11, 1)
    w = kernel.w(q, 3)
    assert w.shape == (11, 1)
    sigma = 3 / (2 * np.pi)
    qq = q[:, 0]
    expected = sigma * np.where(qq <= 1, 2 / 3 - qq**2 + 0.5 * qq**3, np.where(qq <= 2, (2 - qq) ** 3 / 6, 0))
    assert np.allclose(w[:, 0], expected, rtol=1e-14, atol=1e-16)
    assert kernel.dw(0.5, 3).shape == ()
    assert kernel.name == "cubic_bspline" and kernel.support == 2.0 and kernel.info["dimensions"] == [1, 2, 3]


def test_a_million_k_values_in_one_call_keep_their_shape():
    ks = np.linspace(0.75, 1.25, 10**6)
    got = sphkern.eps("cubic_bspline", "fcc", ks)
    assert all(got[key].shape == (10**6,) for key in ("eps_rho", "eps_gradp", "eps_lateral", "nh"))
    # Spot checks against single evaluations.
    for i in (0, 123457, 10**6 - 1):
        close(float(got["eps_rho"][i]), float(sphkern.eps("cubic_bspline", "fcc", float(ks[i]))["eps_rho"]))
    grid = sphkern.eps("cubic_bspline", "fcc", ks.reshape(1000, 1000))
    assert grid["eps_gradp"].shape == (1000, 1000)
    assert np.array_equal(grid["eps_gradp"].ravel(), got["eps_gradp"])


@pytest.mark.parametrize("call, args", [
    (lambda: sphkern.eps("cubic", "fcc", 1.0), ("eps", "cubic", "fcc", "--k", "1")),
    (lambda: sphkern.eps("cubic_bspline", "fccc", 1.0), ("eps", "cubic_bspline", "fccc", "--k", "1")),
    (lambda: sphkern.eps("composite", "fcc", 1.0), ("eps", "composite", "fcc", "--k", "1")),
    (lambda: sphkern.eps("cubic_bspline", "fcc", 1.0, a_p="hexagon"), ("eps", "cubic_bspline", "fcc", "--k", "1", "--ap", "hexagon")),
    (lambda: sphkern.eps("cubic_bspline", "fcc", 1.0, params={"alpha": 1}),
     ("eps", "cubic_bspline", "fcc", "--k", "1", "--set", "alpha=1")),
    (lambda: sphkern.eps("cubic_bspline", "fcc", 1.0, gravity=[0, 0, 0]),
     ("eps", "cubic_bspline", "fcc", "--k", "1", "--gravity", "0,0,0")),
    (lambda: sphkern.shells("fcc", 1e5), ("shells", "fcc", "--radius", "1e5")),
    (lambda: sphkern.surface("cubic_bspline", "fcc", 1.2, form="up"),
     ("surface", "cubic_bspline", "fcc", "--k", "1.2", "--form", "up")),
    (lambda: sphkern.stability("cubic_bspline", "fcc", kmin=0.8, kmax=1.6, steps=2000, grid=400),
     ("stability", "cubic_bspline", "fcc", "--kmin", "0.8", "--kmax", "1.6", "--steps", "2000", "--grid", "400")),
])
def test_bad_input_raises_value_error_with_the_command_lines_message(call, args):
    code, message = cli_error(*args)
    assert code == (2 if "--gravity" in args else 3)  # a zero direction is an option out of its range; the rest, inputs
    with pytest.raises(ValueError) as raised:
        call()
    # The same line, but for the options' names: the module's keywords are "gravity", "steps" and "grid", the
    # command line's "--gravity", "--steps" and "--grid".
    for option in ("gravity", "steps", "grid"):
        message = message.replace("--" + option, option)
    assert str(raised.value) == message


def test_bad_numbers_and_types_raise_instead_of_crashing():
    for k in (-1.0, 0.0, float("nan"), float("inf"), 1e300):
        with pytest.raises(ValueError, match="is not allowed"):
            sphkern.eps("cubic_bspline", "fcc", k)
    with pytest.raises(ValueError, match="empty array"):
        sphkern.eps("cubic_bspline", "fcc", np.array([]))
    with pytest.raises(ValueError, match="params"):
        sphkern.eps("cubic_bspline", "fcc", 1.0, params=[1, 2])
    with pytest.raises(ValueError, match="params"):
        sphkern.eps("wendland_c2_shape", "fcc", 1.0, params={"beta": "big"})
    with pytest.raises(ValueError, match="gravity"):
        sphkern.eps("cubic_bspline", "fcc", 1.0, gravity=[0, 1])
    with pytest.raises(ValueError, match="sites 0 to 0"):
        sphkern.eps("cubic_bspline", "fcc", 1.0, site=3)
    with pytest.raises(ValueError, match="q = -1 is not allowed"):
        sphkern.kernel("cubic_bspline").w(np.array([0.5, -1.0]), 3)
    with pytest.raises(ValueError, match="not on the 1D lattice"):
        sphkern.kernel("wendland_c4").w(0.5, 1)
    with pytest.raises(ValueError, match="no such file"):
        sphkern.load_lattice("/nonexistent/lattice.json")
    with pytest.raises(TypeError):
        sphkern.eps(None, "fcc", 1.0)


def test_a_site_the_lattice_lacks_is_refused_by_every_function_in_one_wording():
    for call, lattice in [(lambda: sphkern.eps("cubic_bspline", "fcc", 1.0, site=3), "fcc"),
                          (lambda: sphkern.surface("cubic_bspline", "fcc", 1.2, site=3), "fcc"),
                          (lambda: sphkern.roots("cubic_bspline", "fcc", site=3), "fcc"),
                          (lambda: sphkern.design("cubic_bspline+desbrun_spiky", "triangular", "alpha", site=3),
                           "triangular")]:
        with pytest.raises(ValueError) as raised:
            call()
        assert str(raised.value) == f"site: site 3 does not exist; lattice {lattice} has sites 0 to 0"


def test_plugins_are_probed_as_the_command_line_probes_them(tmp_path):
    with pytest.raises(RuntimeError, match="crash_in_w.so: plugin crashed with signal 11"):
        sphkern.load_plugin(os.path.join(BROKEN, "crash_in_w.so"))
    with pytest.raises(RuntimeError, match="W is not finite at q = 0.70"):
        sphkern.load_plugin(os.path.join(BROKEN, "nan_band.so"))
        sphkern.eps(os.path.join(BROKEN, "nan_band.so"), "fcc", 1 / 0.705)
    expression = tmp_path / "x_cubic.json"
    expression.write_text(json.dumps({
        "name": "x_cubic", "support": 2, "dimensions": [3],
        "w": "(q < 1 ? 1 - 1.5*q^2 + 0.75*q^3 : (q < 2 ? 0.25*(2-q)^3 : 0)) / _pi"}))
    assert sphkern.load_plugin(str(expression))["name"] == "x_cubic"
    close(float(sphkern.eps(str(expression), "fcc", 1.2)["eps_rho"]),
          float(sphkern.eps("cubic_bspline", "fcc", 1.2)["eps_rho"]))


def test_a_lattice_file_loads_and_is_usable(tmp_path):
    honeycomb = tmp_path / "honeycomb.json"
    honeycomb.write_text(json.dumps({"name": "honeycomb", "dimension": 2, "basis": [[1.7320508075688772, 0],
                                     [0.8660254037844386, 1.5]], "motif": [[0, 0], [0.3333333333333333, 0.3333333333333333]]}))
    described = sphkern.load_lattice(str(honeycomb))
    assert described["sites"] == 2 and described["dimension"] == 2
    close(float(sphkern.eps("cubic_bspline", str(honeycomb), 1.1)["eps_rho"]),
          cli_json("eps", "cubic_bspline", str(honeycomb), "--k", "1.1")["eps_rho"])


def test_a_shipped_plugin_loaded_by_its_path_is_still_found_by_name():
    # In a fresh interpreter: the loaded plugin stays in the module's registry.
    script = """
import sphkern
shipped = [k for k in sphkern.kernels() if k["name"] == "wendland_c2"][0]["file"]
assert sphkern.load_plugin(shipped)["name"] == "wendland_c2"
print(sphkern.eps("wendland_c2", "fcc", 1.2)["eps_rho"], len([k for k in sphkern.kernels() if k["name"] == "wendland_c2"]))
"""
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=os.environ)
    assert out.returncode == 0, out.stderr
    eps_rho, listed = out.stdout.split()
    assert float(eps_rho) == float(sphkern.eps("wendland_c2", "fcc", 1.2)["eps_rho"]) and listed == "1"


def test_shells_names_its_arguments():
    with pytest.raises(ValueError, match=r"^radius = -1: expected a positive finite number$"):
        sphkern.shells("fcc", -1.0)
    with pytest.raises(ValueError, match=r"^site: site 3 does not exist; lattice fcc has sites 0 to 0$"):
        sphkern.shells("fcc", 2.0, site=3)
    with pytest.raises(ValueError, match=r"^gravity: 2 components, expected 3 \(one per dimension\)$"):
        sphkern.shells("fcc", 2.0, gravity=[0, 1])


def test_a_codes_setting_as_the_command_line_gives_it():
    # code_k is eps --code's k; roots(code=...) adds the command line's "code" document.
    for kernel, code, value in [("wendland_c2", "swift", 1.2348), ("cubic_bspline", "gadget2", 48.0),
                                ("wendland_c2", "pysph", 1.2)]:
        k = sphkern.code_k(kernel, "fcc", code, value)
        assert k == cli_json("eps", kernel, "fcc", "--code", code, {"swift": "--eta", "gadget2": "--nngb",
                                                                    "pysph": "--hdx"}[code], repr(value))["k"]
    close(sphkern.roots("cubic_bspline", "fcc", stability=True, steps=10, code="swift")["code"],
          cli_json("roots", "cubic_bspline", "fcc", "--stability", "--steps", "10", "--code", "swift")[0]["code"])
    with pytest.raises(ValueError, match="gadget2 does not ship it; its kernels are cubic_bspline"):
        sphkern.code_k("wendland_c2", "fcc", "gadget2", 48)
