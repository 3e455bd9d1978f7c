"""Bad input to a run's series (`particles FILE FILE ...`, a folder), to `assess` on a particle
file (its sweep of a code's parameter, --threads, --neighbours-by), to the threads of assess,
roots and design on a lattice, and to the count options:
one line, the README's exit code (2 an option, 3 an input, 5 an output)."""
import pytest
from conftest import expect

LATTICE_CSV = "x,y\n" + "\n".join(f"{i}.5,{j}.5" for i in range(12) for j in range(12)) + "\n"


@pytest.fixture
def square(tmp_path):
    (tmp_path / "square.csv").write_text(LATTICE_CSV)
    return str(tmp_path / "square.csv")


ASSESS = ["assess", "cubic_bspline", "{csv}", "--box", "12,12", "--code", "pysph"]
PARTICLES = ["particles", "cubic_bspline", "{csv}", "--box", "12,12"]

CASES = [
    ("range-reversed", [*ASSESS, "--hdx-range", "1.6", "1.0"], 2, r"^sphkern: error: --hdx-range: \[1\.6, 1\]: expected min < max$"),
    ("range-negative", [*ASSESS, "--hdx-range", "-1", "1.0"], 2, r"^sphkern: error: --hdx-range -1: expected a number in \(0, 1000000\]$"),
    ("range-steps-zero", [*ASSESS, "--hdx-range", "1.0", "1.6", "--steps", "0"], 2, r"^sphkern: error: --steps 0, expected 1 to 100$"),
    ("range-other-code", [*ASSESS, "--eta-range", "1.0", "1.6"], 2,
     r"^sphkern: error: --eta-range sweeps eta; expected --code with that parameter \(pysph sets hdx\)$"),
    ("range-and-value", [*ASSESS, "--hdx", "1.2", "--hdx-range", "1.0", "1.6"], 2,
     r"^sphkern: error: --hdx-range sweeps the parameter; expected no single value beside it$"),
    ("range-on-lattice", ["assess", "cubic_bspline", "square", "--code", "pysph", "--hdx-range", "1.0", "1.6"], 2,
     r"^sphkern: error: --hdx-range is for a particle file; expected one, not a lattice$"),
    ("bias-correction-on-lattice", ["assess", "wendland_c2", "fcc", "--code", "gadget4", "--nngb", "64", "--bias-correction"],
     2, r"^sphkern: error: --bias-correction is for a particle file; expected one, not a lattice$"),
    ("bias-correction-stored-h", [*ASSESS, "--bias-correction"], 2,
     r"^sphkern: error: --bias-correction is the code's correction of its density solve; expected --code with its parameter"),
    ("threads-on-lattice-negative", ["assess", "cubic_bspline", "square", "--k", "1.2", "--threads", "-1"], 2,
     r"^sphkern: error: --threads -1, expected 0 to 1024$"),
    ("roots-threads-negative", ["roots", "cubic_bspline", "square", "--stability", "--threads", "-1"], 2,
     r"^sphkern: error: --threads -1, expected 0 to 1024$"),
    ("design-threads-too-many", ["design", "wendland_c2_shape", "fcc", "--param", "beta", "--threads", "2000"], 2,
     r"^sphkern: error: --threads 2000, expected 0 to 1024$"),
    ("threads-negative", [*ASSESS, "--hdx", "1.2", "--threads", "-1"], 2, r"^sphkern: error: --threads -1, expected 0 to 1024$"),
    ("neighbours-by-word", [*PARTICLES, "--code", "swift", "--eta", "1.2", "--neighbours-by", "weight"], 2,
     r"^sphkern: error: --neighbours-by weight: expected number or mass$"),
    ("neighbours-by-spacing-code", [*PARTICLES, "--code", "pysph", "--hdx", "1.2", "--neighbours-by", "mass"], 2,
     r"^sphkern: error: --code: pysph: PySPH sets h from the mean spacing, with no neighbour count; expected no count$"),
    ("series-sweep", [*PARTICLES, "{csv}", "--nh-range", "20", "40"], 2,
     r"^sphkern: error: --h-over-l-range and --nh-range sweep one file; a series measures each snapshot at one h"),
    ("series-lattice", [*PARTICLES, "fcc", "--nh", "40"], 2,
     r"^sphkern: error: fcc: a series is made of particle files \(and folders of them\)"),
    ("series-vtk-not-pvd", [*PARTICLES, "{csv}", "--nh", "40", "--vtk", "{dir}/out.vtu"], 2,
     r"^sphkern: error: --vtk .*out\.vtu: a series is written as a ParaView collection; expected NAME\.pvd"),
    ("series-missing-file", [*PARTICLES, "{dir}/none.csv", "--nh", "40"], 3, r"none\.csv"),
    ("series-empty-folder", ["particles", "cubic_bspline", "{dir}/empty", "--nh", "40"], 3,
     r"^sphkern: error: .*empty: the folder holds no particle file; expected snapshots"),
    ("series-plot-folder", [*PARTICLES, "{csv}", "--nh", "40", "--plot", "{dir}/empty"], 2,
     r"^sphkern: error: --plot .*empty: expected a figure file ending in \.svg, \.png or \.pdf$"),
    ("series-csv-is-input", [*PARTICLES, "{dir}/copy.csv", "--nh", "40", "--csv", "{csv}"], 5, r"^sphkern: error: --csv"),
]


@pytest.mark.parametrize("name, args, code, pattern", CASES, ids=[c[0] for c in CASES])
def test_bad_input(tmp_path, square, name, args, code, pattern):
    (tmp_path / "empty").mkdir()
    (tmp_path / "copy.csv").write_text(LATTICE_CSV)
    expect([a.format(csv=square, dir=tmp_path) for a in args], code, pattern)
