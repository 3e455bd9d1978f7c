"""PySPH's kernels, from PySPH's own classes (pysph/base/kernels.py: kernel and dwdq), against
the sphkern kernels that --code pysph maps them to (core/codes/pysph/pysph.cpp), at many q in
every dimension PySPH's class accepts. Its SuperGaussian is pysph_super_gaussian in every
dimension, and the paper's super_gaussian in 1D and 3D only."""
import os
import subprocess

import numpy as np
import pytest
import sphkern
from pysph.base import kernels as pysph_kernels

CLI = os.environ["SPHKERN_CLI"]

# PySPH's class, sphkern's kernel, the dimensions its constructor accepts.
MAPPED = [
    ("CubicSpline", "cubic_bspline", (1, 2, 3)),
    ("WendlandQuintic", "wendland_c2", (2, 3)),
    ("WendlandQuinticC4", "wendland_c4", (2, 3)),
    ("WendlandQuinticC6", "wendland_c6", (2, 3)),
    ("QuinticSpline", "morris_quintic", (1, 2, 3)),
    ("SuperGaussian", "pysph_super_gaussian", (1, 2, 3)),
    ("SuperGaussian", "super_gaussian", (1, 3)),
]


@pytest.mark.parametrize("pysph_name,name,dims", MAPPED, ids=[f"{a}-{b}" for a, b, _ in MAPPED])
def test_pysph_kernel_is_the_mapped_one(pysph_name, name, dims):
    ours = sphkern.kernel(name)
    for dim in dims:
        theirs = getattr(pysph_kernels, pysph_name)(dim=dim)
        assert theirs.radius_scale == ours.support
        for q in np.linspace(0.01, theirs.radius_scale - 1e-9, 300):
            w = theirs.kernel(rij=q, h=1.0)
            assert ours.w(q, dim) == pytest.approx(w, rel=1e-12, abs=1e-14), (dim, q)
            assert ours.dw(q, dim) == pytest.approx(theirs.dwdq(rij=q, h=1.0), rel=1e-12, abs=1e-14), (dim, q)


def test_pysph_2d_super_gaussian_is_not_the_papers():
    theirs = pysph_kernels.SuperGaussian(dim=2)
    assert sphkern.kernel("super_gaussian").w(0.5, 2) != pytest.approx(theirs.kernel(rij=0.5, h=1.0), rel=1e-3)


def run(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)


def test_pysph_takes_its_own_super_gaussian_and_warns_on_the_papers_in_2d():
    own = run("eps", "pysph_super_gaussian", "square", "--code", "pysph", "--hdx", "1.2", "--json")
    assert own.returncode == 0 and own.stderr == ""
    papers = run("eps", "super_gaussian", "square", "--code", "pysph", "--hdx", "1.2")
    assert papers.returncode == 0
    assert "super_gaussian: pysph has it in 1D and 3D only; its kernels in 2D are" in papers.stderr
    assert "pysph_super_gaussian" in papers.stderr and "taken as a user's kernel" in papers.stderr


def test_pysph_takes_a_users_expression_kernel(tmp_path):
    kernel = tmp_path / "mine.json"
    kernel.write_text('{"name": "mine", "support": 2, "dimensions": [2], "normalise": true, '
                      '"w": "q < 2 ? (1 - q/2)^4 * (2*q + 1) : 0"}')
    out = run("eps", "mine", "square", "--plugin", str(kernel), "--code", "pysph", "--hdx", "1.2")
    assert out.returncode == 0, out.stderr
    assert "mine: pysph does not ship it" in out.stderr and "taken as a user's kernel, which PySPH accepts" in out.stderr


def test_python_assess_takes_the_codes_rest_pressure():
    # As `assess --code dualsphysics --coef-sound 10`: the same JSON's pressure and verdict.
    ours = sphkern.assess("wendland_c2", "sc", code="dualsphysics", value=1.0, coef_sound=10)
    assert ours["pressure"]["model"] == "tait" and ours["pressure"]["p0_over_rho_c2"] == pytest.approx(0.01, rel=1e-15)
    cli = run("assess", "wendland_c2", "sc", "--code", "dualsphysics", "--coefh", "1.0", "--coef-sound", "10", "--json")
    import json
    assert json.loads(cli.stdout)["verdict"] == ours["verdict"]
    with pytest.raises(ValueError, match="coef_sound: 10: the sound speed over sqrt"):
        sphkern.assess("wendland_c2", "sc", code="swift", value=1.2, coef_sound=10)
