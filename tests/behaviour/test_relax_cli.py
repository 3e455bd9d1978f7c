"""relax and pairing: every setting out of range is one line and exit 2, as for every option;
what relax writes (SWIFT's layout, a CSV with its box, --history, --tile, a block cut from the
rectangular cell, a code's h) reads back."""
import re

import h5py
import pytest
from conftest import expect, fill, text_of, write

COMMON = {"free.csv": "x,y\n0.1,0.2\n0.5,0.7\n0.9,0.3\n"}

CASES = [
    ("relax-steps-0", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "0"],
     2, "--steps 0, expected 1 to 10000000"),
    ("relax-tolerance-neg1", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--tolerance", "-1"],
     2, r"--tolerance -1: expected a number in \[0, 1\]"),
    ("relax-dt-0.9", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--dt", "0.9"],
     2, r"--dt 0.9: expected a number in \(0, 0.5\]"),
    ("relax-damping-neg1", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--damping", "-1"],
     2, r"--damping -1: expected a number in \[0, 100\]"),
    ("relax-alpha-0", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--method", "shift", "--alpha", "0"],
     2, r"--alpha 0: expected a number in \(0, 10\]"),
    ("relax-max-move-1", {},
     ["relax", "wendland_c2", "poisson", "--count", "500", "--method", "shift", "--max-move", "1"],
     2, r"--max-move 1: expected a number in \(0, 0.5\]"),
    ("relax-gamma-0", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--gamma", "0"],
     2, r"--gamma 0: expected a number in \(0, 1000\]"),
    ("relax-method-jiggle", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--method", "jiggle"],
     2, '--method: "jiggle" is unknown, expected pressure or shift'),
    ("relax-h-over-l-and-nh", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--h-over-l", "1.2", "--nh", "50"],
     2, "give one of --h-over-l, --nh and --k"),
    ("relax-eta-1.2", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--eta", "1.2"],
     2, "^sphkern: error: --eta is SWIFT's eta"),
    ("relax-free-without-box", {}, ["relax", "wendland_c2", "{w}/free.csv"],
     3, "free.csv: relaxation needs a periodic box"),
    ("relax-block-below-twice-support", {}, ["relax", "wendland_c2", "sc", "--size", "4,4,4", "--k", "1.5"],
     3, "less than twice the support radius"),
    ("relax-output-txt", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--output", "{w}/glass.txt"],
     2, "expected a name ending in .h5, .hdf5 or .csv"),
    ("relax-output-parallelepiped", {},
     ["relax", "wendland_c2", "fcc", "--size", "8,8,8", "--k", "1.2", "--output", "{w}/glass.h5"],
     3, "a parallelepiped, not a rectangular box"),
    ("relax-output-and-history-same", {},
     ["relax", "wendland_c2", "poisson", "--count", "500", "--output", "{w}/g.csv", "--history", "{w}/g.csv"],
     5, "names the same file"),
    # A lattice block cut from the lattice's rectangular cell: written where the primitive cell's block is refused.
    ("relax-output-primitive-cell", {},
     ["relax", "wendland_c2", "fcc", "--size", "8,8,8", "--k", "1.2", "--steps", "1", "--output", "{w}/fcc_p.h5"],
     3, "; --cell rectangular cuts the block from the lattice.s rectangular cell$"),
    ("particles-cell-cubic", {},
     ["particles", "cubic_bspline", "fcc", "--size", "6,6,6", "--k", "1.2", "--cell", "cubic"],
     2, '^sphkern: error: --cell: "cubic" is unknown, expected primitive or rectangular'),
    ("particles-poisson-cell", {},
     ["particles", "cubic_bspline", "poisson", "--count", "500", "--cell", "rectangular"],
     2, "^sphkern: error: --cell is the cell of a lattice block; poisson is not a lattice"),
    # relax --code: the code the written set is for, and with its parameter the run's h.
    ("relax-hfact-without-code", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--hfact", "1.2"],
     2, "^sphkern: error: --hfact is a code.s setting; expected --code too$"),
    ("relax-swift-nngb", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--code", "swift", "--nngb", "50"],
     2, "^sphkern: error: --nngb: swift sets its resolution with --eta$"),
    ("relax-swift-eta-and-nh", {},
     ["relax", "wendland_c2", "poisson", "--count", "500", "--code", "swift", "--eta", "1.2", "--nh", "50"],
     2, "^sphkern: error: --code swift sets h with --eta; expected no --h-over-l, --nh or --k beside it$"),
    ("relax-code-alone", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--code", "swift"],
     2, "^sphkern: error: --code: swift: names the code the written set is for, or with --eta sets h; expected an output or --eta$"),
    ("relax-eta-neg1", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--code", "swift", "--eta", "-1"],
     2, r"^sphkern: error: --eta -1: expected a number in \(0, 100\]$"),
    ("relax-code-gadget", {},
     ["relax", "cubic_bspline", "poisson", "--count", "500", "--code", "gadget", "--output", "{w}/c1.hdf5"],
     2, '^sphkern: error: --code: "gadget" is unknown'),
    ("relax-gadget2-wendland_c2", {},
     ["relax", "wendland_c2", "poisson", "--count", "500", "--code", "gadget2", "--output", "{w}/c2.hdf5"],
     2, "^sphkern: error: wendland_c2: gadget2 does not ship it; its kernels are cubic_bspline$"),
    # Copies of the relaxed set side by side: bad counts refused.
    ("relax-tile-0-1-1", {},
     ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "1", "--output", "{w}/t0.csv", "--tile", "0,1,1"],
     2, "^sphkern: error: --tile: 0,1,1: expected whole numbers of copies from 1 to 1000"),
    ("relax-tile-without-output", {}, ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "1", "--tile", "2,2,2"],
     2, "^sphkern: error: --tile copies the set --output writes; expected --output too"),
    ("relax-tile-2-2", {},
     ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "1", "--output", "{w}/t1.csv", "--tile", "2,2"],
     3, "^sphkern: error: --tile 2,2: 2 counts for a set in 3 dimensions; expected 3"),
    ("relax-tile-1000-1000-1000", {},
     ["relax", "wendland_c2", "poisson", "--count", "500", "--steps", "1", "--output", "{w}/t2.csv", "--tile", "1000,1000,1000"],
     3, "more than the memory budget holds"),
    ("pairing-without-k", {}, ["pairing", "cubic_bspline", "fcc"], 2, "give --k, or --kmin and --kmax"),
    ("pairing-k-and-kmin", {}, ["pairing", "cubic_bspline", "fcc", "--k", "1.2", "--kmin", "1"],
     2, "give --k, or --kmin and --kmax"),
    ("pairing-eta-and-kmin-kmax", {},
     ["pairing", "wendland_c2", "fcc", "--code", "swift", "--eta", "1.2", "--kmin", "1", "--kmax", "2"],
     2, "give --k, or --kmin and --kmax"),
    ("particles-swift-hfact", {},
     ["particles", "wendland_c2", "poisson", "--count", "500", "--code", "swift", "--hfact", "1.2"],
     2, "^sphkern: error: --hfact: swift sets its resolution with --eta$"),
    ("particles-hfact-without-code", {}, ["particles", "wendland_c2", "poisson", "--count", "500", "--hfact", "1.2"],
     2, "^sphkern: error: --hfact is a code's setting; expected --code too$"),
    ("particles-swift-without-eta", {}, ["particles", "wendland_c2", "poisson", "--count", "500", "--code", "swift"],
     3, r"^sphkern: error: poisson: the set stores no h; with --code swift, expected --eta too \(the code's parameter\)$"),
    ("particles-code-and-nh", {},
     ["particles", "wendland_c2", "poisson", "--count", "500", "--code", "swift", "--eta", "1.2", "--nh", "40"],
     2, "^sphkern: error: --code: gives h for one setting; expected no --h-over-l, --nh, --k or sweep beside it$"),
    ("particles-phantom-desbrun_spiky", {},
     ["particles", "desbrun_spiky", "poisson", "--count", "500", "--code", "phantom", "--hfact", "1.2"],
     2, "desbrun_spiky: phantom does not ship it; its kernels are"),
    ("pairing-eta-neg1", {}, ["pairing", "wendland_c2", "fcc", "--code", "swift", "--eta", "-1"],
     2, r"^sphkern: error: --eta -1: expected a number in \(0, 100\]$"),
    ("pairing-kmin-alone", {}, ["pairing", "cubic_bspline", "fcc", "--kmin", "1"],
     2, "a range needs both --kmin and --kmax"),
    ("pairing-noise-0.5", {}, ["pairing", "cubic_bspline", "fcc", "--k", "1.2", "--noise", "0.5"],
     2, r"--noise 0.5: expected a number in \(0, 0.01\]"),
    ("pairing-samples-0", {}, ["pairing", "cubic_bspline", "fcc", "--kmin", "1", "--kmax", "2", "--samples", "0"],
     2, "--samples 0, expected 1 to 1000"),
    ("pairing-duration-neg1", {}, ["pairing", "cubic_bspline", "fcc", "--k", "1.2", "--duration", "-1"],
     2, "--duration -1: expected a number"),
    ("pairing-kmin-2-kmax-1", {}, ["pairing", "cubic_bspline", "fcc", "--kmin", "2", "--kmax", "1"],
     2, "expected 0 < kmin <= kmax <= 100"),
]


@pytest.mark.parametrize("files,args,code,pattern", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_relax_or_pairing_setting(tmp_path, files, args, code, pattern):
    write(tmp_path, {**COMMON, **files})
    expect(fill(args, tmp_path), code, pattern)



def test_a_glass_in_swifts_layout(tmp_path):
    glass = str(tmp_path / "glass.h5")
    expect(["relax", "wendland_c2", "poisson", "--count", "3000", "--nh", "60", "--steps", "20", "--output", glass, "--history",
            str(tmp_path / "history.csv")], 0, r"^$")
    # relax --history: the documented columns, one row per step and the start.
    lines = (tmp_path / "history.csv").read_text().splitlines()
    assert lines[0] == "step,time,rms_move,max_move,rms_e0,rms_e1,kinetic", lines[0]
    assert len(lines) == 1 + 21
    expect(["particles", "wendland_c2", glass, "--nh", "60"], 0, r"^$")
    # relax --output: SWIFT's layout, the support per h stated twice.
    with h5py.File(glass, "r") as f:
        assert list(f["Header"].attrs["BoxSize"]) == [1, 1, 1] and f["Header"].attrs["Dimension"] == 3
        gamma = 15 ** 0.5 / 2  # SWIFT's Wendland C2 in 3D, sqrt(15/4) = 1.936492
        assert f["PartType0/Coordinates"].shape == (3000, 3)
        assert abs(f["PartType0/SmoothingLength"].attrs["support_per_h"] - gamma) < 1e-12
        assert abs(f["HydroScheme"].attrs["Kernel gamma"] - gamma) < 1e-12
        assert f["HydroScheme"].attrs["Kernel function"] == b"Wendland C2"
    # particles reads the glass relax wrote, with its h (support per h from the file).
    assert "3000 particles" in text_of("particles", "wendland_c2", glass)


def test_a_2d_glass_in_csv_reads_back_with_its_box(tmp_path):
    glass2 = str(tmp_path / "glass2.csv")
    expect(["relax", "wendland_c2", "poisson", "--count", "2000", "--dim", "2", "--nh", "30", "--steps", "20", "--method", "shift",
            "--output", glass2], 0, r"^$")
    support = re.search(r"support radius = ([0-9.e+-]*) h", (tmp_path / "glass2.csv").read_text()).group(1)
    assert "2000 particles in 2D" in text_of("particles", "wendland_c2", glass2, "--box", "1,1", "--support-per-h", support)


def test_a_block_from_the_rectangular_cell(tmp_path):
    expect(["relax", "wendland_c2", "fcc", "--size", "6,4,3", "--cell", "rectangular", "--k", "1.2", "--steps", "3", "--output",
            str(tmp_path / "fcc_r.csv")], 0, r"^$")
    # fcc's block of 6 x 4 x 3 rectangular cells holds 432 particles in a rectangular box.
    lines = (tmp_path / "fcc_r.csv").read_text().splitlines()
    assert len([line for line in lines if not line.startswith("#")]) == 433


def test_a_gadget2_set_with_its_h(tmp_path):
    # relax --code: the code the written set is for, and with its parameter the run's h.
    ic = str(tmp_path / "gadget_ic.hdf5")
    expect(["relax", "cubic_bspline", "poisson", "--count", "1000", "--steps", "5", "--code", "gadget2", "--nngb", "50", "--output",
            ic], 0, r"^$")
    # Each written h is the support of 50 weighted neighbours, as particles --code solves it.
    import json
    a = json.loads(text_of("particles", "cubic_bspline", ic, "--code", "gadget2", "--json"))
    b = json.loads(text_of("particles", "cubic_bspline", ic, "--code", "gadget2", "--nngb", "50", "--json"))
    assert abs(a["h_min"] - b["h_min"]) < 1e-12 and abs(a["h_max"] - b["h_max"]) < 1e-12 and a["h_min"] < a["h_max"]


def test_tiled_copies(tmp_path):
    # Copies of the relaxed set side by side: the count and the box read back.
    expect(["relax", "wendland_c2", "poisson", "--count", "500", "--nh", "60", "--steps", "5", "--output",
            str(tmp_path / "tiled.csv"), "--tile", "2,3,1"], 0, r"^$")
    lines = (tmp_path / "tiled.csv").read_text().splitlines()
    assert len([line for line in lines if not line.startswith("#")]) == 3001
    assert any(line.startswith("# periodic box 2 3 1;") for line in lines)
