"""GADGET-2's own binary snapshots (SnapFormat 1 and 2): files written here as GADGET-2's
io.c write_file writes them (float and double, either byte order, one or two files per
snapshot, gas masses in the MassTable or in the MASS block, dark matter beside the gas) must
give the statistics of the same gas particles in a GADGET HDF5 snapshot, bit for bit; a file
SPLASH converts to GADGET format reads back to its source; broken files give one line naming
the record and exit 3. Run by ctest with SPHKERN_CLI set."""
import json
import os
import shutil
import struct
import subprocess

import numpy as np
import pytest

h5py = pytest.importorskip("h5py")

CLI = os.environ["SPHKERN_CLI"]
N_GAS, N_DARK, L = 400, 60, 1.0
SPLIT = (250, 30)  # the gas and dark-matter particles of part 0 of a two-file snapshot


def particles():
    rng = np.random.default_rng(42)
    return {
        "gas_pos": rng.uniform(0, L, (N_GAS, 3)),
        "gas_vel": rng.normal(size=(N_GAS, 3)),
        "gas_mass": (L**3 / N_GAS) * rng.uniform(0.9, 1.1, N_GAS),
        "u": rng.uniform(1, 2, N_GAS),
        "rho": rng.uniform(0.9, 1.1, N_GAS),
        "hsml": 0.3 * rng.uniform(0.95, 1.05, N_GAS),  # GADGET's support radius
        "dark_pos": rng.uniform(0, L, (N_DARK, 3)),
        "dark_vel": rng.normal(size=(N_DARK, 3)),
        "dark_mass": np.full(N_DARK, 0.01),
    }


def header_bytes(npart, mass, npart_total, num_files, box, endian, time=0.0):
    """struct io_header of GADGET-2's allvars.h: 256 bytes."""
    total = [n & 0xFFFFFFFF for n in npart_total]
    high = [n >> 32 for n in npart_total]
    return struct.pack(endian + "6i6d2d2i6I2i4d2i6Ii60x", *npart, *mass, time, 0.0, 0, 0, *total, 0, num_files,
                       box, 0.3, 0.7, 0.7, 0, 0, *high, 0)


def record(f, payload, endian):
    f.write(struct.pack(endian + "i", len(payload)))
    f.write(payload)
    f.write(struct.pack(endian + "i", len(payload)))


def write_gadget_file(path, types, mass_table, npart_total, num_files, box, dtype, endian, snap_format,
                      gas_blocks=("U", "RHO", "HSML"), time=0.0):
    """One file as write_file writes it: the header, then POS, VEL, ID, MASS (types whose
    MassTable entry is 0), U, RHO, HSML (gas), each block only where it holds particles, the
    types in order 0..5 in every block; SnapFormat 2 puts a labelled 8-byte record before each."""
    npart = [len(t["pos"]) if t else 0 for t in types]
    present = [t for t in types if t]
    real = np.dtype(dtype).newbyteorder(endian)

    def cat(key, which=present):
        return np.concatenate([t[key] for t in which]) if which else np.zeros(0)

    blocks = [("POS", cat("pos").astype(real)), ("VEL", cat("vel").astype(real)),
              ("ID", cat("id").astype(np.dtype("i4").newbyteorder(endian)))]
    with_mass = [t for k, t in enumerate(types) if t and mass_table[k] == 0]
    if with_mass:
        blocks.append(("MASS", cat("mass", with_mass).astype(real)))
    if npart[0]:
        for label in gas_blocks:
            blocks.append((label, types[0][label.lower()].astype(real)))
    with open(path, "wb") as f:
        head = header_bytes(npart, mass_table, npart_total, num_files, box, endian, time)
        if snap_format == 2:
            record(f, b"HEAD" + struct.pack(endian + "i", len(head) + 8), endian)
        record(f, head, endian)
        for label, values in blocks:
            data = values.tobytes()
            if snap_format == 2:
                record(f, label.ljust(4).encode() + struct.pack(endian + "i", len(data) + 8), endian)
            record(f, data, endian)


def write_snapshot(base, p, files=1, dtype="f4", endian="<", snap_format=1, table_mass=False, time=0.0):
    """The particles as a snapshot of `files` files (BASE, or BASE.0, BASE.1); returns the path
    of its first file."""
    gas_mass = np.full(N_GAS, p["gas_mass"][0]) if table_mass else p["gas_mass"]
    mass_table = [gas_mass[0] if table_mass else 0.0, 0, 0, 0, 0, 0]  # dark matter in MASS
    ids = np.arange(1, N_GAS + N_DARK + 1)
    gas = {"pos": p["gas_pos"], "vel": p["gas_vel"], "id": ids[:N_GAS], "mass": gas_mass, "u": p["u"], "rho": p["rho"],
           "hsml": p["hsml"]}
    dark = {"pos": p["dark_pos"], "vel": p["dark_vel"], "id": ids[N_GAS:], "mass": p["dark_mass"]}
    total = [N_GAS, N_DARK, 0, 0, 0, 0]
    if files == 1:
        write_gadget_file(base, [gas, dark, None, None, None, None], mass_table, total, 1, L, dtype, endian, snap_format,
                          time=time)
        return str(base)
    cuts = ((0, SPLIT[0]), (0, SPLIT[1])), ((SPLIT[0], N_GAS), (SPLIT[1], N_DARK))
    for k, ((g0, g1), (d0, d1)) in enumerate(cuts):
        part = [{key: v[g0:g1] for key, v in gas.items()}, {key: v[d0:d1] for key, v in dark.items()}, None, None, None, None]
        write_gadget_file(f"{base}.{k}", part, mass_table, total, 2, L, dtype, endian, snap_format, time=time)
    return f"{base}.0"


def write_hdf5(path, p, dtype="f4", table_mass=False):
    """The same gas particles as a GADGET HDF5 snapshot (SnapFormat 3)."""
    with h5py.File(path, "w") as f:
        header = f.create_group("Header")
        header.attrs["NumPart_ThisFile"] = np.array([N_GAS, N_DARK, 0, 0, 0, 0], dtype=np.int32)
        header.attrs["NumPart_Total"] = np.array([N_GAS, N_DARK, 0, 0, 0, 0], dtype=np.uint32)
        header.attrs["MassTable"] = [p["gas_mass"][0] if table_mass else 0.0, 0, 0, 0, 0, 0]
        header.attrs["BoxSize"] = L
        header.attrs["NumFilesPerSnapshot"] = np.int32(1)
        part = f.create_group("PartType0")
        part["Coordinates"] = p["gas_pos"].astype(dtype)
        part["SmoothingLength"] = p["hsml"].astype(dtype)
        part["Density"] = p["rho"].astype(dtype)
        if not table_mass:
            part["Masses"] = p["gas_mass"].astype(dtype)


def measure(path, *args):
    done = subprocess.run([CLI, "particles", "cubic_bspline", str(path), "--code", "gadget2", *args, "--json"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def results(doc):
    """What a run computes, without what names its input file or times the run."""
    doc = dict(doc)
    for key in ("provenance", "phases", "inputs", "seconds", "cpu_seconds"):
        doc.pop(key)
    doc["source"] = {k: v for k, v in doc["source"].items() if k != "name"}
    return doc


def refused(path, *args):
    done = subprocess.run([CLI, "particles", "cubic_bspline", str(path), "--code", "gadget2", *args],
                          capture_output=True, text=True)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 3, done.stderr
    assert len(lines) == 1 and lines[0].startswith("sphkern: error: "), done.stderr
    return lines[0]


@pytest.fixture(scope="module")
def references(tmp_path_factory):
    """The HDF5 snapshot's results for each precision and place of the gas masses."""
    p = particles()
    folder = tmp_path_factory.mktemp("hdf5")
    found = {}
    for dtype in ("f4", "f8"):
        for table_mass in (False, True):
            path = folder / f"snap_{dtype}_{table_mass}.hdf5"
            write_hdf5(path, p, dtype, table_mass)
            found[dtype, table_mass] = measure(path)
    return p, found


@pytest.mark.parametrize("snap_format", [1, 2])
@pytest.mark.parametrize("dtype", ["f4", "f8"])
@pytest.mark.parametrize("endian", ["<", ">"])
@pytest.mark.parametrize("files", [1, 2])
@pytest.mark.parametrize("table_mass", [False, True])
def test_a_binary_snapshot_gives_the_results_of_the_same_hdf5_snapshot(tmp_path, references, snap_format, dtype, endian,
                                                                        files, table_mass):
    p, found = references
    reference = found[dtype, table_mass]
    assert reference["source"]["particles"] == N_GAS and reference["mean_neighbours"] > 20
    first = write_snapshot(tmp_path / "snap_000", p, files, dtype, endian, snap_format, table_mass)
    doc = measure(first)
    assert results(doc) == results(reference)
    if files == 2:
        # Any part names the snapshot, and so does its base name, as GADGET-2's find_files reads it.
        assert results(measure(tmp_path / "snap_000.1")) == results(reference)
        assert results(measure(tmp_path / "snap_000")) == results(reference)


def test_a_set_with_a_constant_z_is_read_as_2d(tmp_path):
    p = particles()
    p["gas_pos"][:, 2] = 0.5
    p["hsml"] = np.full(N_GAS, 0.15)
    path = write_snapshot(tmp_path / "flat", p)
    done = subprocess.run([CLI, "particles", "cubic_bspline", path, "--support-per-h", "1", "--dim", "2", "--json"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["source"]["particles"] == N_GAS


def test_a_file_splash_converts_to_gadget_reads_back_to_its_source(tmp_path):
    splash = shutil.which("splash")
    assert splash, "splash is not installed (the test setup installs it: share/bootstrap.sh)"
    rng = np.random.default_rng(7)
    n = 300
    columns = {"x": rng.uniform(0, 1, n), "y": rng.uniform(0, 1, n), "z": rng.uniform(0, 1, n),
               "h": 0.15 * rng.uniform(0.95, 1.05, n), "particle_mass": rng.uniform(0.9, 1.1, n) / n,
               "density": rng.uniform(0.9, 1.1, n), "vx": rng.normal(size=n), "vy": rng.normal(size=n),
               "vz": rng.normal(size=n), "u": np.ones(n)}
    rows = [" ".join(repr(float(columns[c][i])) for c in columns) for i in range(n)]
    (tmp_path / "dump.dat").write_text("# " + " ".join(columns) + "\n" + "\n".join(rows) + "\n")
    done = subprocess.run([splash, "to", "gadget", "dump.dat"], cwd=tmp_path, stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, timeout=60)
    out = tmp_path / "dump.dat.gadget"
    assert done.returncode == 0 and out.exists(), done.stdout + done.stderr
    # SPLASH writes HSML = 2 h (GADGET's support radius of the cubic spline of smoothing length h),
    # which sphkern reads as the support, R h with R = 2: h comes back as it was. It writes a
    # BoxSize of its own: the source's box is given instead.
    per_particle = tmp_path / "read.csv"
    done = subprocess.run([CLI, "particles", "cubic_bspline", str(out), "--box", "1,1,1", "--csv", str(per_particle),
                           "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    read = np.genfromtxt(per_particle, delimiter=",", names=True)
    for axis in "xyz":
        assert np.array_equal(read[axis], columns[axis]), axis
    assert np.array_equal(read["h"], columns["h"])
    # File volumes are m / rho: the masses and densities came through.
    assert np.allclose(read["volume"], columns["particle_mass"] / columns["density"], rtol=1e-15, atol=0)
    with open(tmp_path / "same.csv", "w") as f:
        f.write("x,y,z,h,m,rho\n")
        for i in range(n):
            values = [columns[c][i] for c in ("x", "y", "z")] + [2 * columns["h"][i]]
            values += [columns[c][i] for c in ("particle_mass", "density")]
            f.write(",".join(repr(float(v)) for v in values) + "\n")
    reference = subprocess.run([CLI, "particles", "cubic_bspline", str(tmp_path / "same.csv"), "--box", "1,1,1",
                                "--support-per-h", "1", "--json"], capture_output=True, text=True)
    assert reference.returncode == 0, reference.stderr
    assert results(json.loads(done.stdout)) == results(json.loads(reference.stdout))


def test_initial_conditions_have_no_h_and_take_the_codes(tmp_path):
    # read_ic.c reads POS, VEL, ID, MASS and U: initial conditions hold no RHO and no HSML.
    p = particles()
    ids = np.arange(1, N_GAS + 1)
    gas = {"pos": p["gas_pos"], "vel": p["gas_vel"], "id": ids, "mass": p["gas_mass"], "u": p["u"]}
    for snap_format in (1, 2):
        path = tmp_path / f"ics_{snap_format}"
        write_gadget_file(path, [gas, None, None, None, None, None], [0.0] * 6, [N_GAS, 0, 0, 0, 0, 0], 1, L, "f4", "<",
                          snap_format, gas_blocks=("U",))
        with h5py.File(tmp_path / "ics.hdf5", "w") as f:
            header = f.create_group("Header")
            header.attrs["NumPart_ThisFile"] = np.array([N_GAS, 0, 0, 0, 0, 0], dtype=np.int32)
            header.attrs["NumPart_Total"] = np.array([N_GAS, 0, 0, 0, 0, 0], dtype=np.uint32)
            header.attrs["MassTable"] = np.zeros(6)
            header.attrs["BoxSize"] = L
            header.attrs["NumFilesPerSnapshot"] = np.int32(1)
            part = f.create_group("PartType0")
            part["Coordinates"] = p["gas_pos"].astype("f4")
            part["Masses"] = p["gas_mass"].astype("f4")
        doc = measure(path, "--nngb", "40")
        assert results(doc) == results(measure(tmp_path / "ics.hdf5", "--nngb", "40"))
        assert doc["source"]["particles"] == N_GAS


def good_file(tmp_path, name="snap_000", **kwargs):
    return write_snapshot(tmp_path / name, particles(), **kwargs)


def test_a_truncated_file_is_refused_naming_the_record(tmp_path):
    path = good_file(tmp_path)
    data = open(path, "rb").read()
    open(path, "wb").write(data[: 264 + 4 + 100])  # 100 bytes into POS, record 2
    line = refused(path)
    assert "snap_000: record 2 declares 5520 bytes, but the file ends 100 bytes into it" in line
    assert "truncated" in line
    # Cut after a whole record: the blocks the header promises are missing.
    open(path, "wb").write(data[: 264 + 5528])
    assert "snap_000: the file ends after record 2; expected block VEL for 460 particles" in refused(path)
    # SnapFormat 2 cut after a label.
    path = good_file(tmp_path, "two", snap_format=2)
    data = open(path, "rb").read()
    open(path, "wb").write(data[: 16 + 264 + 16])
    assert "record 3, the label of block POS, is the file's last" in refused(path)


def test_records_whose_markers_differ_are_refused(tmp_path):
    path = good_file(tmp_path)
    data = bytearray(open(path, "rb").read())
    vel_end = 264 + 5528 + 4 + 5520
    data[vel_end: vel_end + 4] = struct.pack("<i", 80)
    open(path, "wb").write(bytes(data))
    assert "snap_000: record 3's end marker is 80, its start marker 5520 (a truncated or corrupt file?)" in refused(path)


def test_a_block_of_the_wrong_length_is_refused(tmp_path):
    p = particles()
    path = tmp_path / "snap_000"
    with open(path, "wb") as f:
        record(f, header_bytes([N_GAS, N_DARK, 0, 0, 0, 0], [0.0] * 6, [N_GAS, N_DARK, 0, 0, 0, 0], 1, L, "<"), "<")
        record(f, p["gas_pos"][:, :2].astype("<f4").tobytes(), "<")  # two coordinates
    assert ("snap_000: block POS (record 2) is 3200 bytes; expected 12 or 24 bytes per particle for 460 particles"
            in refused(path))
    # Format 2: a gas block, by its label.
    path = good_file(tmp_path, "labelled", snap_format=2)
    data = bytearray(open(path, "rb").read())
    hsml = data.rindex(b"HSML")
    end = len(data)
    data[hsml + 4: hsml + 8] = struct.pack("<i", 8 + 8)
    data[hsml + 12: end] = struct.pack("<i", 8) + b"\0" * 8 + struct.pack("<i", 8)
    open(path, "wb").write(bytes(data))
    assert "labelled: block HSML (record 16) is 8 bytes; expected 4 or 8 bytes per particle for 400 gas particles" in refused(path)


def test_the_parts_of_a_snapshot_must_agree(tmp_path):
    p = particles()
    first = write_snapshot(tmp_path / "snap_042", p, files=2)
    os.remove(tmp_path / "snap_042.1")
    assert "part 1 of the snapshot's 2 files" in refused(first) and "does not exist" in refused(first)
    # A part of another snapshot: its header's counts differ.
    write_snapshot(tmp_path / "snap_042", p, files=2)
    other = particles()
    write_snapshot(tmp_path / "other", other, files=2, table_mass=True)
    shutil.copy(tmp_path / "other.1", tmp_path / "snap_042.1")
    assert "snap_042.1: its header's MassTable differs from" in refused(first)
    # Counts that do not add up to npartTotal.
    path = tmp_path / "short.0"
    gas = {"pos": p["gas_pos"][:10], "vel": p["gas_vel"][:10], "id": np.arange(10), "mass": p["gas_mass"][:10],
           "u": p["u"][:10], "rho": p["rho"][:10], "hsml": p["hsml"][:10]}
    for k in range(2):
        write_gadget_file(tmp_path / f"short.{k}", [gas, None, None, None, None, None], [0.0] * 6, [25, 0, 0, 0, 0, 0], 2,
                          L, "f4", "<", 1)
    assert "the snapshot's 2 files hold 20 gas particles but their headers' npartTotal[0] declares 25" in refused(path)
