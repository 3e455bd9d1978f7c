"""What each SPH code can run, as its profile (core/codes/<code>/) says: its dimensions and its
kernels per dimension (exit 2 naming what it has), and a setting below the one a particle with
no neighbour inside its support has (exit 2, naming the option, before any sum)."""
import pytest
from conftest import expect

CASES = [
    # Phantom is 3D only; SPlisHSPlasH's 2D simulation has the cubic and Wendland C2 only.
    ("phantom-2d", ["eps", "cubic_bspline", "triangular", "--code", "phantom", "--hfact", "1.2"], 2,
     r"^sphkern: error: cubic_bspline: phantom runs in 3D only, not in 2D$"),
    ("phantom-2d-particles", ["particles", "cubic_bspline", "poisson", "--count", "500", "--dim", "2", "--code",
                              "phantom", "--hfact", "1.2"], 2, r"phantom runs in 3D only, not in 2D$"),
    ("splishsplash-poly6-2d", ["eps", "muller_poly6", "square", "--code", "splishsplash", "--particle-radius", "0.5"], 2,
     r"^sphkern: error: muller_poly6: splishsplash has it in 3D only; its kernels in 2D are cubic_bspline, wendland_c2$"),
    ("splishsplash-spiky-3d", ["eps", "desbrun_spiky", "fcc", "--code", "splishsplash", "--particle-radius", "0.5"], 0, r"^$"),
    ("gadget2-wendland", ["eps", "wendland_c2", "fcc", "--code", "gadget2", "--nngb", "48"], 2,
     r"^sphkern: error: wendland_c2: gadget2 does not ship it; its kernels are cubic_bspline$"),
    ("pysph-2d-super-gaussian", ["eps", "pysph_super_gaussian", "square", "--code", "pysph", "--hdx", "1.2"], 0, r"^$"),
    # A setting below a lone particle's: refused before the density solve (round 5, item 1).
    ("swift-eta-below-lone", ["particles", "wendland_c2", "poisson", "--count", "2000", "--code", "swift", "--eta", "0.5"],
     2, r"^sphkern: error: --eta: 0\.5: expected more than 0\.77\d+, the eta of a particle with no neighbour inside its support"),
    ("swift-eta-tiny", ["particles", "wendland_c2", "poisson", "--count", "2000", "--code", "swift", "--eta", "0.01"], 2,
     r"^sphkern: error: --eta: 0\.01: expected more than 0\.77"),
    ("phantom-hfact-below-lone", ["particles", "cubic_bspline", "poisson", "--count", "2000", "--code", "phantom",
                                  "--hfact", "0.3"], 2, r"^sphkern: error: --hfact: 0\.3: expected more than 0\.68\d+, the hfact"),
    ("gadget2-nngb-below-lone", ["particles", "cubic_bspline", "poisson", "--count", "2000", "--code", "gadget2",
                                 "--nngb", "5"], 2, r"^sphkern: error: --nngb: 5: expected more than 10\.66\d+, the nngb"),
    ("relax-eta-below-lone", ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "2", "--code", "swift",
                              "--eta", "0.5", "--output", "/nonexistent-folder/ic.hdf5"], 2, r"--eta: 0\.5: expected more than"),
    # Phantom starts from its own full dumps (any name but .csv, .h5, .hdf5), only Phantom does.
    ("relax-phantom-hdf5", ["relax", "cubic_bspline", "poisson", "--count", "300", "--steps", "2", "--code", "phantom",
                            "--hfact", "1.2", "--output", "/nonexistent-folder/ic.hdf5"], 2,
     r"^sphkern: error: --output /nonexistent-folder/ic\.hdf5: Phantom starts from its own full dumps, not HDF5; "
     r"expected a name without \.h5 or \.hdf5 \(NAME_00000\.tmp\) or one ending in \.csv$"),
    ("relax-dump-name-without-phantom", ["relax", "cubic_bspline", "poisson", "--count", "300", "--steps", "2", "--code",
                                         "gadget2", "--output", "/nonexistent-folder/ic_00000.tmp"], 2,
     r"^sphkern: error: --output /nonexistent-folder/ic_00000\.tmp: expected a name ending in \.h5, \.hdf5 or \.csv "
     r"\(with --code phantom, any other name: a Phantom full dump\)$"),
    ("relax-phantom-dump-parallelepiped", ["relax", "cubic_bspline", "fcc", "--size", "4,4,4", "--k", "1.2", "--steps", "2",
                                           "--code", "phantom", "--output", "/nonexistent-folder/ic_00000.tmp"], 3,
     r"^sphkern: error: fcc: the periodic box is a parallelepiped, not a rectangular box; --output "
     r"/nonexistent-folder/ic_00000\.tmp stores three sides .*; --cell rectangular cuts the block"),
    ("relax-phantom-dump-unwritable", ["relax", "cubic_bspline", "poisson", "--count", "300", "--steps", "2", "--code",
                                       "phantom", "--output", "/nonexistent-folder/ic_00000.tmp"], 5,
     r"^sphkern: error: /nonexistent-folder/ic_00000\.tmp: cannot be written"),
]


@pytest.mark.parametrize("args,code,pattern", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_code_case(args, code, pattern):
    expect(args, code, pattern)


def test_gadget_initial_conditions_end_in_hdf5(tmp_path):
    expect(["relax", "cubic_bspline", "poisson", "--count", "300", "--steps", "2", "--code", "gadget2", "--output",
            str(tmp_path / "ic.h5")], 2, r"gadget2: GADGET opens <InitCondFile>\.hdf5 .*expected a name ending in \.hdf5")
    assert not (tmp_path / "ic.h5").exists()


def test_weakly_compressible_codes_stability_assumes_their_rest_pressure():
    import json
    from conftest import run
    done = run(["assess", "wendland_c2", "sc", "--code", "dualsphysics", "--coefh", "1.0", "--json"])
    assert done.returncode == 0, done.stderr
    pressure = json.loads(done.stdout)["pressure"]
    assert pressure["model"] == "tait" and pressure["coef_sound"] == 20 and pressure["p0_over_rho_c2"] == 1 / 400
    done = run(["assess", "wendland_c2", "sc", "--code", "dualsphysics", "--coefh", "1.0", "--coef-sound", "10"])
    assert done.returncode == 0, done.stderr
    assert "Tait's pressure at rest (DualSPHysics): hydrostatic, up to rho c^2 / 100" in done.stdout
    swift = run(["assess", "wendland_c2", "sc", "--code", "swift", "--eta", "1.2", "--json"])
    assert json.loads(swift.stdout)["pressure"] == {"model": "ideal_gas", "gamma": 5 / 3,
                                                    "text": "an ideal gas at rest, P0 / rho = c^2 / gamma (gamma = 1.66667)"}
    expect(["assess", "wendland_c2", "sc", "--code", "swift", "--eta", "1.2", "--coef-sound", "10"], 2,
           r"^sphkern: error: --coef-sound: 10: the sound speed over sqrt\(g H\) of a weakly compressible code")


def test_a_setting_past_the_lattices_reach_names_the_option():
    expect(["eps", "wendland_c2", "fcc", "--code", "swift", "--eta", "100"], 2,
           r"^sphkern: error: --eta: 100: its k, about 86\.\d+, is more than the lattice's sums can reach")


def test_a_k_without_neighbours_says_so_in_assess():
    expect(["assess", "wendland_c2", "fcc", "--k", "0.2"], 3,
           r"^sphkern: error: k = 0\.2: no neighbour lies inside the support, so no SPH force holds a particle")


def test_coef_sound_out_of_range_names_the_option():
    for value in ("0.5", "2000", "nan"):
        expect(["assess", "wendland_c2", "sc", "--code", "dualsphysics", "--coefh", "1.0", "--coef-sound", value], 2,
               r"^sphkern: error: --coef-sound: .*: expected a number in \[1, 1000\]$")
