"""Command-line values: a value out of its range, of the wrong form or missing exits 2 naming the
option; a value the lattice or kernel cannot take exits 3. One line each, never a crash."""
from conftest import expect, fill, table

CASES = [
    # Command-line values.
    ("shells-fcc", ["shells", "fcc"], 2, "error: "),
    ("frobnicate", ["frobnicate"], 2, "error: "),
    ("eps-k-neg1", ["eps", "cubic_bspline", "fcc", "--k", "-1"], 2, "--k -1 is not allowed"),
    ("eps-gravity-0-0-0", ["eps", "cubic_bspline", "fcc", "--k", "1", "--gravity", "0,0,0"],
     2, "--gravity: expected a direction: finite components, not all zero"),
    ("eps-gravity-0-1", ["eps", "cubic_bspline", "fcc", "--k", "1", "--gravity", "0,-1"],
     3, r"--gravity: 2 components, expected 3 \(one per dimension\)"),
    ("eps-ap-neg1", ["eps", "cubic_bspline", "fcc", "--k", "1", "--ap", "-1"], 3, "a_p = -1 is not allowed"),
    ("eps-ap-hexagon", ["eps", "cubic_bspline", "triangular", "--k", "1", "--ap", "hexagon"],
     3, 'no volume coefficient "hexagon"'),
    ("eps-composite-on-fcc", ["eps", "composite", "fcc", "--k", "1"],
     3, "composite is defined in 2D only, not on the 3D lattice fcc"),
    ("eps-unknown-kernel", ["eps", "cubic", "fcc", "--k", "1"], 3, 'unknown kernel "cubic";'),
    ("roots-kmin-1.2-kmax-0.8", ["roots", "cubic_bspline", "fcc", "--kmin", "1.2", "--kmax", "0.8"], 2, "min < max"),
    ("roots-kmin-0-kmax-0.8", ["roots", "cubic_bspline", "fcc", "--kmin", "0", "--kmax", "0.8"], 2, "min < max"),
    ("roots-shells-1-1.5", ["roots", "cubic_bspline", "triangular", "--shells", "1,1.5"],
     3, "no neighbour shell at radius 1.5 d"),
    ("roots-continue-past-support", ["roots", "cubic_bspline", "triangular", "--continue-past-support"],
     2, "needs an explicit --shells"),
    ("eps-set-x", ["eps", "cubic_bspline", "fcc", "--k", "1", "--set", "x"], 2, "--set x: expected NAME=VALUE"),
    ("eps-set-alpha-1", ["eps", "cubic_bspline", "fcc", "--k", "1", "--set", "alpha=1"], 3, 'has no parameter "alpha"'),
    # Surface profiles and particle blocks.
    ("surface-gravity-1.4142-1", ["surface", "cubic_bspline", "triangular", "--k", "1.2", "--gravity", "1.4142,-1"],
     3, "not normal to a family of lattice planes"),
    ("surface-form-up", ["surface", "cubic_bspline", "fcc", "--k", "1.2", "--form", "up"],
     3, 'gradient form "up" is unknown'),
    ("block-size-0-10-10", ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "0,10,10"],
     3, "positive number of cells"),
    ("block-size-neg4-10-10", ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "-4,10,10"],
     3, "positive number of cells"),
    ("block-size-100000-100000-100000",
     ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "100000,100000,100000"],
     3, "more than the limit of"),
    ("block-size-10-10", ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "10,10"],
     3, "--size 10,10: the lattice is 3D, expected 3 cell counts"),
    ("block-size-10-x-10", ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "10,x,10"],
     2, r"expected N1,N2\[,N3\] integers"),
    ("block-periodic", ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "3,3,3", "--periodic"],
     3, "a periodic block needs more than"),
    ("surface-layers-0", ["surface", "cubic_bspline", "fcc", "--k", "1.2", "--layers", "0"],
     2, "^sphkern: error: --layers 0, expected 1 to 10000$"),
    ("eps-site-5", ["eps", "cubic_bspline", "fcc", "--k", "1", "--site", "5"],
     3, "--site: site 5 does not exist; lattice fcc has sites 0 to 0"),
    ("roots-epsilon-2", ["roots", "cubic_bspline", "fcc", "--epsilon", "2"], 2, r"--epsilon must be in \(0, 1\)"),
    ("block-threads-neg1", ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "4,4,4", "--threads", "-1"],
     2, "error: --threads -1, expected 0 to 1024$"),
    ("check-timeout-0", ["check", "cubic_bspline", "--timeout", "0"], 2, "error: --timeout 0, expected 0.1 to 3600$"),
    # Each value is checked once, by its request, naming the option.
    ("surface-k-neg1", ["surface", "cubic_bspline", "fcc", "--k", "-1"],
     2, r"error: --k -1 is not allowed, expected a number in \(0, 100\]$"),
    # surface takes a code's setting as eps does (the k itself: a check case below)
    ("surface-without-k", ["surface", "cubic_bspline", "fcc"],
     2, r"^sphkern: error: --k is required \(or --code and the code's setting\)$"),
    ("surface-k-and-eta", ["surface", "wendland_c2", "fcc", "--k", "1", "--code", "swift", "--eta", "1.2"],
     2, "give one of --k and --eta"),
    ("surface-eta-without-code", ["surface", "wendland_c2", "fcc", "--eta", "1.2"],
     2, "--eta is a code's setting; expected --code too"),
    ("block-k-neg1", ["block", "cubic_bspline", "fcc", "--k", "-1", "--size", "4,4,4"],
     2, r"error: --k -1 is not allowed, expected a number in \(0, 100\]$"),
    ("spectrum-dim-4", ["spectrum", "cubic_bspline", "--dim", "4"], 2, "error: --dim 4, expected 1 to 3$"),
    ("spectrum-k-0", ["spectrum", "cubic_bspline", "--dim", "3", "--k", "0"],
     2, "error: --k 0, expected 0.001 to 100$"),
    ("spectrum-max-0", ["spectrum", "cubic_bspline", "--dim", "3", "--max", "0"],
     2, "error: --max 0, expected 0.1 to 1000$"),
    ("spectrum-points-0", ["spectrum", "cubic_bspline", "--dim", "3", "--points", "0"],
     2, "error: --points 0, expected 1 to 100000$"),
    ("design-site-3", ["design", "cubic_bspline+desbrun_spiky", "triangular", "--param", "alpha", "--site", "3"],
     3, "error: --site: site 3 does not exist; lattice triangular has sites 0 to 0$"),
    ("eps-h_over_l-60-is-k-120", ["eps", "cubic_bspline", "fcc", "--axis", "h_over_l", "--k", "60", "--ap", "8"],
     3, r"error: k = 120 is not allowed, expected a number in \(0, 100\] \(--k 60 on the h_over_l axis\)$"),
    ("eps-axis-eta", ["eps", "cubic_bspline", "fcc", "--axis", "eta", "--k", "1.2"],
     3, r'^sphkern: error: --axis "eta" is the old name of sphkern.s own h / V\^\(1/D\); expected h_over_l \(SWIFT.s eta is a code.s setting: --code swift --eta\)$'),
    ("stability-steps-0", ["stability", "cubic_bspline", "fcc", "--kmin", "1", "--kmax", "1.2", "--steps", "0"],
     2, "error: --steps 0, expected 1 to 2000$"),
    ("stability-grid-1", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--grid", "1"],
     2, "error: --grid 1, expected 2 to 400$"),
    ("stability-grid-0", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--grid", "0"],
     2, "error: --grid 0, expected 2 to 400$"),
    ("stability-path-0", ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--path", "0"],
     2, "error: --path 0, expected 2 to 100000$"),
    ("stability-kmin-kmax-with-wavevector",
     ["stability", "cubic_bspline", "fcc", "--kmin", "1", "--kmax", "1.2", "--wavevector", "1,0,0"],
     2, "error: --kmin and --kmax go together, without --k, --wavevector or --path$"),
    ("design-param-beta", ["design", "cubic_bspline", "fcc", "--param", "beta"],
     3, 'kernel cubic_bspline has no parameter "beta"'),
]


@table(CASES)
def test_command_line_value(args, code, pattern):
    expect(fill(args), code, pattern)


def test_block_writes_every_cell(tmp_path):
    expect(["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "4,4,4", "--vtk", str(tmp_path)], 5, r"is a folder")
    expect(["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "8,8,8", "--periodic", "--vtk",
            str(tmp_path / "b.vtk"), "--csv", str(tmp_path / "b.csv")], 0, r"^$")
    assert len((tmp_path / "b.csv").read_text().splitlines()) == 513
    assert "SCALARS eps_gradp double 1" in (tmp_path / "b.vtk").read_text()


# Values the parser would read as something else: refused by name.
PARSER_CASES = [
    ("log-level-verbose", ["--log-level", "verbose", "kernels"], 2, "--log-level: verbose not in"),
    ("eps-k-empty", ["eps", "cubic_bspline", "fcc", "--k", ""], 2, "--k: an empty value"),
    ("surface-termination-neg2", ["surface", "cubic_bspline", "fcc", "--k", "1.2", "--termination", "-2"],
     2, "--termination: Value -2 not in range|--termination.*-2"),
    ("eps-set-beta-2", ["eps", "wendland_c2_shape", "fcc", "--k", "1.2", "--set", "beta=1", "--set", "beta=2"],
     2, "--set beta is given twice"),
    ("block-k-1e-300", ["block", "cubic_bspline", "fcc", "--k", "1e-300", "--size", "4,4,4"],
     3, "k = 1e-300 is outside what kernel cubic_bspline can be evaluated at"),
]


@table(PARSER_CASES)
def test_value_the_parser_would_misread(args, code, pattern):
    expect(args, code, pattern)


# One rule for every command: an option's value outside its range exits 2, naming the option.
ONE_RULE_CASES = [
    ("eps-k-neg1-named", ["eps", "cubic_bspline", "fcc", "--k", "-1"], 2, "^sphkern: error: --k -1"),
    ("roots-kmax-1", ["roots", "cubic_bspline", "fcc", "--kmin", "2", "--kmax", "1"], 2, "^sphkern: error: --kmin"),
    ("stability-kmax-2-steps-0", ["stability", "cubic_bspline", "fcc", "--kmin", "1", "--kmax", "2", "--steps", "0"],
     2, "^sphkern: error: --steps 0"),
    ("particles-h-over-l-0", ["particles", "cubic_bspline", "poisson", "--count", "1000", "--h-over-l", "0"],
     2, "^sphkern: error: --h-over-l 0"),
    ("particles-rho0-neg1", ["particles", "cubic_bspline", "poisson", "--count", "1000", "--rho0", "-1"],
     2, "^sphkern: error: --rho0 -1"),
    ("particles-histogram-100001",
     ["particles", "cubic_bspline", "poisson", "--count", "1000", "--histogram", "100001"],
     2, "^sphkern: error: --histogram 100001"),
    ("relax-dt-0.6", ["relax", "wendland_c2", "poisson", "--count", "500", "--dt", "0.6"],
     2, "^sphkern: error: --dt 0.6"),
    ("relax-rdf-bins-0", ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "1", "--rdf-bins", "0"],
     2, "^sphkern: error: --rdf-bins 0, expected 1 to 100000"),
    ("relax-rdf-bins-100001",
     ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "1", "--rdf-bins", "100001"],
     2, "^sphkern: error: --rdf-bins 100001, expected 1 to 100000"),
    ("relax-rdf-max-0", ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "1", "--rdf-max", "0"],
     2, "^sphkern: error: --rdf-max 0: expected a finite number above 0.5"),
    ("relax-rdf-max-nan", ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "1", "--rdf-max", "nan"],
     2, "^sphkern: error: --rdf-max nan: expected a finite number above 0.5"),
    ("pairing-noise-0", ["pairing", "cubic_bspline", "fcc", "--k", "1.2", "--noise", "0"],
     2, "^sphkern: error: --noise 0"),
]


@table(ONE_RULE_CASES)
def test_one_rule_for_every_command(args, code, pattern):
    expect(args, code, pattern)
