"""Phantom's dumps: files written here as Phantom writes them (dump_utils' open_dumpfile_w,
write_header, write_block_header and write_array, called as readwrite_dumps' write_fulldump and
write_smalldump call them) must give the statistics of the same particles in a CSV file, bit for
bit (real*8 full dumps, and real*4 small dumps against the float-rounded values); SPLASH reads
the same files back to the values written; broken files give one line naming the record or the
tag and exit 3. Run by ctest with SPHKERN_CLI set."""
import json
import os
import re
import shutil
import struct
import subprocess

import numpy as np
import pytest

CLI = os.environ["SPHKERN_CLI"]
N_SIDE, HFACT = 8, 1.2
N = N_SIDE**3
MAXTYPES = 8  # config.F90: 7 + 2*maxdustlarge - 1, maxdustlarge 1 in a build without dust
IGAS, IDUST = 1, 7


def particles():
    """512 particles on a jittered cubic lattice in the unit box, h = hfact (m/rho)^(1/3)."""
    rng = np.random.default_rng(11)
    grid = (np.stack(np.meshgrid(*[np.arange(N_SIDE)] * 3, indexing="ij"), -1).reshape(-1, 3) + 0.5) / N_SIDE
    x = grid + rng.uniform(-0.1, 0.1, grid.shape) / N_SIDE
    rho = rng.uniform(0.95, 1.05, N)
    m = 1.0 / N
    return {"x": x, "h": HFACT * (m / rho) ** (1 / 3), "m": m, "v": rng.normal(size=(N, 3)), "u": np.ones(N)}


def record(f, payload, endian="<"):
    f.write(struct.pack(endian + "i", len(payload)))
    f.write(payload)
    f.write(struct.pack(endian + "i", len(payload)))


def tags(names):
    return b"".join(n.ljust(16).encode() for n in names)


# dump_utils' data types, in their order: integer, int*1, int*2, int*4, int*8, real, real*4, real*8.
def codes(real):
    return ["i4", "i1", "i2", "i4", "i8", real, "f4", "f8"]


def write_dump(path, p, small=False, endian="<", types=None, box=True, drop=(), fileid=None, lower=0.0, time=0.0):
    """A dump as write_fulldump (FT, default real*8) or write_smalldump (ST, every real as
    real*4) writes it: the magic numbers, the file id, the header of 8 typed sections (count,
    tags, values), the number of blocks, the block headers, then the arrays of each block by
    type. `types` gives itype per particle (written when some are not gas), `drop` leaves out
    header values and arrays by tag."""
    real = "f4" if small else "f8"
    dt = [np.dtype(c).newbyteorder(endian) for c in codes(real)]
    n = len(p["x"])
    npartoftype = [0] * MAXTYPES
    if types is None:
        npartoftype[0] = n
    else:
        for t in types:
            npartoftype[t - 1] += 1
    massoftype = [0.0] * MAXTYPES
    massoftype[0] = p["m"]
    massoftype[IDUST - 1] = 0.01 * p["m"]
    header = [
        [("nparttot", n), ("ntypes", MAXTYPES)] + [("npartoftype", k) for k in npartoftype]
        + [("nblocks", 1), ("nptmass", 0), ("ndustlarge", 0), ("ndustsmall", 0), ("idust", IDUST), ("idtmax_n", 1),
           ("idtmax_frac", 0), ("idumpfile", 0), ("majorv", 2025), ("minorv", 0), ("microv", 0)],
        [], [],
        [("iexternalforce", 0), ("ieos", 1)],  # write_headeropts_eos then puts gamma first among the reals
        [("nparttot", n), ("ntypes", MAXTYPES)] + [("npartoftype", k) for k in npartoftype],
        [("gamma", 1.0), ("time", time), ("dtmax", 0.1), ("rhozero", 1.0), ("hfact", HFACT), ("tolh", 1e-4), ("C_cour", 0.3),
         ("C_force", 0.25), ("alpha", 1.0), ("alphau", 1.0), ("alphaB", 1.0)]
        + [("massoftype", m) for m in massoftype] + [("Bextx", 0.0), ("Bexty", 0.0), ("Bextz", 0.0), ("dum", 0.0)]
        + ([(f"{a}{end}", lower + side) for a in "xyz" for end, side in (("min", 0.0), ("max", 1.0))] if box else [])
        + [("get_conserv", 1.0), ("mtot_in", 0.0), ("etot_in", 0.0), ("angtot_in", 0.0), ("totmom_in", 0.0)],
        [],
        [("udist", 1.0), ("umass", 1.0), ("utime", 1.0), ("umagfd", 1.0)],
    ]
    header = [[(t, v) for t, v in section if t not in drop] for section in header]
    x = p["x"]
    # The hydro block's arrays by type, as write_fulldump's calls order them within each type.
    arrays = [[] for _ in range(8)]
    if types is not None:
        arrays[1].append(("itype", np.asarray(types)))
    arrays[5] += [("x", x[:, 0]), ("y", x[:, 1]), ("z", x[:, 2])]
    if not small:
        arrays[5] += [("vx", p["v"][:, 0]), ("vy", p["v"][:, 1]), ("vz", p["v"][:, 2]), ("u", p["u"])]
        arrays[4].append(("iorig", np.arange(1, n + 1)))
    arrays[6].append(("h", p["h"]))
    if not small:
        arrays[6] += [("alpha", np.ones(n)), ("divv", np.zeros(n)), ("dt", np.full(n, 0.01))]
    arrays = [[(t, v) for t, v in a if t not in drop] for a in arrays]
    if fileid is None:
        fileid = ("ST" if small else "FT") + ":Phantom:2025.0.0:0000000 (hydro): 01/01/2025 00:00:00.0"
    with open(path, "wb") as f:
        i4, r = np.dtype("i4").newbyteorder(endian), dt[5]
        record(f, np.array([60769], i4).tobytes() + np.array([60878.0], r).tobytes()
               + np.array([60878, 1, 690706], i4).tobytes(), endian)
        record(f, fileid.ljust(100).encode(), endian)
        for k, section in enumerate(header):
            record(f, np.array([len(section)], i4).tobytes(), endian)
            if section:
                record(f, tags([t for t, _ in section]), endian)
                record(f, np.array([v for _, v in section]).astype(dt[k]).tobytes(), endian)
        record(f, np.array([2], i4).tobytes(), endian)  # nblocks x narraylengths: hydro and sinks
        record(f, np.array([n], np.dtype("i8").newbyteorder(endian)).tobytes()
               + np.array([len(a) for a in arrays], i4).tobytes(), endian)
        record(f, np.array([0], np.dtype("i8").newbyteorder(endian)).tobytes() + np.zeros(8, i4).tobytes(), endian)
        for k, section in enumerate(arrays):
            for tag, values in section:
                record(f, tags([tag]), endian)
                record(f, np.asarray(values).astype(dt[k]).tobytes(), endian)
    return str(path)


def write_csv(path, x, h, m):
    with open(path, "w") as f:
        f.write("x,y,z,h,m\n")
        for q, hh in zip(x, h):
            f.write(f"{float(q[0])!r},{float(q[1])!r},{float(q[2])!r},{float(hh)!r},{float(m)!r}\n")


def run(path, *args):
    done = subprocess.run([CLI, "particles", "cubic_bspline", str(path), "--code", "phantom", *args, "--json"],
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


def refused(path):
    done = subprocess.run([CLI, "particles", "cubic_bspline", str(path), "--code", "phantom"], capture_output=True, text=True)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 3, done.stderr
    assert len(lines) == 1 and lines[0].startswith("sphkern: error: "), done.stderr
    return lines[0]


def f32(a):
    return np.asarray(a, dtype=np.float32).astype(np.float64)


@pytest.mark.parametrize("endian", ["<", ">"])
def test_a_full_dump_gives_the_results_of_the_same_csv(tmp_path, endian):
    p = particles()
    dump = write_dump(tmp_path / "disc_00000", p, endian=endian)
    write_csv(tmp_path / "same.csv", p["x"], f32(p["h"]), p["m"])  # write_fulldump writes h as real*4
    doc = run(dump)
    assert doc["source"]["particles"] == N and doc["mean_neighbours"] > 20
    assert results(doc) == results(run(tmp_path / "same.csv", "--box", "1,1,1"))


def test_a_small_dump_gives_the_results_of_the_float_rounded_csv(tmp_path):
    p = particles()
    dump = write_dump(tmp_path / "disc_00042.tmp", p, small=True)
    write_csv(tmp_path / "same.csv", f32(p["x"]), f32(p["h"]), f32(p["m"]))
    assert results(run(dump)) == results(run(tmp_path / "same.csv", "--box", "1,1,1"))


def test_only_gas_particles_are_read(tmp_path):
    p = particles()
    types = np.full(N, IGAS)
    types[::7] = IDUST
    dump = write_dump(tmp_path / "dusty_00001", p, types=types)
    gas = types == IGAS
    write_csv(tmp_path / "gas.csv", p["x"][gas], f32(p["h"][gas]), p["m"])
    doc = run(dump)
    assert doc["source"]["particles"] == gas.sum()
    assert results(doc) == results(run(tmp_path / "gas.csv", "--box", "1,1,1"))


def test_positions_are_taken_from_the_lower_corner_of_the_box(tmp_path):
    p = particles()
    p["x"] = p["x"] - 0.5
    dump = write_dump(tmp_path / "centred_00000", p, lower=-0.5)
    write_csv(tmp_path / "same.csv", p["x"] - (-0.5), f32(p["h"]), p["m"])
    assert results(run(dump)) == results(run(tmp_path / "same.csv", "--box", "1,1,1"))


def test_a_dump_without_bounds_is_free(tmp_path):
    p = particles()
    dump = write_dump(tmp_path / "free_00000", p, box=False)
    write_csv(tmp_path / "same.csv", p["x"], f32(p["h"]), p["m"])
    # Phantom stores no density, so a free set has no volumes of its own: --box gives them.
    assert "uniform volumes need a periodic box" in refused(dump)
    assert results(run(dump, "--box", "1,1,1")) == results(run(tmp_path / "same.csv", "--box", "1,1,1"))


@pytest.mark.parametrize("small", [False, True])
def test_splash_reads_the_dump_back_to_the_values_written(tmp_path, small):
    splash = shutil.which("splash")
    assert splash, "splash is not installed (the test setup installs it: share/bootstrap.sh)"
    p = particles()
    write_dump(tmp_path / "dump_00000", p, small=small)
    done = subprocess.run([splash, "to", "ascii", "-phantom", "dump_00000"], cwd=tmp_path, stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, timeout=60)
    out = tmp_path / "dump_00000.ascii"
    assert done.returncode == 0 and out.exists(), done.stdout + done.stderr
    # The last comment line names the columns, 24 characters each ("particle mass" is one).
    names = [line for line in out.read_text().splitlines() if line.startswith("#")][-1]
    names = re.split(r"\s{2,}", names.lstrip("#").strip())
    table = np.loadtxt(out, comments="#", ndmin=2)
    assert table.shape[0] == N
    # SPLASH writes 16 significant digits, one fewer than a double can need.
    expected = {"x": p["x"][:, 0], "y": p["x"][:, 1], "z": p["x"][:, 2], "h": f32(p["h"])}
    for name, values in expected.items():
        written = f32(values) if small else values
        assert np.allclose(table[:, names.index(name)], written, rtol=1e-15, atol=0), name


def good_dump(tmp_path, name="disc_00000", **kwargs):
    return write_dump(tmp_path / name, particles(), **kwargs)


def test_a_truncated_dump_is_refused_naming_the_record(tmp_path):
    path = good_dump(tmp_path)
    data = open(path, "rb").read()
    open(path, "wb").write(data[:-100])
    line = refused(path)
    assert "disc_00000: record" in line and "but the file ends" in line and "truncated" in line
    # Cut after a whole record: what comes next is named.
    open(path, "wb").write(data[:32 + 108])
    assert "disc_00000: the file ends after record 2; expected the number of integer header values" in refused(path)


def test_records_whose_markers_differ_are_refused(tmp_path):
    path = good_dump(tmp_path)
    data = bytearray(open(path, "rb").read())
    data[32 + 104: 32 + 108] = struct.pack("<i", 99)  # the file id's end marker
    open(path, "wb").write(bytes(data))
    assert "disc_00000: record 2's end marker is 99, its start marker 100" in refused(path)


def test_an_array_of_the_wrong_length_is_refused(tmp_path):
    p = particles()
    p["h"] = p["h"][:-1]
    path = write_dump(tmp_path / "short_00000", p)
    line = refused(path)
    assert "short_00000: array h (record" in line and f"expected 4 (real*4) for each of the block's {N} particles" in line


def test_a_dump_without_positions_or_masses_is_refused(tmp_path):
    path = good_dump(tmp_path, drop=("x",))
    assert f"disc_00000: block 1 has no real array x; expected the positions x, y, z of its {N} particles" in refused(path)
    p = particles()
    p["m"] = 0.0
    path = write_dump(tmp_path / "massless_00000", p)
    assert "massless_00000: its header's massoftype(1) is 0" in refused(path)
    path = good_dump(tmp_path, "nomass_00000", drop=("massoftype",))
    assert "nomass_00000: its header has no massoftype; expected the gas particle mass" in refused(path)


def test_an_untagged_dump_is_refused(tmp_path):
    path = good_dump(tmp_path, fileid="FU:sphNG")
    assert "expected a tagged dump" in refused(path)
