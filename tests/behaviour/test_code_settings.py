"""A code's own setting (--code with --eta, --hfact, --nngb, --hdx, --particle-radius): given
only with --code, alone, for a kernel the code ships, refused as eps refuses it in every command;
the k it gives is the k eps --code finds, in surface, particles, pairing, stability and roots."""

import pytest
from conftest import expect, fill, json_of, table, text_of

SETTING = ["wendland_c2", "fcc", "--code", "swift", "--eta", "1.2348"]




def test_surface_runs_at_eps_k():
    # surface --code: the k eps --code finds for the same setting, named with the code in the text.
    eps, surface = json_of("eps", *SETTING, "--json"), json_of("surface", *SETTING, "--json")
    assert surface["k"] == eps["k"] and surface["code"] == eps["code"], (surface["k"], eps["k"])
    assert "(swift eta = 1.2348)" in text_of("surface", *SETTING).splitlines()[0]


def test_particles_on_a_block_every_h_is_eps_k():
    eps = json_of("eps", *SETTING, "--json")
    p = json_of("particles", "wendland_c2", "fcc", "--size", "6,6,6", "--code", "swift", "--eta", "1.2348", "--json")
    assert abs(p["h_min"] / eps["k"] - 1) < 1e-9 and abs(p["h_max"] / eps["k"] - 1) < 1e-9, (p["h_min"], p["h_max"], eps["k"])
    assert p["code"]["h_from"] == "sph_density", p["code"]


def test_pairing_runs_at_eps_k():
    eps, pairing = json_of("eps", *SETTING, "--json"), json_of("pairing", *SETTING, "--duration", "5", "--json")
    assert [p["k"] for p in pairing["points"]] == [eps["k"]] and pairing["code"] == eps["code"], pairing["code"]


# A code's own setting (eps --code): given only with --code, alone, for a kernel the code ships.
CASES = [
    ("eps-eta-without-code", ["eps", "wendland_c2", "fcc", "--eta", "1.2"],
     2, "^sphkern: error: --eta is a code.s setting; expected --code too"),
    ("eps-swift-hdx", ["eps", "wendland_c2", "fcc", "--code", "swift", "--hdx", "1.2"],
     2, "^sphkern: error: --hdx: swift sets its resolution with --eta"),
    ("eps-eta-and-k", ["eps", "wendland_c2", "fcc", "--code", "swift", "--eta", "1.2", "--k", "1"],
     2, "^sphkern: error: give one of --k and --eta"),
    ("eps-code-misspelt", ["eps", "wendland_c2", "fcc", "--code", "swfit", "--eta", "1.2"],
     2, r'^sphkern: error: --code: "swfit" is unknown, expected one of swift, phantom, gadget2, gadget4, pysph, dualsphysics, splishsplash \(did you mean "swift"\?\)'),
    ("eps-gadget2-wendland_c2", ["eps", "wendland_c2", "fcc", "--code", "gadget2", "--nngb", "48"],
     2, "^sphkern: error: wendland_c2: gadget2 does not ship it; its kernels are cubic_bspline"),
    ("eps-eta-0", ["eps", "wendland_c2", "fcc", "--code", "swift", "--eta", "0"],
     2, r"^sphkern: error: --eta 0: expected a number in \(0, 100\]"),
    ("eps-swift-without-eta", ["eps", "wendland_c2", "fcc", "--code", "swift"],
     2, "^sphkern: error: --code swift: expected its setting, --eta"),
    ("eps-eta-below-lone-particle", ["eps", "wendland_c2", "fcc", "--code", "swift", "--eta", "0.3"],
     2, "^sphkern: error: --eta: 0.3: expected more than 0.772083, the eta of a particle with no neighbour inside its support"),
    ("eps-code-and-axis", ["eps", "wendland_c2", "fcc", "--code", "swift", "--eta", "1.2", "--axis", "eta"],
     2, "^sphkern: error: --axis is the scale of --k; --code gives the code.s own setting"),
    ("eps-swift-eta-1.2348", ["eps", "wendland_c2", "fcc", "--code", "swift", "--eta", "1.2348"], 0, "^$"),
    ("roots-splishsplash", ["roots", "wendland_c2", "fcc", "--code", "splishsplash"],
     3, r"^sphkern: error: splishsplash: its particle radius fixes the particle volume too \(0.8 \(2 r\)\^D\), which a window of k"),
    ("assess-splishsplash",
     ["assess", "wendland_c2", "fcc", "--code", "splishsplash", "--particle-radius", "0.5"],
     3, "^sphkern: error: splishsplash: .*which the window of the recommended setting"),
    ("pairing-splishsplash",
     ["pairing", "wendland_c2", "fcc", "--code", "splishsplash", "--particle-radius", "0.5"],
     3, "^sphkern: error: splishsplash: .*which the motion of a lattice block cannot take"),
    ("particles-splishsplash", ["particles", "wendland_c2", "poisson", "--count", "500", "--code", "splishsplash"],
     3, "^sphkern: error: splishsplash: .*which a particle set cannot take"),
    ("eps-particle-radius-without-code", ["eps", "wendland_c2", "fcc", "--particle-radius", "0.5"],
     2, "^sphkern: error: --particle-radius is a code.s setting; expected --code too$"),
    ("eps-splishsplash-morris_quintic",
     ["eps", "morris_quintic", "fcc", "--code", "splishsplash", "--particle-radius", "0.5"],
     2, "^sphkern: error: morris_quintic: splishsplash does not ship it; its kernels are cubic_bspline, wendland_c2, muller_poly6, desbrun_spiky$"),
    ("eps-splishsplash-radius-neg1", ["eps", "wendland_c2", "fcc", "--code", "splishsplash", "--particle-radius", "-1"],
     2, r"^sphkern: error: --particle-radius -1: expected a number in \(0, 100\]$"),
    # assess: one verdict; its setting refused as eps refuses it.
    ("assess-without-k", ["assess", "wendland_c2", "fcc"],
     2, r"^sphkern: error: --k is required \(or --code and the code.s setting\)"),
    ("assess-epsilon-2", ["assess", "wendland_c2", "fcc", "--k", "1.2", "--epsilon", "2"],
     2, r"^sphkern: error: --epsilon: 2: expected a number in \(0, 1\)"),
    ("assess-gadget2-wendland_c2", ["assess", "wendland_c2", "fcc", "--code", "gadget2", "--nngb", "48"],
     2, "^sphkern: error: wendland_c2: gadget2 does not ship it"),
    # assess on a particle file: a code's setting, checked as particles checks it.
    ("assess-file-epsilon-2",
     ["assess", "wendland_c2", "{w}/free.csv", "--code", "swift", "--eta", "1.2", "--epsilon", "2"],
     2, r"^sphkern: error: --epsilon: 2: expected a number in \(0, 1\)"),
    ("assess-file-swift-without-eta", ["assess", "wendland_c2", "{w}/free.csv", "--code", "swift"],
     3, "free.csv: the set stores no h; with --code swift, expected --eta too"),
    ("assess-file-swift-nngb", ["assess", "wendland_c2", "{w}/free.csv", "--code", "swift", "--nngb", "40"],
     2, "^sphkern: error: --nngb: swift sets its resolution with --eta$"),
    ("assess-missing-file", ["assess", "wendland_c2", "{w}/missing.csv", "--code", "swift", "--eta", "1.2"],
     3, "^sphkern: error: .*missing.csv"),
    ("stability-code-without-window", ["stability", "wendland_c2", "fcc", "--k", "1.2", "--code", "swift"],
     2, "^sphkern: error: --code gives the stable intervals over k in a code.s setting; expected --kmin and --kmax"),
    ("roots-gadget2-wendland_c2", ["roots", "wendland_c2", "fcc", "--code", "gadget2"],
     2, "^sphkern: error: wendland_c2: gadget2 does not ship it; its kernels are cubic_bspline"),
]


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    folder = tmp_path_factory.mktemp("code")
    (folder / "free.csv").write_text("x,y\n0.1,0.2\n0.5,0.7\n0.9,0.3\n")
    return folder


@table(CASES)
def test_code_setting(work, args, code, pattern):
    expect(fill(args, work), code, pattern)


def test_splishsplash_radius_sets_k_and_volume():
    # SPlisHSPlasH: its particle radius sets the support 4 r and the volume 0.8 (2 r)^D, so on sc at r = d / 2
    # (its own sampling) eps --code is eps at k = 4 r / R with a_p = 0.8; the commands that keep the
    # lattice's volume refuse it (the table above).
    a = json_of("eps", "wendland_c2", "sc", "--code", "splishsplash", "--particle-radius", "0.5", "--json")
    b = json_of("eps", "wendland_c2", "sc", "--k", "1", "--ap", "0.8", "--json")
    assert a["k"] == 1 and a["a_p"] == 0.8 and a["code"]["a_p"] == 0.8
    assert a["eps_rho"] == b["eps_rho"] and a["eps_gradp"] == b["eps_gradp"]
    first = text_of("surface", "wendland_c2", "sc", "--code", "splishsplash", "--particle-radius", "0.5").splitlines()[0]
    assert "a_p = 0.8," in first, first


def test_assess_ends_with_one_line_a_person_can_act_on():
    last = text_of("assess", *SETTING).splitlines()[-1]
    assert last == ("swift eta 1.2348 with wendland_c2 on fcc: stable, inaccurate (|eps_gradP| 0.0205 > 0.01); "
                    "recommended eta 1.7 (1.68 to 1.71, N_H 140 to 140; narrow: +-0.81% in h, less than the +-2% a relaxed glass's h spans)"), last


def test_stability_intervals_in_swifts_eta():
    out = text_of("stability", "wendland_c2", "fcc", "--kmin", "0.9", "--kmax", "2.0", "--steps", "3", "--code", "swift")
    assert "for eta in [1.18311, 1.26521] [1.68359, 1.71112]" in out, out


def test_roots_recommended_eta_is_the_recommended_k():
    # roots --code: the recommended setting, given back to eps --code, is the recommended k.
    r = json_of("roots", "cubic_bspline", "fcc", "--stability", "--code", "swift", "--json")
    doc = r[0] if isinstance(r, list) else r
    eta, k = doc["code"]["recommended"], doc["stability"]["recommended"]["k"]
    e = json_of("eps", "cubic_bspline", "fcc", "--code", "swift", "--eta", repr(eta), "--json")
    assert abs(e["k"] - k) < 1e-9, (e["k"], k)
