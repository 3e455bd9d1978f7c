"""Budgets before work: a blend of too many kernels, a study or a command line asking for more
samples, wave vectors, neighbours or pair evaluations than the limits is refused (exit 3) before
any of it runs, with the count and the limit; a plugin folder holding devices is not read."""
import json
import os
import re
import subprocess

import pytest
from conftest import CLI, expect, fill, run, table, write

BLEND = "+".join(["cubic_bspline"] * 8000)


def test_a_blend_of_too_many_kernels(tmp_path):
    expect(["eps", BLEND, "fcc", "--k", "1"], 3, r"a blend of 8000 kernels, more than the limit of 16")
    (tmp_path / "s_deep.json").write_text('{"name": "s", "kernels": ["' + BLEND + '"], "lattices": ["fcc"], "plots": false}')
    expect(["run", str(tmp_path / "s_deep.json"), "-o", str(tmp_path / "out_deep")], 3,
           r"a blend of 8000 kernels, more than the limit of 16")
    # No partial after a refused blend.
    assert sorted(os.listdir(tmp_path)) == ["s_deep.json"]
    expect(["eps", "cubic_bspline+wendland_c2+liu_quartic", "fcc", "--k", "1"], 0, r"^$")


def test_devices_in_a_plugin_folder_are_skipped_without_reading_them(tmp_path):
    folder = tmp_path / "plugin-folder"
    folder.mkdir()
    (folder / "zero.so").symlink_to("/dev/zero")
    (folder / "zero.json").symlink_to("/dev/zero")
    out = run(["kernels"], env_extra={"SPHKERN_PLUGIN_PATH": str(folder)})
    assert out.returncode == 0, out.stderr
    # The device plugin is named.
    assert "zero.so: is not a regular file" in out.stderr, out.stderr


STUDY_CASES = [
    ("study-samples",
     {"s_budget.json": '{"name": "s", "kernels": ["cubic_bspline", "morris_quintic", "liu_quartic", "wendland_c4"], "lattices": ["fcc", "bcc", "sc", "hcp"], "volume_coefficients": ["voronoi", "ball", "cube"], "k": {"samples": 100000}}'},
     ["run", "{w}/s_budget.json", "-o", "{w}/out_budget", "--no-plots"],
     3, "s_budget.json: /: the study asks for kernels x lattices x volume_coefficients x modes x k samples = 4800000, more than the limit of 2000000"),
    ("study-sweep-samples",
     {"s_budget_sweep.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc", "bcc", "sc", "hcp", "hex_prism", "triangular"], "sweeps": [{"kernel": "wendland_c2_shape", "parameter": "beta", "range": [0.5, 3], "samples": 1000}, {"kernel": "wendland_c2_shape", "parameter": "beta", "range": [0.5, 3], "samples": 1000}]}'},
     ["run", "{w}/s_budget_sweep.json", "-o", "{w}/out_budget"],
     3, "lattices x sweep samples x k samples, over all sweeps = 2412000"),
]


@pytest.mark.parametrize("files,args,code,pattern", [c[1:] for c in STUDY_CASES], ids=[c[0] for c in STUDY_CASES])
def test_study_over_budget(tmp_path, files, args, code, pattern):
    write(tmp_path, files)
    expect(fill(args, tmp_path), code, pattern)
    assert sorted(os.listdir(tmp_path)) == sorted(files)


# Budgets on the command line are the study's: one rule, exit 3.
CASES = [
    ("stability-k-scan-fcc",
     ["stability", "cubic_bspline", "fcc", "--kmin", "0.8", "--kmax", "1.6", "--steps", "2000", "--grid", "400"],
     3, "the stability scan over k asks for k samples x wave vectors = 128064000000, more than the limit of 100000000"),
    ("stability-k-scan-triangular",
     ["stability", "cubic_bspline", "triangular", "--kmin", "0.8", "--kmax", "1.6", "--steps", "2000", "--grid", "400"],
     3, "the stability scan over k asks for k samples x wave vectors = 320160000, more than the limit of 100000000"),
    # Stability counts its neighbour sums before it lists a neighbour: neighbours within the support
    # (the ball of radius R k over the volume per site, 1/sqrt(2) on fcc: 4/3 pi 120^3 sqrt(2) =
    # 10236402.3 at k = 60)
    # times the first grid's wave vectors (8^3 = 512 in 3D, or the path's points), at most 5e8; and at
    # most 4e6 neighbours are listed for one k (about 170 bytes each).
    ("stability-zone-scan-k-60", ["stability", "cubic_bspline", "fcc", "--k", "60", "--gamma", "1e-6"],
     3, "the stability zone scan asks for neighbours x wave vectors = 5241037973, more than the limit of 500000000; make it smaller"),
    ("stability-zone-scan-k-60-json", ["stability", "cubic_bspline", "fcc", "--k", "60", "--json"],
     3, "the stability zone scan asks for neighbours x wave vectors = 5241037973, more than the limit of 500000000"),
    ("stability-zone-scan-grid-400", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--grid", "400"],
     3, "the stability zone scan asks for neighbours x wave vectors = 5241037973, more than the limit of 500000000"),
    ("stability-neighbours-k-100", ["stability", "cubic_bspline", "fcc", "--k", "100", "--wavevector", "1,0,0"],
     3, "stability at k = 100 asks for neighbours within the support = 47390752, more than the limit of 4000000"),
    ("stability-path-k-6", ["stability", "cubic_bspline", "fcc", "--k", "6", "--path", "100000"],
     3, "the dispersion path asks for neighbours x wave vectors = 1023640229, more than the limit of 500000000"),
    ("stability-k-scan-to-100", ["stability", "cubic_bspline", "fcc", "--kmin", "1", "--kmax", "100", "--steps", "10"],
     3, "the stability scan over k asks for neighbours x wave vectors = 74005410032, more than the limit of 500000000"),
    # A k so small that h^3 underflows has no neighbour and an infinite density: the scan over k
    # called it "stable" with omega^2 = 0; refused like --k 1e-300 is.
    ("stability-k-1e-300", ["stability", "cubic_bspline", "fcc", "--kmin", "1e-300", "--kmax", "1e-299", "--steps", "2"],
     3, "k = 1e-300 is outside what this kernel and lattice fcc can be evaluated at: the SPH density is inf times rho0"),
    ("stability-k-1e-100",
     ["stability", "cubic_bspline", "fcc", "--kmin", "1e-100", "--kmax", "1e-99", "--steps", "2"],
     3, "k = 1e-100 is outside what this kernel and lattice fcc can be evaluated at"),
    # A tiny gamma overflowed 2/gamma: refused, and never a non-finite omega^2.
    ("stability-gamma-1e-320", ["stability", "cubic_bspline", "fcc", "--gamma", "1e-320", "--k", "1.2"],
     2, r"--gamma 1e-320 is not allowed, expected a number in \[1e-06, 1e\+06\]"),
    ("stability-gamma-1e-07", ["stability", "cubic_bspline", "fcc", "--gamma", "1e-7", "--kmin", "1", "--kmax", "1.2"],
     2, "--gamma 1e-07 is not allowed"),
    ("roots-gamma-1.1e6", ["roots", "cubic_bspline", "fcc", "--stability", "--gamma", "1.1e6"],
     2, "--gamma 1100000 is not allowed"),
    # pairing's work is counted before any motion, like stability's (k = 100 ran for minutes).
    ("pairing-k-100", ["pairing", "cubic_bspline", "triangular", "--k", "100", "--duration", "1"],
     3, r"pairing: the motion asks for .* pair evaluations over its 1 sample\(s\) of k, over the limit"),
    ("pairing-k-40", ["pairing", "cubic_bspline", "triangular", "--k", "40"], 3, "over the limit"),
]


@table(CASES)
def test_command_over_budget(args, code, pattern):
    expect(args, code, pattern)


def test_the_smallest_gamma_gives_finite_numbers():
    out = subprocess.run([CLI, "stability", "cubic_bspline", "fcc", "--gamma", "1e-6", "--k", "1.2"],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
    assert not re.search(r"nan|inf", out.stdout, re.I), out.stdout


def test_many_volume_coefficients_read_in_linear_time(tmp_path):
    # A lattice with 10^5 volume coefficients is read in linear time (the test only reads it).
    d = {"name": "t", "dimension": 2, "basis": [[1, 0], [0, 1]], "motif": [[0, 0]],
         "volume_coefficients": {"c%d" % i: 1.0 for i in range(100000)}}
    (tmp_path / "many_ap.json").write_text(json.dumps(d))
    expect(["eps", "cubic_bspline", str(tmp_path / "many_ap.json"), "--k", "1.2", "--ap", "c99999"], 0, r"^$")
