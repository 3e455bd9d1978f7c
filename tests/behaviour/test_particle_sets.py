"""Particle sets (particles on a lattice block, a poisson set or a file): every option out of
range or not for this source is one line and exit 2; a set the option cannot measure is exit 3;
an output aimed at an input is exit 5; the documented columns of --csv and --vtk."""
import pytest
from conftest import expect, fill, write

# Small particle files the cases read, written into each case's folder.
COMMON = {
    "free.csv": "x,y\n0.1,0.2\n0.5,0.7\n0.9,0.3\n",
    "lonely.csv": "x,y,m,rho\n0.1,0.2,1,1\n0.5,0.7,1,1\n0.9,0.1,1,1\n",
    "withh.csv": "x,y,h\n0.1,0.2,0.1\n0.5,0.7,0.1\n",
    "fake.h5": "garbage",
    "xyz.csv": "x,y,z\n0.1,0.2,0.3\n0.5,0.7,0.4\n",
}

CASES = [
    ("particles-lattice-without-size", {}, ["particles", "cubic_bspline", "fcc", "--k", "1.2"], 2, "a lattice source needs --size"),
    ("particles-size-8-8", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8"],
     3, "--size: the lattice is 3D, expected 3 cell counts"),
    ("particles-size-8-0.5-8", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,0.5,8"],
     2, "expected whole numbers of cells"),
    ("particles-block-below-twice-support", {}, ["particles", "cubic_bspline", "fcc", "--size", "3,3,3", "--k", "1.2"],
     3, "less than twice the support radius"),
    ("particles-sigma-neg1", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--sigma", "-1"],
     2, r"--sigma -1: expected a number in \[0, 10\]"),
    ("particles-sigma-0.1", {}, ["particles", "cubic_bspline", "poisson", "--count", "100", "--sigma", "0.1"],
     2, "--sigma disturbs a lattice"),
    ("particles-poisson-without-count", {}, ["particles", "cubic_bspline", "poisson"],
     2, "a poisson set needs --count N"),
    ("particles-count-1", {}, ["particles", "cubic_bspline", "poisson", "--count", "1"], 2, "--count 1, expected 2 to"),
    ("particles-dim-4", {}, ["particles", "cubic_bspline", "poisson", "--count", "100", "--dim", "4"],
     2, "^sphkern: error: --dim: 4: expected 2 or 3$"),
    ("study-poisson-4",
     {"s_pdim.json": '{"name": "s", "kernels": ["wendland_c2"], "lattices": ["fcc"], "plots": false, "particles": {"sources": [{"poisson": 4, "count": 500}], "nh": {"min": 30, "max": 60}}}'},
     ["run", "{w}/s_pdim.json", "-o", "{w}/out_pdim"],
     3, "s_pdim.json: /particles/sources/0/poisson: 4: expected 2 or 3$"),
    ("particles-memory-limit-1", {},
     ["particles", "cubic_bspline", "poisson", "--count", "100000000", "--memory-limit", "1"],
     3, r"more than the memory limit of [0-9]+ particles \(--memory-limit\)"),
    ("particles-memory-limit-neg1", {},
     ["particles", "cubic_bspline", "poisson", "--count", "100", "--memory-limit", "-1"],
     2, "--memory-limit -1: expected GiB"),
    ("particles-poisson-with-k", {}, ["particles", "cubic_bspline", "poisson", "--count", "1000", "--k", "1.2"],
     3, "--k needs a lattice"),
    ("particles-h-over-l-0", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--h-over-l", "0"],
     2, r"--h-over-l 0: expected a number in \(0, 100\]"),
    ("particles-eta-1.2", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--eta", "1.2"],
     2, r"^sphkern: error: --eta is SWIFT's eta, a code's setting \(--code swift --eta\); sphkern's own h over the mean spacing is --h-over-l$"),
    ("particles-eta-range", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--eta-range", "1", "2"],
     2, "^sphkern: error: --eta-range is the old name of --h-over-l-range"),
    ("particles-nh-0.5", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--nh", "0.5"],
     2, r"--nh 0.5: expected a number in \[1, 100000\]"),
    ("particles-h-over-l-and-nh", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--h-over-l", "1.2", "--nh", "50"],
     2, "give one of --h-over-l, --nh, --k"),
    ("particles-volume-cells", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--volume", "cells"],
     2, '--volume: "cells" is unknown, expected uniform, file or voronoi'),
    ("particles-h-over-l-range-2", {},
     ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--h-over-l-range", "2", "1"],
     2, r"--h-over-l-range: \[2, 1\]: expected min < max"),
    ("particles-sweep-and-csv", {},
     ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--h-over-l-range", "1", "2", "--csv", "{w}/p.csv"],
     2, "they do not go with a sweep"),
    ("particles-csv-empty", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--csv", ""],
     2, "--csv: an empty value"),
    ("particles-gravity-0-0-0", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--gravity", "0,0,0"],
     2, "--gravity: expected a direction"),
    ("particles-depth-neg1", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--depth", "-1"],
     2, "--depth -1: expected a number"),
    ("particles-free-uniform", {}, ["particles", "cubic_bspline", "{w}/free.csv"],
     3, "free.csv: uniform volumes need a periodic box"),
    ("particles-free-voronoi", {}, ["particles", "cubic_bspline", "{w}/free.csv", "--volume", "voronoi"],
     3, "free.csv: Voronoi volumes need a periodic box"),
    ("particles-free-file-volumes", {}, ["particles", "cubic_bspline", "{w}/free.csv", "--volume", "file"],
     3, r"free.csv: the file.s volumes \(m / rho\) need masses and densities"),
    ("particles-lonely", {}, ["particles", "cubic_bspline", "{w}/lonely.csv", "--h-over-l", "0.1"],
     3, "lonely.csv: particle 0 has no neighbour inside its support"),
    ("particles-h-without-convention", {}, ["particles", "cubic_bspline", "{w}/withh.csv", "--box", "1,1"],
     3, "the file.s smoothing lengths need a convention: --support-per-h X"),
    ("particles-support-per-h-with-rule", {},
     ["particles", "cubic_bspline", "{w}/free.csv", "--support-per-h", "2", "--h-over-l", "1"],
     2, "--support-per-h: maps a file.s h"),
    ("particles-csv-and-vtk-same", {},
     ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--csv", "{w}/same", "--vtk", "{w}/same"],
     5, "names the same file"),
    ("particles-not-a-particle-file", {}, ["particles", "cubic_bspline", "{w}/free.xyz"],
     3, "not a particle file; expected"),
    ("particles-fake-h5", {"fake.h5": "garbage"}, ["particles", "cubic_bspline", "{w}/fake.h5"], 3, "fake.h5: not an HDF5 file"),
    ("particles-dim-2-of-3d", {}, ["particles", "cubic_bspline", "{w}/xyz.csv", "--dim", "2", "--box", "1,1"],
     3, "--dim 2, but no coordinate is the same for every particle"),
    # A lattice block disturbed by more than its own width is still periodic: wrapped, not blamed
    # on the set sphkern made ("particle 1 ... lies outside the periodic box").
    ("particles-sigma-10", {}, ["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--sigma", "10"], 0, "^$"),
]


@pytest.mark.parametrize("files,args,code,pattern", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_particle_set(tmp_path, files, args, code, pattern):
    write(tmp_path, {**COMMON, **files})
    expect(fill(args, tmp_path), code, pattern)


def test_the_input_survives_an_output_aimed_at_it(tmp_path):
    write(tmp_path, COMMON)
    expect(["particles", "cubic_bspline", str(tmp_path / "withh.csv"), "--box", "1,1", "--support-per-h", "2", "--csv",
            str(tmp_path / "withh.csv")], 5, r"is a file this run reads")
    assert "0.5,0.7,0.1" in (tmp_path / "withh.csv").read_text()


def test_csv_and_vtk_columns(tmp_path):
    expect(["particles", "cubic_bspline", "fcc", "--size", "8,8,8", "--k", "1.2", "--csv", str(tmp_path / "p.csv"), "--vtk",
            str(tmp_path / "p.vtk")], 0, r"^$")
    # --csv: the documented columns, one row per particle.
    lines = (tmp_path / "p.csv").read_text().splitlines()
    assert lines[0] == "id,x,y,z,h,volume,neighbours,e0,eps_rho,eps_gradp,e1_x,e1_y,e1_z,m1_x,m1_y,m1_z", lines[0]
    assert len(lines) == 1 + 8 * 8 * 8
    # --vtk: point data for every particle.
    assert "POINT_DATA 512" in (tmp_path / "p.vtk").read_text().splitlines()
