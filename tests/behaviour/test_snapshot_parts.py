"""Snapshots in several files (snap.0.hdf5, snap.1.hdf5, ...) whose headers lie about their
parts: each written here as SWIFT writes its distributed snapshots, with the exit code and the
one line expected."""
import h5py
import numpy as np
from conftest import expect

N = 216


def lattice(n_side=6):
    g = (np.arange(n_side) + 0.5) / n_side
    return np.array(np.meshgrid(g, g, g, indexing="ij")).reshape(3, -1).T


def write_parts(base, rows, files=None, this_file=None, total=None, high_word=0):
    """Part K of a snapshot holds rows[K] particles of one lattice, its header NumFilesPerSnapshot
    `files` (len(rows) by default), NumPart_ThisFile[0] this_file[K] (its rows by default) and
    NumPart_Total[0] `total` (the rows' sum by default)."""
    x = lattice()
    files = len(rows) if files is None else files
    total = sum(rows) if total is None else total
    first = 0
    for k, count in enumerate(rows):
        with h5py.File(f"{base}.{k}.hdf5", "w") as f:
            header = f.create_group("Header")
            header.attrs["BoxSize"] = [1.0, 1.0, 1.0]
            header.attrs["Dimension"] = 3
            header.attrs["NumFilesPerSnapshot"] = np.int32(files)
            header.attrs["NumPart_Total"] = np.array([total, 0, 0, 0, 0, 0], dtype=np.uint32)
            header.attrs["NumPart_Total_HighWord"] = np.array([high_word, 0, 0, 0, 0, 0], dtype=np.uint32)
            declared = count if this_file is None else this_file[k]
            header.attrs["NumPart_ThisFile"] = np.array([declared, 0, 0, 0, 0, 0], dtype=np.uint32)
            header.attrs["MassTable"] = [0.0] * 6
            header.attrs["ThisFile"] = np.int32(k)
            f.create_group("HydroScheme").attrs["Kernel gamma"] = 1.936492
            part = f.create_group("PartType0")
            part["Coordinates"] = x[np.arange(first, first + count) % N].reshape(count, 3)
            part["SmoothingLengths"] = np.full(count, 1.2 / 6 * 2 / 1.936492)
            part["Masses"] = np.full(count, 1.0 / N)
        first += count
    return [str(base) + f".{k}.hdf5" for k in range(len(rows))]


def particles(name):
    return ["particles", "wendland_c2", name]


def test_a_part_whose_header_lies_about_its_rows_is_refused_whichever_part_is_named(tmp_path):
    # Part 0 holds no rows but says 10; part 1 alone holds all the declared total.
    names = write_parts(tmp_path / "snap", [0, N], this_file=[10, N], total=N)
    for name in names:
        expect(particles(name), 3, r"snap\.0\.hdf5: /Header NumPart_ThisFile\[0\] is 10 but /PartType0/Coordinates "
                                   r"has 0 rows")


def test_a_file_beyond_the_declared_parts_is_refused(tmp_path):
    write_parts(tmp_path / "snap", [N // 2, N - N // 2])
    # A third file beside them, its header copied from theirs: not one of the 2 parts.
    write_parts(tmp_path / "extra", [N // 2, N - N // 2, 10], files=2, total=N)
    (tmp_path / "extra.2.hdf5").rename(tmp_path / "snap.2.hdf5")
    expect(particles(str(tmp_path / "snap.2.hdf5")), 3,
           r"snap\.2\.hdf5: part 2 of a snapshot whose header says 2 files \(/Header NumFilesPerSnapshot\), "
           r"parts 0 to 1; expected one of those")


def test_a_file_beyond_the_parts_is_refused_though_it_holds_the_declared_total(tmp_path):
    write_parts(tmp_path / "snap", [N // 2, N - N // 2])
    write_parts(tmp_path / "extra", [1, 1, N], files=2, total=N)
    (tmp_path / "extra.2.hdf5").rename(tmp_path / "snap.2.hdf5")
    expect(particles(str(tmp_path / "snap.2.hdf5")), 3, r"snap\.2\.hdf5: part 2 of a snapshot whose header says 2 files")


def test_counts_that_miss_the_declared_total_with_its_high_word_are_refused(tmp_path):
    # NumPart_Total[0] matches the rows, but its high word adds 2^32 particles no part holds.
    write_parts(tmp_path / "snap", [N // 2, N - N // 2], high_word=1)
    expect(particles(str(tmp_path / "snap.1.hdf5")), 3,
           r"snap\.1\.hdf5: the snapshot's 2 files hold 216 particles but /Header NumPart_Total declares 4294967512")


def test_a_one_file_snapshot_whose_total_lies_is_refused(tmp_path):
    (name,) = write_parts(tmp_path / "one", [N], total=N, high_word=1)
    expect(particles(name), 3, r"one\.0\.hdf5: /Header NumPart_Total declares 4294967512 "
                               r"particles but /PartType0/Coordinates has 216 rows")


def test_a_correct_snapshot_in_two_parts_reads_from_either_part(tmp_path):
    for name in write_parts(tmp_path / "snap", [N // 2, N - N // 2]):
        expect(particles(name), 0, r"^$")
    # A part with no particles is a part too, where its header says so.
    for name in write_parts(tmp_path / "empty", [0, N]):
        expect(particles(name), 0, r"^$")


def test_swifts_virtual_file_over_the_parts_reads_alone(tmp_path):
    """SWIFT's snap.hdf5 beside snap.0.hdf5 ...: its header says the parts' count, its datasets
    are virtual over theirs and hold every row."""
    names = write_parts(tmp_path / "snap", [N // 2, N - N // 2])
    with h5py.File(names[0]) as first, h5py.File(tmp_path / "snap.hdf5", "w") as f:
        first.copy("Header", f)
        first.copy("HydroScheme", f)
        f["Header"].attrs["NumPart_ThisFile"] = np.array([N, 0, 0, 0, 0, 0], dtype=np.uint32)
        for dataset, shape in (("Coordinates", (N, 3)), ("SmoothingLengths", (N,)), ("Masses", (N,))):
            layout = h5py.VirtualLayout(shape=shape, dtype=np.float64)
            at = 0
            for name in names:
                with h5py.File(name) as part:
                    rows = part["PartType0/" + dataset].shape[0]
                layout[at:at + rows] = h5py.VirtualSource(name, "PartType0/" + dataset, shape=(rows,) + shape[1:])
                at += rows
            f.create_virtual_dataset("PartType0/" + dataset, layout)
    expect(particles(str(tmp_path / "snap.hdf5")), 0, r"^$")


def test_a_part_that_is_a_folder_is_named_as_one(tmp_path):
    import os
    import shutil
    names = write_parts(tmp_path / "snap", [N // 2, N - N // 2])
    os.remove(names[1])
    os.mkdir(names[1])
    expect(particles(names[0]) + ["--code", "swift"], 3, r"part 1 of the snapshot's 2 files, .*snap\.1\.hdf5, is a folder")
    shutil.rmtree(names[1])
