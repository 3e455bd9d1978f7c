"""Particle files that lie or surprise (round 5, items 2, 3, 5, 7, 8, 16): each written here as
the code or h5py writes it, with the exit code and the one line expected."""
import json

import h5py
import numpy as np
from conftest import expect, run

N = 216


def lattice(n_side=6):
    g = (np.arange(n_side) + 0.5) / n_side
    return np.array(np.meshgrid(g, g, g, indexing="ij")).reshape(3, -1).T


def swift_file(path, kernel_label):
    x = lattice()
    with h5py.File(path, "w") as f:
        header = f.create_group("Header")
        header.attrs["BoxSize"] = [1.0, 1.0, 1.0]
        header.attrs["Dimension"] = 3
        scheme = f.create_group("HydroScheme")
        scheme.attrs["Kernel gamma"] = 1.936492
        scheme.attrs["Kernel function"] = kernel_label  # a Python str: h5py writes a variable-length UTF-8 string
        part = f.create_group("PartType0")
        part["Coordinates"] = x
        part["SmoothingLengths"] = np.full(N, 1.2 / 6 * 2 / 1.936492)
        part["Masses"] = np.full(N, 1.0 / N)


def test_swift_kernel_name_as_h5py_writes_it_is_checked(tmp_path):
    swift_file(tmp_path / "c2.hdf5", "Wendland C2")
    expect(["particles", "cubic_bspline", str(tmp_path / "c2.hdf5"), "--code", "swift"], 3,
           r"the file's h is for its kernel .*Wendland C2.*, not cubic_bspline")
    expect(["particles", "wendland_c2", str(tmp_path / "c2.hdf5"), "--code", "swift"], 0, r"^$")


def test_gadget_2d_initial_conditions_read_back_in_2d(tmp_path):
    out = tmp_path / "ic2d.hdf5"
    expect(["relax", "cubic_bspline", "poisson", "--count", "400", "--dim", "2", "--steps", "5", "--code", "gadget2",
            "--output", str(out)], 0, r"^$|wrote")
    with h5py.File(out) as f:
        assert int(np.ravel(f["Header"].attrs["Dimension"])[0]) == 2
    done = run(["particles", "cubic_bspline", str(out), "--code", "gadget2", "--json"])
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["source"]["dimension"] == 2


def big_snapshot(path):
    with h5py.File(path, "w") as f:
        f.create_group("Header").attrs["BoxSize"] = [1.0, 1.0, 1.0]
        f.create_dataset("PartType0/Coordinates", data=np.random.default_rng(6).random((60000, 3)))


def test_tmpdir_that_cannot_hold_the_slabs_is_named(tmp_path):
    big_snapshot(tmp_path / "big.h5")
    args = ["particles", "cubic_bspline", str(tmp_path / "big.h5"), "--nh", "40", "--memory-limit", "0.012"]
    for tmpdir, why in ((str(tmp_path / "missing"), "no such folder"), (str(tmp_path / "big.h5"), "not a folder")):
        out = run(args, env_extra={"TMPDIR": tmpdir})
        assert out.returncode == 5, out.stderr
        assert f"TMPDIR={tmpdir}: {why}" in out.stderr
    assert run(args, env_extra={"TMPDIR": ""}).returncode == 0


def pysph_file(path, solid_h=0.15, solid_rows=64, fluid_rows=N):
    x = lattice()[:fluid_rows]
    with h5py.File(path, "w") as f:
        for name, rows, h in (("fluid", fluid_rows, 0.15), ("solid", solid_rows, solid_h)):
            arrays = f.create_group(f"particles/{name}/arrays")
            xs = x[:rows] if name == "fluid" else lattice()[:rows] * 0.5 + 0.01
            for key, values in (("x", xs[:, 0]), ("y", xs[:, 1]), ("z", xs[:, 2]), ("h", np.full(rows, h)),
                                ("m", np.full(rows, 1.0 / N)), ("rho", np.ones(rows))):
                arrays[key] = values
            if name == "solid" and rows > 5:
                arrays["h"][5] = -1.0


def test_a_wall_particle_is_named_in_its_array(tmp_path):
    pysph_file(tmp_path / "wall.hdf5")
    expect(["particles", "cubic_bspline", str(tmp_path / "wall.hdf5"), "--array", "fluid,solid", "--code", "pysph",
            "--box", "1,1,1"], 3, r'the smoothing length of particle 5 of array "solid" is -1')


def test_empty_pysph_arrays(tmp_path):
    pysph_file(tmp_path / "empty_solid.hdf5", solid_rows=0)
    expect(["particles", "cubic_bspline", str(tmp_path / "empty_solid.hdf5"), "--array", "fluid,solid", "--code",
            "pysph", "--box", "1,1,1"], 0, r"^$")
    pysph_file(tmp_path / "empty_fluid.hdf5", fluid_rows=0)
    expect(["particles", "cubic_bspline", str(tmp_path / "empty_fluid.hdf5"), "--array", "fluid,solid", "--code",
            "pysph", "--box", "1,1,1"], 3, r'particle array "fluid" has no particles')


def test_compound_coordinates_are_not_numbers(tmp_path):
    records = np.zeros(N, dtype=[("x", "f8"), ("y", "f8"), ("z", "f8")])
    with h5py.File(tmp_path / "compound.h5", "w") as f:
        f.create_group("Header").attrs["BoxSize"] = [1.0, 1.0, 1.0]
        f["PartType0/Coordinates"] = records
    expect(["particles", "cubic_bspline", str(tmp_path / "compound.h5"), "--nh", "40"], 3,
           r"dataset /PartType0/Coordinates does not hold numbers \(its values are records of several fields\)")


def test_options_that_mean_nothing_on_the_file_are_said_not_ignored(tmp_path):
    swift_file(tmp_path / "c2.hdf5", "Wendland C2")
    expect(["particles", "wendland_c2", str(tmp_path / "c2.hdf5"), "--code", "swift", "--array", "fluid"], 2,
           r"--array fluid: names PySPH's particle arrays; .*c2\.hdf5 is a SWIFT or GADGET snapshot")
    for option, value in (("--ap", "ball"), ("--site", "1"), ("--kmin", "0.9"), ("--gamma", "1.4")):
        expect(["assess", "wendland_c2", str(tmp_path / "c2.hdf5"), "--code", "swift", option, value], 2,
               rf"^sphkern: error: {option} is for a lattice; on a particle file .* expected none$")
