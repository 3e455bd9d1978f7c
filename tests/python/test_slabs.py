"""Snapshots larger than the memory budget are measured in slabs: the statistics and the CSV equal
the whole set's in memory bit for bit, on periodic and free sets in 2D and 3D with variable h, on
any number of threads, and from a snapshot in several files; what slabs cannot do is refused in one
line. Run by ctest with SPHKERN_CLI set."""
import json
import os
import subprocess

import h5py
import numpy as np
import pytest

from test_particle_files import refused

CLI = os.environ["SPHKERN_CLI"]
N = 60000
# Under the budget of N particles (in the engine's estimate), over what the plan keeps aside: slabs.
SLABS = ["--memory-limit", "0.011"]
COMPARED = ["statistics", "histograms", "h_over_l", "nh", "h_min", "h_max", "mean_neighbours", "pairs", "mean_volume",
            "rho0", "source"]


def snapshot(path, dim, periodic, parts=1, seed=7, gadget=False, tamper=None, count=N):
    """A SWIFT snapshot of `count` Poisson particles, h varying by +-15%, masses and densities; in
    `parts` files BASE.K.hdf5 where parts > 1 (then `path` is the base). GADGET's layout where
    asked: single precision, SmoothingLength and Density, one mass in the MassTable."""
    N = count
    rng = np.random.default_rng(seed)
    x = rng.uniform(0, 1, (N, 3))
    if dim == 2:
        x[:, 2] = 0
    l = (1.0 / N) ** (1 / dim)
    h = 1.2 * l * rng.uniform(0.85, 1.15, N)
    m = rng.uniform(0.9, 1.1, N) / N
    rho = rng.uniform(0.95, 1.05, N)
    if tamper:
        tamper(x)
    bounds = np.linspace(0, N, parts + 1).astype(int)
    names = []
    for k in range(parts):
        lo, hi = bounds[k], bounds[k + 1]
        name = str(path) if parts == 1 else f"{path}.{k}.hdf5"
        with h5py.File(name, "w") as f:
            header = f.create_group("Header")
            header.attrs["Dimension"] = dim
            if periodic:
                header.attrs["BoxSize"] = [1.0, 1.0, 1.0]
            header.attrs["NumPart_Total"] = np.array([N, 0, 0, 0, 0, 0], dtype=np.uint32)
            header.attrs["NumPart_ThisFile"] = np.array([hi - lo, 0, 0, 0, 0, 0], dtype=np.uint32)
            header.attrs["NumFilesPerSnapshot"] = parts
            p = f.create_group("PartType0")
            if gadget:
                header.attrs["MassTable"] = [1.0 / N, 0, 0, 0, 0, 0]
                p["Coordinates"] = x[lo:hi].astype(np.float32)
                p["SmoothingLength"] = h[lo:hi].astype(np.float32)
                p["Density"] = rho[lo:hi].astype(np.float32)
            else:
                f.create_group("HydroScheme").attrs["Kernel gamma"] = 1.936492
                p["Coordinates"] = x[lo:hi]
                p["SmoothingLengths"] = h[lo:hi]
                p["Masses"] = m[lo:hi]
                p["Densities"] = rho[lo:hi]
        names.append(name)
    return names[0]


def run(*args, env=None):
    done = subprocess.run([CLI, "--log-level", "debug", "particles", "wendland_c2", *args, "--json"],
                          capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    slabs = [line for line in done.stderr.splitlines() if " slabs along axis " in line]
    return json.loads(done.stdout), slabs


@pytest.mark.parametrize("dim,periodic", [(3, True), (3, False), (2, True), (2, False)])
def test_slabs_give_the_whole_sets_statistics_and_csv(tmp_path, dim, periodic):
    name = snapshot(tmp_path / "set.hdf5", dim, periodic)
    whole, slabs = run(name, "--histogram", "9", "--csv", str(tmp_path / "whole.csv"))
    assert not slabs, "the whole set fits the default budget"
    spill = tmp_path / "spill"
    spill.mkdir()
    env = dict(os.environ, TMPDIR=str(spill))
    for threads in ("1", "2", "7"):
        sliced, slabs = run(name, *SLABS, "--histogram", "9", "--threads", threads, "--csv", str(tmp_path / "slabs.csv"), env=env)
        assert slabs and int(slabs[0].split(" in ")[1].split()[0]) >= 3, slabs
        for key in COMPARED:
            assert sliced.get(key) == whole.get(key), key
        assert (tmp_path / "slabs.csv").read_bytes() == (tmp_path / "whole.csv").read_bytes()
        assert not list(spill.iterdir()), "the slabs' spill folder is removed"


def test_runs_of_rows_follow_the_threads_and_change_no_bit(tmp_path):
    """The file is read, and the spills merged, in runs of eight blocks per thread where the budget
    holds them: a different run on one thread and on two, the same statistics."""
    name = snapshot(tmp_path / "set.hdf5", 3, True, count=200000)
    whole, _ = run(name, "--histogram", "9")
    runs = set()
    for threads in ("1", "2", "7"):
        sliced, slabs = run(name, "--memory-limit", "0.05", "--histogram", "9", "--threads", threads)
        assert slabs, "the set is over the budget"
        rows = int(slabs[0].split("in runs of ")[1].split()[0])
        assert rows % 8192 == 0
        runs.add(rows)
        for key in COMPARED:
            assert sliced.get(key) == whole.get(key), key
    assert len(runs) == 2, runs


def test_snapshots_in_parts_in_slabs_give_the_one_file_result(tmp_path):
    whole, _ = run(snapshot(tmp_path / "one.hdf5", 3, True), "--code", "pysph")
    sliced, slabs = run(snapshot(tmp_path / "snap", 3, True, parts=3).replace(".0.", ".2."), *SLABS, "--code", "pysph")
    assert slabs
    for key in COMPARED[:-1]:
        assert sliced.get(key) == whole.get(key), key
    # GADGET's multi-part files in slabs against its one file in memory.
    whole, _ = run(snapshot(tmp_path / "gadget.hdf5", 3, True, gadget=True), "--support-per-h", "2")
    sliced, slabs = run(snapshot(tmp_path / "gadget", 3, True, parts=4, gadget=True), *SLABS, "--support-per-h", "2")
    assert slabs
    for key in COMPARED[:-1]:
        assert sliced.get(key) == whole.get(key), key


def test_what_slabs_cannot_do_is_refused(tmp_path):
    name = snapshot(tmp_path / "set.hdf5", 3, True)
    assert f"{N} particles, over the memory budget (--memory-limit), are measured in slabs, which take one h, not a sweep" \
        in refused(name, *SLABS, "--nh-range", "40", "60")
    assert "not solved from each particle's density" in refused(name, *SLABS, "--code", "swift", "--eta", "1.2")
    assert "not Voronoi cells" in refused(name, *SLABS, "--volume", "voronoi")
    assert "--csv only" in refused(name, *SLABS, "--vtk", str(tmp_path / "a.vtk"))
    assert "expected its /Header Dimension instead" in subprocess.run(
        [CLI, "particles", "wendland_c2", name, *SLABS, "--dim", "3"], capture_output=True, text=True).stderr
    assert "leaves nothing for a slab" in refused(name, "--memory-limit", "0.001")
    assert not (tmp_path / "a.vtk").exists()


def test_a_bad_particle_in_slabs_is_named_by_its_row_as_in_memory(tmp_path):
    def not_finite(x):
        x[45000, 1] = np.nan

    def twins(x):
        x[50001] = x[41234]
    for tamper, says in ((not_finite, "particle 45000 has a non-finite coordinate"),
                         (twins, "particles 41234 and 50001 are at the same position")):
        name = snapshot(tmp_path / f"{tamper.__name__}.hdf5", 3, True, tamper=tamper)
        whole, sliced = refused(name), refused(name, *SLABS)
        assert says in whole and sliced == whole, (whole, sliced)
