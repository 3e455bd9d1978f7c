"""Particle files that lie or surprise: declared sizes over the file or the memory budget, a
Dimension that is nan, PySPH files without arrays or with several, SPlisHSPlasH's VTK files
without h, HDF5 links to other files, a particle outside the periodic box, a NUL byte in a field,
two particles closer than a squared distance can tell, masses that overflow eps_rho; and a
relaxation that diverges. Each is one line with the file named, never a crash."""
import csv
import math
import os
import random

import h5py
import numpy
import pytest
from conftest import expect, fill, table


def write_files(work):
    # Declared sizes are checked against the file and the memory budget before anything is
    # allocated for them (they were believed: "out of memory" with no file named).
    with h5py.File(work / "declared.h5", "w") as f:
        f.create_dataset("PartType0/Coordinates", shape=(10**12, 3), dtype="f8", chunks=(1024, 3))
    with h5py.File(work / "budget.h5", "w") as f:
        f.create_dataset("PartType0/Coordinates", shape=(5 * 10**7, 3), dtype="f8", chunks=(4096, 3))
    with h5py.File(work / "nandim.h5", "w") as f:
        f.create_group("Header").attrs["Dimension"] = numpy.nan
        f.create_dataset("PartType0/Coordinates", data=numpy.random.default_rng(1).random((100, 3)))
    x = numpy.random.default_rng(5).random((100000, 3))
    x[:, 2] *= 0.001  # one thin layer: one row of bins holds every particle
    with h5py.File(work / "crowded.h5", "w") as f:
        f.create_group("Header").attrs["BoxSize"] = [1.0, 1.0, 1.0]
        f.create_dataset("PartType0/Coordinates", data=x)
    (work / "declared.vtk").write_text("# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 1099511627776 double\n0 0 0\n")
    # PySPH files: no array at all, and an array name longer than 255 characters.
    with h5py.File(work / "noarrays.h5", "w") as f:
        f.create_group("particles")
    with h5py.File(work / "longname.h5", "w") as f:
        rng = numpy.random.default_rng(2)
        for axis in "xyz":
            f.create_dataset("particles/" + "a" * 300 + "/arrays/" + axis, data=rng.random(500))
    rng = numpy.random.default_rng(3)
    with h5py.File(work / "arrays.h5", "w") as f:
        for name in ("fluid", "solid"):
            for axis in "xyz":
                f.create_dataset("particles/" + name + "/arrays/" + axis, data=rng.random(300))
    (work / "s_arrays.json").write_text('{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "particles": '
                                        '{"sources": [{"file": "arrays.h5", "array": "fluid,,solid"}]}}')
    rng = numpy.random.default_rng(4)
    for name, title in (("splish.vtk", "SPlisHSPlasH particle data"), ("notsplish.vtk", "other particles")):
        with open(work / name, "w") as f:
            f.write("# vtk DataFile Version 4.1\n" + title + "\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 300 float\n")
            f.write("\n".join(" ".join(repr(c) for c in p) for p in rng.random((300, 3))) + "\n")
    # Files reached through an HDF5 file's links.
    rng = numpy.random.default_rng(5)
    with h5py.File(work / "target.h5", "w") as f:
        f.create_dataset("PartType0/Coordinates", data=rng.random((500, 3)))
        f["Header/BoxSize"] = 1.0
    with h5py.File(work / "linking.h5", "w") as f:
        f["PartType0"] = h5py.ExternalLink("target.h5", "/PartType0")
        f.create_group("Header").attrs["BoxSize"] = 1.0
    with h5py.File(work / "to_pipe.h5", "w") as f:
        f["PartType0"] = h5py.ExternalLink("pipe.h5", "/PartType0")
    with h5py.File(work / "to_nowhere.h5", "w") as f:
        f["PartType0"] = h5py.ExternalLink("nowhere.h5", "/PartType0")
    with h5py.File(work / "source.h5", "w") as f:
        f["x"] = rng.random((500, 3))
    layout = h5py.VirtualLayout(shape=(500, 3), dtype="f8")
    layout[:] = h5py.VirtualSource(str(work / "source.h5"), "x", shape=(500, 3))
    with h5py.File(work / "virtual.h5", "w") as f:
        f.create_virtual_dataset("PartType0/Coordinates", layout)
        f.create_group("Header").attrs["BoxSize"] = 1.0
    os.mkfifo(work / "pipe.h5")
    random.seed(7)
    for name, x in (("near", 1.9), ("far", 2.1)):
        with open(work / f"{name}.csv", "w") as f:
            f.write("x,y,z\n" + "%g,0.5,0.5\n" % x)
            for i in range(400):
                f.write("%r,%r,%r\n" % (random.random(), random.random(), random.random()))
    (work / "nul.csv").write_bytes(b"x,y,z\n0.1,0.2,0.3\n0.5,0\0abc,0.7\n0.9,0.3,0.2\n")
    random.seed(11)
    with open(work / "close.csv", "w") as f:
        f.write("x,y,z\n0,0.5,0.5\n1e-301,0.5,0.5\n")
        for i in range(300):
            f.write("%r,%r,%r\n" % (random.random(), random.random(), random.random()))
    random.seed(3)
    with open(work / "massive.csv", "w") as f:
        f.write("x,y,z,mass\n")
        for i in range(400):
            f.write(f"{random.random()},{random.random()},{random.random()},0.0025\n")


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    folder = tmp_path_factory.mktemp("files")
    write_files(folder)
    return folder


CASES = [
    # `particles` measures a snapshot over the budget in slabs: the disk their results need is
    # checked first, and a slab one row of bins thick must fit the budget. Other commands read a
    # set whole.
    ("declared-slabs-disk", ["particles", "cubic_bspline", "{w}/declared.h5", "--nh", "40"],
     3, r"declared.h5: the slabs. per-particle results need 8e\+13 bytes of disk in .*expected more room there"),
    ("budget-declared-particles",
     ["relax", "cubic_bspline", "{w}/budget.h5", "--nh", "40", "--steps", "1", "--memory-limit", "0.05"],
     3, r"budget.h5: /PartType0/Coordinates declares 50000000 particles \(.*bytes for the particles\); over the .* particles \(.* bytes\) the memory budget of .* bytes holds \(--memory-limit\)"),
    ("crowded-slab",
     ["particles", "cubic_bspline", "{w}/crowded.h5", "--nh", "40", "--memory-limit", "0.03"],
     3, "crowded.h5: a slab one row of bins thick holds [0-9]+ particles and images .*over the .* bytes a slab may take of the memory budget"),
    ("nandim", ["particles", "cubic_bspline", "{w}/nandim.h5", "--nh", "40"],
     3, "nandim.h5: /Header Dimension is nan; expected 2 or 3"),
    ("declared-vtk", ["particles", "cubic_bspline", "{w}/declared.vtk", "--nh", "40"],
     3, "declared.vtk.*unexpected end of file"),
    # PySPH files: no array at all, and an array name longer than 255 characters.
    ("pysph-no-arrays", ["particles", "cubic_bspline", "{w}/noarrays.h5", "--nh", "40"],
     3, "noarrays.h5: /particles holds no particle array"),
    ("pysph-long-array-name", ["particles", "cubic_bspline", "{w}/longname.h5", "--nh", "40", "--box", "1,1,1"], 0, "^$"),
    # Several PySPH arrays: names that exist, each once, and no relaxation of walls.
    ("pysph-two-arrays",
     ["particles", "cubic_bspline", "{w}/arrays.h5", "--array", "fluid,solid", "--nh", "40", "--box", "1,1,1"],
     0, "^$"),
    ("pysph-array-wall",
     ["particles", "cubic_bspline", "{w}/arrays.h5", "--array", "fluid,wall", "--nh", "40"],
     3, 'arrays.h5: no particle array "wall"; the file has fluid, solid'),
    ("pysph-array-empty-name",
     ["particles", "cubic_bspline", "{w}/arrays.h5", "--array", "fluid,,solid", "--nh", "40"],
     2, "--array fluid,,solid: an empty array name"),
    ("pysph-array-twice",
     ["particles", "cubic_bspline", "{w}/arrays.h5", "--array", "fluid,fluid", "--nh", "40"],
     2, '--array fluid,fluid: array "fluid" named twice'),
    # h from the SPH density is solved for every particle: a set with neighbours-only particles is refused.
    ("pysph-neighbours-only",
     ["particles", "cubic_bspline", "{w}/arrays.h5", "--array", "fluid,solid", "--box", "1,1,1", "--code", "swift", "--eta", "1.2"],
     3, "arrays.h5: h from the SPH density is solved for every particle; the set has .* neighbours-only particles"),
    # A study source's array list is checked where the command line's is, named by its pointer.
    ("study-array-empty-name", ["run", "{w}/s_arrays.json", "-o", "{w}/out_arrays"],
     3, "s_arrays.json: /particles/sources/0/array fluid,,solid: an empty array name"),
    ("relax-two-arrays",
     ["relax", "cubic_bspline", "{w}/arrays.h5", "--array", "fluid,solid", "--box", "1,1,1", "--nh", "40", "--steps", "1"],
     3, "arrays.h5: relaxation moves every particle; expected one particle array"),
    # SPlisHSPlasH's VTK files hold no h and no particle radius: the radius is asked for, and given
    # only for its files.
    ("splish-radius",
     ["particles", "cubic_bspline", "{w}/splish.vtk", "--particle-radius", "0.05", "--box", "1,1,1"],
     0, "^$"),
    ("splish-without-radius", ["particles", "cubic_bspline", "{w}/splish.vtk", "--box", "1,1,1"],
     3, r"splish.vtk: the file holds no h and no particle radius \(its support is 4 radii\); give --particle-radius R"),
    ("radius-not-splish",
     ["particles", "cubic_bspline", "{w}/notsplish.vtk", "--particle-radius", "0.05", "--box", "1,1,1"],
     2, "--particle-radius: .*notsplish.vtk is not SPlisHSPlasH"),
    ("radius-not-vtk",
     ["particles", "cubic_bspline", "{w}/arrays.h5", "--particle-radius", "0.05", "--box", "1,1,1"],
     2, "--particle-radius: .*arrays.h5 is not a VTK file"),
    ("radius-poisson",
     ["particles", "cubic_bspline", "poisson", "--count", "100", "--particle-radius", "0.05"],
     2, "--particle-radius gives the h of a SPlisHSPlasH file; poisson is not a file"),
    ("radius-neg1",
     ["particles", "cubic_bspline", "{w}/splish.vtk", "--particle-radius", "-1", "--box", "1,1,1"],
     2, "--particle-radius -1: expected a positive length whose support radius 4 r is finite"),
    # The radius gives the file's h: a rule for h would leave it unused.
    ("radius-and-h-over-l",
     ["particles", "cubic_bspline", "{w}/splish.vtk", "--particle-radius", "0.05", "--h-over-l", "1.2", "--box", "1,1,1"],
     2, "--particle-radius excludes --h-over-l "),
    ("radius-and-nh-range",
     ["particles", "cubic_bspline", "{w}/splish.vtk", "--particle-radius", "0.05", "--nh-range", "30", "40", "--box", "1,1,1"],
     2, "--particle-radius excludes --nh-range "),
    ("relax-radius-and-k",
     ["relax", "cubic_bspline", "{w}/splish.vtk", "--particle-radius", "0.05", "--k", "1.2", "--box", "1,1,1", "--steps", "1"],
     2, "--particle-radius excludes --k "),
    # Files reached through an HDF5 file's links are inputs too: an output may not replace them
    # (it did, exit 0), and a link is followed only to a regular file (a FIFO blocked the open).
    ("link-read", ["particles", "cubic_bspline", "{w}/linking.h5", "--nh", "40"],
     0, "^$"),
    ("virtual-source-as-output",
     ["particles", "cubic_bspline", "{w}/virtual.h5", "--nh", "40", "--vtk", "{w}/source.h5"],
     5, "--vtk .*source.h5: is a file this run reads"),
    ("link-to-pipe", ["particles", "cubic_bspline", "{w}/to_pipe.h5", "--nh", "40"],
     3, "to_pipe.h5: the external link in / to pipe.h5:/PartType0 leads to .*pipe.h5, which is not a regular file"),
    ("link-to-nowhere", ["particles", "cubic_bspline", "{w}/to_nowhere.h5", "--nh", "40"],
     3, "to_nowhere.h5: the external link in / to nowhere.h5:/PartType0 leads to nowhere.h5, which does not exist"),
    # A relaxation that diverges is said to diverge, with its step and the settings to change; the
    # set sphkern made is not blamed ("particle 0 at (1.2e+67, ...) lies outside the periodic box").
    ("relax-diverges", ["relax", "wendland_c2", "poisson", "--count", "500", "--gamma", "1000", "--steps", "50"],
     3, r"poisson: the integration diverged at step [0-9]+ \(t = .*\): .*; expected a smaller --dt \(now 0.2\), more --damping \(now 0.5\) or a --gamma nearer 1 \(now 1000\)"),
    ("pairing-diverges", ["pairing", "cubic_bspline", "fcc", "--k", "1.2", "--gamma", "1e-6"],
     3, r"fcc: the integration diverged at step 1 .*--gamma nearer 1 \(now 1e-06\)"),
    # A particle within one box width outside a periodic box is wrapped in (as documented); farther is refused.
    ("near-box-wrapped", ["particles", "cubic_bspline", "{w}/near.csv", "--box", "1,1,1", "--nh", "40"],
     0, "^$"),
    ("far-outside-box",
     ["particles", "cubic_bspline", "{w}/far.csv", "--box", "1,1,1", "--nh", "40"],
     3, r"far.csv: particle 0 at \(2.1, 0.5, 0.5\) lies outside the periodic box"),
    # A NUL byte in a field is shown escaped, and the line goes on after it (it cut the error line).
    ("nul-in-field", ["particles", "cubic_bspline", "{w}/nul.csv", "--box", "1,1,1", "--nh", "4"],
     3, r'nul.csv: line 3, column y \(particle 1\): "0\\x00abc" is not a number$'),
    # Two particles 1e-301 apart: their squared distance underflows; named, with the file (it was
    # "a duplicate position that is not there").
    ("two-particles-too-close", ["particles", "cubic_bspline", "{w}/close.csv", "--box", "1,1,1", "--nh", "20"],
     3, "close.csv: particles 0 and 1 are 1e-301 apart, too close for their squared distance to be a number"),
    # No result is a non-finite number: eps_rho against a reference density 10^300 below the
    # masses' overflows its statistics, and is refused naming the quantity (it printed inf).
    ("masses-overflow-statistics",
     ["particles", "cubic_bspline", "{w}/massive.csv", "--box", "1,1,1", "--nh", "40", "--rho0", "1e-300"],
     3, r"massive.csv: the statistics of eps_rho overflow a double \(the masses over rho0 = 1e-300\)"),
    ("masses-overflow-particle",
     ["particles", "cubic_bspline", "{w}/massive.csv", "--box", "1,1,1", "--nh", "40", "--rho0", "5e-324", "--json"],
     3, r"massive.csv: eps_rho of particle [0-9]+ overflows a double \(its masses over rho0 = 4.94066e-324\)"),
]


@table(CASES)
def test_particle_file(work, args, code, pattern):
    expect(fill(args, work), code, pattern)


def test_a_linked_file_stays_as_it_was(work):
    before = (work / "target.h5").read_bytes()
    expect(["particles", "cubic_bspline", str(work / "linking.h5"), "--nh", "40", "--csv", str(work / "target.h5")], 5,
           r"--csv .*target.h5: is a file this run reads")
    expect(["relax", "wendland_c2", str(work / "linking.h5"), "--nh", "40", "--steps", "1", "--output", str(work / "target.h5")], 5,
           r"--output .*target.h5: is a file this run reads")
    assert (work / "target.h5").read_bytes() == before


def test_a_diverged_relaxation_writes_its_history_not_its_set(tmp_path):
    # What is safe to write is written: the steps before the divergence (all finite) go to --history,
    # and the error says where; the diverged positions are not written (--output).
    expect(["relax", "wendland_c2", "poisson", "--count", "500", "--gamma", "1000", "--steps", "50", "--history",
            str(tmp_path / "diverged.csv"), "--output", str(tmp_path / "diverged-set.csv")], 3,
           r"diverged at step [0-9]+ .*; the history up to step [0-9]+ is in .*diverged.csv$")
    with open(tmp_path / "diverged.csv") as f:
        rows = list(csv.DictReader(f))
    assert rows and rows[0]["step"] == "0" and all(math.isfinite(float(v)) for r in rows for v in r.values())
    assert not (tmp_path / "diverged-set.csv").exists()
