"""`relax --code phantom --output NAME` writes a Phantom full dump Phantom starts from. The dump
is read here by a reader of its own (Phantom's records, as dump_utils' read_header and
read_dump lay them out), by SPLASH's Phantom reader, and checked against values derived apart
from the writer: the same run's CSV (x, y, z to 17 digits; h as the real*4 Phantom writes it), Phantom's h-rho relation
rho = m (hfact / h)^3 against the SPH density summed here with Phantom's cubic kernel, or
against m / V where no hfact is given. Run by ctest with SPHKERN_CLI set."""
import os
import re
import shutil
import struct
import subprocess

import numpy as np
import pytest

CLI = os.environ["SPHKERN_CLI"]
COUNT, BOX, HFACT, GAMMA = 300, (1.0, 1.5, 1.0), 1.2, 5.0 / 3.0
TYPES = ["i4", "i1", "i2", "i4", "i8", "f8", "f4", "f8"]  # dump_utils' types; "real" is 8 bytes in a full dump


def relax(path, *code):
    """A small relaxed Poisson set in a 1 x 1.5 x 1 box, on one thread (the same run each time)."""
    args = [CLI, "relax", "cubic_bspline", "poisson", "--count", str(COUNT), "--box", ",".join(map(str, BOX)),
            "--seed", "4", "--steps", "5", "--threads", "1", "--code", "phantom", *code, "--output", str(path)]
    done = subprocess.run(args, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return done.stdout


def records(path):
    data = open(path, "rb").read()
    out, at = [], 0
    while at < len(data):
        (n,) = struct.unpack_from("<i", data, at)
        assert struct.unpack_from("<i", data, at + 4 + n) == (n,), f"record at byte {at}: markers differ"
        out.append(data[at + 4:at + 4 + n])
        at += n + 8
    return out


def read_dump(path):
    """The header (each tag's values, in order) and the hydro block's arrays by tag."""
    rec = iter(records(path))
    magic = next(rec)
    assert len(magic) == 24 and struct.unpack("<id3i", magic) == (60769, 60878.0, 60878, 1, 690706)
    fileid = next(rec).decode()
    assert len(fileid) == 100 and fileid.startswith("FT:Phantom")
    header = {}
    for t in TYPES:
        (n,) = struct.unpack("<i", next(rec))
        if n == 0:
            continue
        tags = next(rec)
        values = np.frombuffer(next(rec), dtype=t)
        assert len(values) == n
        for i in range(n):
            header.setdefault(tags[16 * i:16 * i + 16].decode().strip(), []).append(values[i].item())
    (blocks,) = struct.unpack("<i", next(rec))
    assert blocks == 2  # one MPI block: hydro and sinks
    lengths = [struct.unpack("<q8i", next(rec)) for _ in range(blocks)]
    arrays = {}
    for rows, *counts in lengths:
        for t, count in zip(TYPES, counts):
            for _ in range(count):
                tag = next(rec).decode().strip()
                values = np.frombuffer(next(rec), dtype=t)
                assert len(values) == rows, tag
                arrays[tag] = values
    assert next(rec, None) is None
    return header, arrays


def read_csv(path):
    table = np.loadtxt(path, delimiter=",", comments="#", skiprows=2)
    return {"x": table[:, 0], "y": table[:, 1], "z": table[:, 2], "h": table[:, 3], "m": table[:, 4]}


def cubic(q):
    """Phantom's kernel_cubic.f90 without its normalisation 1 / pi: support 2 h."""
    return np.where(q < 1, 1 - 1.5 * q**2 + 0.75 * q**3, np.where(q < 2, 0.25 * (2 - q) ** 3, 0.0))


def sph_density(x, h, m, box):
    """rho_i = sum_j m W(|r_ij|, h_i), the particle itself included, nearest images in the box."""
    d = x[:, None, :] - x[None, :, :]
    d -= np.asarray(box) * np.round(d / np.asarray(box))
    r = np.sqrt((d**2).sum(-1))
    return m * (cubic(r / h[:, None]) / (np.pi * h[:, None] ** 3)).sum(1)


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    """One run with Phantom's hfact, written as a dump and as CSV."""
    folder = tmp_path_factory.mktemp("phantom")
    out = relax(folder / "glass_00000.tmp", "--hfact", str(HFACT))
    assert "Phantom full dump" in out
    relax(folder / "glass.csv", "--hfact", str(HFACT))
    header, arrays = read_dump(folder / "glass_00000.tmp")
    return folder, header, arrays, read_csv(folder / "glass.csv")


def test_the_dump_holds_the_runs_set_bit_for_bit(solved):
    _, header, arrays, csv = solved
    for tag in "xyz":
        assert arrays[tag].dtype == np.float64 and np.array_equal(arrays[tag], csv[tag]), tag
    # write_fulldump writes h as real*4 (use_kind=4).
    assert arrays["h"].dtype == np.float32 and np.array_equal(arrays["h"], csv["h"].astype(np.float32))
    assert header["massoftype"][0] == csv["m"][0] and not any(header["massoftype"][1:])
    assert header["nparttot"] == [COUNT, COUNT] and header["npartoftype"][0] == COUNT
    assert [header[f"{a}{e}"][0] for a in "xyz" for e in ("min", "max")] == [0, BOX[0], 0, BOX[1], 0, BOX[2]]
    assert header["hfact"] == [HFACT] and header["gamma"] == [GAMMA]
    # At rest, with the relaxation's sound speed c = 1: u = c^2 / (gamma (gamma - 1)).
    assert not (arrays["vx"].any() or arrays["vy"].any() or arrays["vz"].any())
    assert np.allclose(arrays["u"], 1 / (GAMMA * (GAMMA - 1)), rtol=1e-15, atol=0)
    assert list(arrays["iorig"]) == list(range(1, COUNT + 1))
    assert "itype" not in arrays  # gas alone: write_fulldump writes itype only beside other types


def test_sphkern_reads_the_dump_as_the_csv(solved):
    folder, *_ = solved
    def measured(path, *extra):
        done = subprocess.run([CLI, "particles", "cubic_bspline", str(path), "--code", "phantom", *extra, "--json"],
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, done.stderr
        import json
        doc = json.loads(done.stdout)
        return {k: v for k, v in doc.items() if k not in ("provenance", "phases", "inputs", "seconds", "cpu_seconds", "source")}
    # h solved again on the set: the dump's positions, masses and box are the CSV's.
    setting = ("--hfact", str(HFACT))
    assert measured(folder / "glass_00000.tmp", *setting) == measured(folder / "glass.csv", *setting, "--box",
                                                                      ",".join(map(str, BOX)))


def test_splash_reads_x_y_z_and_h(solved):
    folder, _, _, csv = solved
    splash = shutil.which("splash")
    assert splash, "splash is not installed (the test setup installs it: share/bootstrap.sh)"
    done = subprocess.run([splash, "to", "ascii", "-phantom", "glass_00000.tmp"], cwd=folder, stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, timeout=60)
    out = folder / "glass_00000.tmp.ascii"
    assert done.returncode == 0 and out.exists(), done.stdout + done.stderr
    names = [line for line in out.read_text().splitlines() if line.startswith("#")][-1]
    names = re.split(r"\s{2,}", names.lstrip("#").strip())
    table = np.loadtxt(out, comments="#", ndmin=2)
    assert table.shape[0] == COUNT
    # SPLASH writes 16 significant digits, one fewer than a double can need; h is the real*4 written.
    for name in "xyz":
        assert np.allclose(table[:, names.index(name)], csv[name], rtol=1e-15, atol=0), name
    h = csv["h"].astype(np.float32).astype(np.float64)
    assert np.allclose(table[:, names.index("h")], h, rtol=1e-15, atol=0)
    # SPLASH's density is Phantom's relation on the h it read: rho = m (hfact / h)^3.
    assert np.allclose(table[:, names.index("density")], csv["m"] * (HFACT / h) ** 3, rtol=1e-12, atol=0)


def test_phantoms_h_rho_relation_holds_with_the_sph_density(solved):
    _, header, arrays, _ = solved
    x = np.stack([arrays["x"], arrays["y"], arrays["z"]], 1)
    m, hfact = header["massoftype"][0], header["hfact"][0]
    h = arrays["h"].astype(np.float64)
    rho = sph_density(x, h, m, BOX)
    # h is real*4: the relation holds to its rounding, 3 x 2^-24 relative, and the density sum's change with it.
    assert np.allclose(m * (hfact / h) ** 3, rho, rtol=1e-6, atol=0)
    assert header["rhozero"][0] == pytest.approx(COUNT * m / np.prod(BOX), rel=1e-14)


def test_without_hfact_every_h_is_the_runs_and_the_relation_gives_m_over_v(tmp_path):
    relax(tmp_path / "even_00000")
    header, arrays = read_dump(tmp_path / "even_00000")
    h, m, hfact = arrays["h"].astype(np.float64), header["massoftype"][0], header["hfact"][0]
    assert np.all(h == h[0])
    assert m * (hfact / h[0]) ** 3 == pytest.approx(COUNT * m / np.prod(BOX), rel=1e-6)  # h is real*4
    # sphkern's default h is 1.2 mean spacings (--h-over-l), the spacing (V / N)^(1/3).
    assert hfact == pytest.approx(1.2, rel=1e-13)
