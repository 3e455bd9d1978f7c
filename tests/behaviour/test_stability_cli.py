"""Stability and spectra: bad values name the option and the range; roots --stability agrees with
stability over k; stability --k agrees with each sampled k; the dispersion path, the adaptive
smoothing length, a best k on the window's edge, --convention as --code's old name, and the
texts of stability, spectrum and check."""
import os

import pytest
from conftest import BROKEN, expect, fill, json_of, run, table, text_of, write

CASES = [
    ("stability-wavevector-0-0-0", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--wavevector", "0,0,0"],
     2, "wavevector 0,0,0: expected a non-zero wave vector"),
    ("stability-wavevector-1-nan-0", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--wavevector", "1,nan,0"],
     2, 'wavevector 1,nan,0: "nan" is not a finite number'),
    ("stability-wavevector-1-2", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--wavevector", "1,2"],
     2, "wavevector 1,2: 2 components, expected 3"),
    ("stability-gamma-0", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--gamma", "0"],
     2, r"gamma 0 is not allowed, expected a number in \[1e-06, 1e\+06\]"),
    ("stability-gamma-neg1", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--gamma", "-1"],
     2, "gamma -1 is not allowed"),
    ("stability-kmin-1.2-kmax-1", ["stability", "cubic_bspline", "fcc", "--kmin", "1.2", "--kmax", "1"],
     2, "kmin 1.2 --kmax 1: expected 0 < kmin < kmax"),
    ("stability-lieb", ["stability", "cubic_bspline", "{examples}/lieb.json", "--k", "1.2"],
     3, "do not see one SPH density"),
    ("stability-path-1", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--path", "1"],
     2, "error: --path 1, expected 2 to 100000$"),
    ("roots-gamma-neg1", ["roots", "cubic_bspline", "fcc", "--stability", "--gamma", "-1"],
     2, r"--gamma -1 is not allowed, expected a number in \[1e-06, 1e\+06\]"),
    ("stability-horizon-neg1", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--horizon", "-1"],
     2, r"--horizon -1 is not allowed, expected a growth time in \(0, 1e12\]"),
    ("roots-horizon-0", ["roots", "cubic_bspline", "fcc", "--stability", "--horizon", "0"],
     2, "--horizon 0 is not allowed"),
    ("roots-convention-nosuch", ["roots", "cubic_bspline", "fcc", "--convention", "nosuch"],
     2, '^sphkern: error: --convention: "nosuch" is unknown, expected one of swift, phantom, gadget2, gadget4, pysph, dualsphysics, splishsplash$'),
    ("roots-code-and-convention", ["roots", "cubic_bspline", "fcc", "--code", "swift", "--convention", "swift"],
     2, r"^sphkern: error: give one of --code and --convention \(its old name\)$"),
    # The smoothing-length model: fixed or adaptive, nothing else.
    ("stability-h-model-grad-h", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--h-model", "grad-h"],
     2, '--h-model "grad-h" is not a smoothing-length model, expected fixed or adaptive'),
    ("roots-h-model-Adaptive", ["roots", "cubic_bspline", "fcc", "--stability", "--h-model", "Adaptive"],
     2, '--h-model "Adaptive" is not a smoothing-length model'),
    ("roots-convention-swift-super_gaussian",
     ["roots", "super_gaussian", "triangular", "--convention", "swift"],
     2, "^sphkern: error: super_gaussian: swift does not ship it"),
    ("stability-kmin-and-path", ["stability", "cubic_bspline", "fcc", "--kmin", "1", "--kmax", "1.2", "--path", "10"],
     2, "--kmin excludes --path"),
    ("stability-wavevector-and-path",
     ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--path", "10", "--wavevector", "1,0,0"],
     2, "--wavevector and --path: give one of them"),
    ("spectrum-dim-1", ["spectrum", "wendland_c2", "--dim", "1"], 3, "defined in 2,3D only"),
]


@table(CASES)
def test_stability_value(args, code, pattern):
    expect(fill(args), code, pattern)


STUDY_CASES = [
    ("study-horizon-neg1",
     {"s_horizon.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"horizon": -1}}'},
     ["run", "{w}/s_horizon.json", "-o", "{w}/out12"],
     3, "s_horizon.json: /stability/horizon: "),
    ("study-h_model-variable",
     {"s_hmodel.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"h_model": "variable"}}'},
     ["run", "{w}/s_hmodel.json", "-o", "{w}/out_hmodel"],
     3, 's_hmodel.json: /stability/h_model: expected "fixed" or "adaptive"'),
]


@pytest.mark.parametrize("files,args,code,pattern", [c[1:] for c in STUDY_CASES], ids=[c[0] for c in STUDY_CASES])
def test_stability_section_of_a_study(tmp_path, files, args, code, pattern):
    write(tmp_path, files)
    expect(fill(args, tmp_path), code, pattern)
    assert sorted(os.listdir(tmp_path)) == sorted(files)




def test_roots_stability_is_stability_over_k_and_its_overlap_with_the_accuracy():
    # roots --stability: the stable intervals of stability --kmin/--kmax, and their overlap with (22).
    r = json_of("roots", "cubic_bspline", "fcc", "--stability", "--steps", "50", "--json")[0]
    s = json_of("stability", "cubic_bspline", "fcc", "--kmin", "0.75", "--kmax", "1.25", "--steps", "50", "--json")
    assert r["stability"]["stable_intervals"] == s["stable_intervals"], (r["stability"], s["stable_intervals"])
    assert r["stability"]["stable_at_horizon"] == s["stable_at_horizon"], (r["stability"], s["stable_at_horizon"])

    def inside(k, v):
        return any(a < k < b for a, b in v)

    for i in range(1, 500):
        k = 0.75 + 0.5 * i / 500
        both = inside(k, r["all_sites"]["acceptance"]["intervals"]) and inside(k, s["stable_at_horizon"])
        assert both == inside(k, r["stability"]["accurate_and_stable"]), k
    rec = r["stability"]["recommended"]
    widest = max(r["stability"]["accurate_and_stable"], key=lambda i: i[1] - i[0])
    assert rec["found"] and abs(rec["k"] - (widest[0] + widest[1]) / 2) < 1e-12 and rec["interval"] == widest, rec


def test_adaptive_h_gives_h_over_l_and_the_grad_h_factor():
    d = json_of("stability", "cubic_bspline", "fcc", "--k", "1.2", "--h-model", "adaptive", "--json")
    assert (d["h_model"], d["h_over_l"] > 0, d["grad_h_factor"] > 0) == ("adaptive", True, True), d


def test_stability_k_gives_each_sampled_k_the_same_verdict():
    s = json_of("stability", "wendland_c2", "hcp", "--kmin", "1.8965", "--kmax", "1.8975", "--steps", "4", "--json")
    for p in s["samples"]:
        one = json_of("stability", "wendland_c2", "hcp", "--k", repr(p["k"]), "--json")
        assert (one["verdict"], one["stable"], one["min_omega2"]) == (p["verdict"], p["stable"], p["min_omega2"]), (p, one["verdict"])
    assert not s["stable_intervals"] and all(not p["stable"] for p in s["samples"])


def test_a_best_k_on_the_windows_edge_is_flagged():
    assert "at the window edge; widen the k window" in text_of("roots", "wendland_c2", "hcp")
    d = json_of("roots", "wendland_c2", "hcp", "--json")[0]
    assert d["best_k_note"] == "at the window edge; widen the k window", d.get("best_k_note")


def test_convention_is_codes_old_name():
    # roots --convention is --code by its old name: the same document.
    a, b = (json_of("roots", "cubic_bspline", "sc", "--stability", "--steps", "20", *x, "--json")[0]
            for x in (("--convention", "gadget2"), ("--code", "gadget2")))
    for d in (a, b):
        d.pop("provenance", None)
    assert a == b and a["code"]["name"] == "gadget2", a.get("code")


def test_the_dispersion_path():
    # stability --path starts at Γ with omega^2 = 0 and ends at R.
    d = json_of("stability", "cubic_bspline", "sc", "--k", "1.2", "--path", "40", "--json")["path"]
    assert [p["label"] for p in d["points"]] == ["Γ", "X", "M", "Γ", "R"], d["points"]
    assert all(abs(w) < 1e-12 for w in d["omega2"][0]) and abs(d["position"][-1] - d["points"][-1]["at"]) < 1e-12


def test_the_texts_of_stability_spectrum_and_check():
    # The cubic spline on fcc at k = 1.2 is unstable.
    assert '"stable": false' in text_of("stability", "cubic_bspline", "fcc", "--k", "1.2", "--json")
    # Stability over k names the stable intervals.
    assert "stable for k in [" in text_of("stability", "wendland_c2", "triangular", "--kmin", "0.9", "--kmax", "1.4",
                                          "--steps", "10")
    # The 3D B-spline first vanishes at 2 pi.
    assert "first zero at kappa h = 6.283" in text_of("spectrum", "cubic_bspline", "--dim", "3")
    # check --json: an array, with the spectrum.
    d = json_of("check", "cubic_bspline", "--json")
    assert isinstance(d, list) and "fourier" in d[0]
    # check names the likely cause of a wrong derivative.
    assert "hint (1D derivative)" in run(["check", "--plugin", os.path.join(BROKEN, "wrong_derivative.so")]).stdout
