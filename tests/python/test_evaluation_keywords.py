"""The evaluation's keywords of eps, roots and assess as the command line's options: the shell
radii summed over (--shells) with the kernel's formula past its support (--continue-past-support),
and eps's axis (--axis h_over_l). Each equal to the command line's JSON. Run by ctest with
SPHKERN_CLI set."""
import json
import os
import subprocess

import pytest

import sphkern

CLI = os.environ["SPHKERN_CLI"]
SHELLS = [1, 3**0.5, 2, 7**0.5, 3]  # the triangular lattice's first five shells, in d


def cli(*args):
    return json.loads(subprocess.run([CLI, *args, "--json"], capture_output=True, text=True, check=True).stdout)


@pytest.mark.parametrize("past", [False, True])
def test_eps_over_given_shells(past):
    flag = ["--continue-past-support"] if past else []
    shells = ",".join(repr(r) for r in SHELLS)
    want = cli("eps", "super_gaussian", "triangular", "--k", "1.1", "--shells", shells, *flag)
    got = sphkern.eps("super_gaussian", "triangular", 1.1, shells=SHELLS, continue_past_support=past)
    assert float(got["eps_rho"]) == want["eps_rho"] and float(got["eps_gradp"]) == want["eps_gradp"]


def test_the_formula_past_the_support_changes_the_sums_over_a_shell_outside_it():
    # At k = 0.9 the 3 d shell lies past R k = 2.7: summed only with continue_past_support.
    cut = sphkern.eps("super_gaussian", "triangular", 0.9, shells=SHELLS)
    past = sphkern.eps("super_gaussian", "triangular", 0.9, shells=SHELLS, continue_past_support=True)
    assert float(cut["eps_rho"]) != float(past["eps_rho"])


def test_eps_on_the_h_over_l_axis():
    want = cli("eps", "cubic_bspline", "fcc", "--k", "1.3", "--axis", "h_over_l")
    got = sphkern.eps("cubic_bspline", "fcc", 1.3, axis="h_over_l")
    assert float(got["eps_rho"]) == want["eps_rho"] and float(got["eps_gradp"]) == want["eps_gradp"]


def test_roots_and_assess_over_given_shells():
    shells = ",".join(repr(r) for r in SHELLS)
    want = cli("roots", "super_gaussian", "triangular", "--kmin", "0.85", "--kmax", "1.05", "--shells", shells,
               "--continue-past-support")
    got = sphkern.roots("super_gaussian", "triangular", kmin=0.85, kmax=1.05, shells=SHELLS, continue_past_support=True)
    assert got["roots"] == want[0]["roots"]  # the command line lists one document per a_p
    want = cli("assess", "super_gaussian", "triangular", "--k", "0.95", "--shells", shells)
    got = sphkern.assess("super_gaussian", "triangular", k=0.95, shells=SHELLS)
    assert got["eps"]["eps_rho"] == want["eps"]["eps_rho"] and got["verdict"] == want["verdict"]


def test_surface_with_the_other_termination_on_top():
    want = cli("surface", "cubic_bspline", "bcc", "--k", "1.2", "--termination", "1")
    got = sphkern.surface("cubic_bspline", "bcc", 1.2, termination=1)
    assert got["termination"] == want["termination"] and got["layers"] == want["layers"]
    assert got["layers"] != sphkern.surface("cubic_bspline", "bcc", 1.2)["layers"]
    with pytest.raises(sphkern.BadValue, match="termination: -1: expected an index"):
        sphkern.surface("cubic_bspline", "bcc", 1.2, termination=-1)


def test_a_bad_axis_or_shell_list_is_refused():
    with pytest.raises(sphkern.BadValue, match="nh names a window, not one value"):
        sphkern.eps("cubic_bspline", "fcc", 1.2, axis="nh")
    with pytest.raises(sphkern.BadValue, match="axis"):
        sphkern.eps("cubic_bspline", "fcc", 1.2, axis="eta_over_d")
    with pytest.raises(sphkern.BadValue, match="shells"):
        sphkern.eps("cubic_bspline", "fcc", 1.2, shells=["one"])


def test_python_refuses_a_density_solve_without_the_codes_value(tmp_path):
    x = [[0.1 * i, 0.05 * i] for i in range(10)]
    path = tmp_path / "set.csv"
    path.write_text("x,y\n" + "".join(f"{a},{b}\n" for a, b in x))
    with pytest.raises(sphkern.BadValue, match="bias_correction: the code's correction of its density solve; expected code"):
        sphkern.assess("wendland_c2", path, box=[1, 1], code="gadget4", bias_correction=True)
