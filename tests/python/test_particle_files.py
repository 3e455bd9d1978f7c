"""`sphkern particles` on the files other codes write: one set of particles stored as CSV,
SWIFT and GADGET HDF5, PySPH HDF5 and big-endian BINARY legacy VTK (POLYDATA and
UNSTRUCTURED_GRID) must give the same statistics as the CSV; broken files give one line
and exit 3, with no HDF5 error stack. Run by ctest with SPHKERN_CLI set."""
import json
import os
import struct
import subprocess

import numpy as np
import pytest

import fluid_tanks

h5py = pytest.importorskip("h5py")

CLI = os.environ["SPHKERN_CLI"]
GAMMA = 1.936492  # SWIFT's kernel gamma of Wendland C2 in 3D
N, L = 1500, 1.0


def particles():
    rng = np.random.default_rng(2026)
    x = rng.uniform(0, L, (N, 3))
    h = 0.085 * rng.uniform(0.9, 1.1, N)
    m = (L**3 / N) * rng.uniform(0.8, 1.2, N)
    rho = rng.uniform(0.9, 1.1, N)
    return x, h, m, rho


def run(*args):
    done = subprocess.run([CLI, "particles", "wendland_c2", *args, "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def refused(*args, code=3):
    done = subprocess.run([CLI, "particles", "wendland_c2", *args], capture_output=True, text=True)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == code, done.stderr
    assert len(lines) == 1 and lines[0].startswith("sphkern: error: "), done.stderr
    return lines[0]


def write_csv(path, x, h, m, rho):
    with open(path, "w") as f:
        f.write("x,y,z,h,m,rho\n")
        for p, hh, mm, r in zip(x, h, m, rho):
            f.write(f"{p[0]!r},{p[1]!r},{p[2]!r},{hh!r},{mm!r},{r!r}\n")


def write_swift(path, x, h, m, rho, gamma=True, kernel=None, kernel_gamma=GAMMA):
    with h5py.File(path, "w") as f:
        header = f.create_group("Header")
        header.attrs["BoxSize"] = [L, L, L]
        header.attrs["Dimension"] = 3
        header.attrs["NumPart_Total"] = [N, 0, 0, 0, 0, 0]
        header.attrs["MassTable"] = [0.0] * 6
        if gamma:
            f.create_group("HydroScheme").attrs["Kernel gamma"] = kernel_gamma
        if kernel:
            f.require_group("HydroScheme").attrs["Kernel function"] = np.bytes_(kernel)  # fixed length, as SWIFT writes
        part = f.create_group("PartType0")
        part["Coordinates"] = x
        part["SmoothingLengths"] = h
        part["Masses"] = m
        part["Densities"] = rho


def write_gadget(path, x, h, m, rho):
    with h5py.File(path, "w") as f:
        header = f.create_group("Header")
        header.attrs["BoxSize"] = L
        header.attrs["NumPart_Total"] = np.array([N, 0, 0, 0, 0, 0], dtype=np.uint32)
        header.attrs["MassTable"] = [m[0], 0, 0, 0, 0, 0]
        part = f.create_group("PartType0")
        part["Coordinates"] = x.astype(np.float32)
        part["SmoothingLength"] = h.astype(np.float32)
        part["Density"] = rho.astype(np.float32)


def write_gadget4(path, x, support, m, rho, swift_mark=False):
    """A snapshot as GADGET-4 writes it (io.cc, snap_io.cc): /Header, /Parameters and /Config
    (its compile-time options) beside /PartType0, single-precision particle fields."""
    with h5py.File(path, "w") as f:
        header = f.create_group("Header")
        header.attrs["NumPart_ThisFile"] = np.array([N, 0, 0, 0, 0, 0], dtype=np.uint64)
        header.attrs["NumPart_Total"] = np.array([N, 0, 0, 0, 0, 0], dtype=np.uint64)
        header.attrs["MassTable"] = np.zeros(6)
        header.attrs["Time"], header.attrs["Redshift"], header.attrs["BoxSize"] = 0.0, 0.0, L
        header.attrs["NumFilesPerSnapshot"] = np.int32(1)
        header.attrs["Git_commit"], header.attrs["Git_date"] = np.bytes_("0123abc"), np.bytes_("2020-01-01")
        if swift_mark:
            header.attrs["Code"] = np.bytes_("SWIFT")
        parameters = f.create_group("Parameters")
        parameters.attrs["DesNumNgb"], parameters.attrs["BoxSize"] = 64, L
        config = f.create_group("Config")
        config.attrs["PERIODIC"], config.attrs["NTYPES"] = 1, 6
        part = f.create_group("PartType0")
        part["Coordinates"] = x.astype(np.float32)
        part["Velocities"] = np.zeros_like(x, dtype=np.float32)
        part["ParticleIDs"] = np.arange(1, N + 1, dtype=np.uint32)
        part["Masses"] = m.astype(np.float32)
        part["Density"] = rho.astype(np.float32)
        part["SmoothingLength"] = support.astype(np.float32)
        part["InternalEnergy"] = np.ones(N, dtype=np.float32)


def write_pysph(path, x, h, m, rho):
    with h5py.File(path, "w") as f:
        for name, scale in (("fluid", 1.0), ("solid", 0.5)):
            arrays = f.create_group(f"particles/{name}/arrays")
            for key, values in (("x", x[:, 0]), ("y", x[:, 1]), ("z", x[:, 2]), ("h", h), ("m", m), ("rho", rho)):
                arrays[key] = values * (scale if key in "xyz" else 1.0)


def write_vtk_binary(path, x, h, m, rho, unstructured):
    with open(path, "wb") as f:
        kind = "UNSTRUCTURED_GRID" if unstructured else "POLYDATA"
        f.write(f"# vtk DataFile Version 3.0\nparticles\nBINARY\nDATASET {kind}\nPOINTS {N} double\n".encode())
        f.write(struct.pack(f">{3 * N}d", *x.ravel()))
        if unstructured:
            f.write(f"\nCELLS {N} {2 * N}\n".encode())
            f.write(struct.pack(f">{2 * N}i", *[v for i in range(N) for v in (1, i)]))
            f.write(f"\nCELL_TYPES {N}\n".encode())
            f.write(struct.pack(f">{N}i", *([1] * N)))
        else:
            f.write(f"\nVERTICES {N} {2 * N}\n".encode())
            f.write(struct.pack(f">{2 * N}i", *[v for i in range(N) for v in (1, i)]))
        f.write(f"\nPOINT_DATA {N}\nSCALARS h float 1\nLOOKUP_TABLE default\n".encode())
        f.write(struct.pack(f">{N}f", *h))
        f.write(b"\nFIELD FieldData 3\n")
        f.write(f"mass 1 {N} double\n".encode())
        f.write(struct.pack(f">{N}d", *m))
        f.write(f"\nvelocity 3 {N} double\n".encode())
        f.write(struct.pack(f">{3 * N}d", *np.zeros(3 * N)))
        f.write(f"\ndensity 1 {N} double\n".encode())
        f.write(struct.pack(f">{N}d", *rho))
        f.write(b"\n")


def close(a, b, tol):
    for key in b["statistics"]:
        for stat in b["statistics"][key]:
            x, y = a["statistics"][key][stat], b["statistics"][key][stat]
            assert abs(x - y) <= tol * (1 + abs(y)), (key, stat, x, y)


def test_every_format_gives_the_statistics_of_the_csv(tmp_path):
    x, h, m, rho = particles()
    write_csv(tmp_path / "set.csv", x, h, m, rho)
    box = ["--box", f"{L},{L},{L}"]
    reference = run(str(tmp_path / "set.csv"), "--support-per-h", str(GAMMA), *box)
    assert reference["volume"] == "file" and reference["source"]["particles"] == N
    assert reference["mean_neighbours"] > 20

    write_swift(tmp_path / "swift.hdf5", x, h, m, rho)
    close(run(str(tmp_path / "swift.hdf5")), reference, 1e-13)  # box and gamma from the file
    write_pysph(tmp_path / "pysph.h5", x, h, m, rho)
    close(run(str(tmp_path / "pysph.h5"), "--support-per-h", str(GAMMA), *box), reference, 1e-13)
    for unstructured in (False, True):
        path = tmp_path / f"set-{unstructured}.vtk"
        # h stored as float: compare with a CSV of the same rounded h.
        write_vtk_binary(path, x, h, m, rho, unstructured)
    h32 = h.astype(np.float32).astype(np.float64)
    write_csv(tmp_path / "set32.csv", x, h32, m, rho)
    reference32 = run(str(tmp_path / "set32.csv"), "--support-per-h", str(GAMMA), *box)
    for unstructured in (False, True):
        close(run(str(tmp_path / f"set-{unstructured}.vtk"), "--support-per-h", str(GAMMA), *box), reference32, 1e-13)

    # GADGET: float32 coordinates, masses from the MassTable, its SmoothingLength is the support radius.
    support = GAMMA * h
    write_gadget(tmp_path / "gadget.hdf5", x, support, m, rho)
    f32 = lambda a: a.astype(np.float32).astype(np.float64)
    write_csv(tmp_path / "gadget.csv", f32(x), f32(support), np.full(N, m[0]), f32(rho))
    close(run(str(tmp_path / "gadget.hdf5"), "--support-per-h", "1"),
          run(str(tmp_path / "gadget.csv"), "--support-per-h", "1", *box), 1e-13)


def test_a_gadget4_snapshot_is_read_with_its_h_as_the_support(tmp_path):
    x, h, m, rho = particles()
    support = GAMMA * h
    write_gadget4(tmp_path / "gadget4.hdf5", x, support, m, rho)
    f32 = lambda a: a.astype(np.float32).astype(np.float64)
    write_csv(tmp_path / "same.csv", f32(x), f32(support), f32(m), f32(rho))
    box = ["--box", f"{L},{L},{L}"]
    # No --support-per-h: the file is GADGET's, whose SmoothingLength is the support radius.
    close(run(str(tmp_path / "gadget4.hdf5")), run(str(tmp_path / "same.csv"), "--support-per-h", "1", *box), 1e-13)
    # A convention given still rules: the support is then 1.5 times the stored h.
    close(run(str(tmp_path / "gadget4.hdf5"), "--support-per-h", "1.5"),
          run(str(tmp_path / "same.csv"), "--support-per-h", "1.5", *box), 1e-13)
    # A mark of SWIFT's makes it no GADGET file: its h then needs a convention.
    write_gadget4(tmp_path / "marked.hdf5", x, support, m, rho, swift_mark=True)
    assert "--support-per-h X" in refused(str(tmp_path / "marked.hdf5"))


def test_pysph_arrays_and_conventions_are_asked_for(tmp_path):
    x, h, m, rho = particles()
    write_pysph(tmp_path / "pysph.h5", x, h, m, rho)
    assert "--support-per-h X" in refused(str(tmp_path / "pysph.h5"), "--array", "fluid")
    write_swift(tmp_path / "nogamma.hdf5", x, h, m, rho, gamma=False)
    assert "SWIFT its kernel gamma" in refused(str(tmp_path / "nogamma.hdf5"))
    assert "no particle array \"gas\"; the file has fluid, solid" in refused(
        str(tmp_path / "pysph.h5"), "--array", "gas", "--h-over-l", "1.2", "--box", "1,1,1")
    # Without --array, PySPH's "fluid" is the default.
    doc = run(str(tmp_path / "pysph.h5"), "--h-over-l", "1.2", "--box", "1,1,1")
    assert doc["source"]["particles"] == N


def test_a_swift_snapshot_of_another_kernel_is_refused_unless_its_h_is_mapped(tmp_path):
    # SWIFT's cubic spline (M4): gamma = sqrt(10/3) in 3D (Dehnen & Aly 2012, table 1).
    x, h, m, rho = particles()
    cubic_gamma = np.sqrt(10 / 3)
    write_swift(tmp_path / "cubic.hdf5", x, h, m, rho, kernel="Cubic spline (M4)", kernel_gamma=cubic_gamma)
    line = refused(str(tmp_path / "cubic.hdf5"))  # run with wendland_c2
    assert 'are for its kernel "Cubic spline (M4)" (sphkern\'s cubic_bspline), not wendland_c2' in line, line
    assert "--support-per-h X" in line, line
    # The kernel the file names takes the file's h as it is; a mapped h goes with any kernel.
    done = subprocess.run([CLI, "particles", "cubic_bspline", str(tmp_path / "cubic.hdf5"), "--json"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    write_csv(tmp_path / "cubic.csv", x, h, m, rho)
    close(json.loads(done.stdout), json.loads(subprocess.run(
        [CLI, "particles", "cubic_bspline", str(tmp_path / "cubic.csv"), "--support-per-h", repr(cubic_gamma),
         "--box", f"{L},{L},{L}", "--json"], capture_output=True, text=True, check=True).stdout), 1e-13)
    assert run(str(tmp_path / "cubic.hdf5"), "--support-per-h", str(GAMMA))["source"]["particles"] == N
    # A label sphkern does not know is still a kernel other than the one asked for.
    write_swift(tmp_path / "other.hdf5", x, h, m, rho, kernel="Gaussian (truncated)")
    assert 'are for its kernel "Gaussian (truncated)", not wendland_c2' in refused(str(tmp_path / "other.hdf5"))
    write_swift(tmp_path / "same.hdf5", x, h, m, rho, kernel="Wendland C2")
    assert run(str(tmp_path / "same.hdf5"))["source"]["particles"] == N


def test_a_code_named_alone_reads_the_stored_h_as_that_code_stores_it(tmp_path):
    x, h, m, rho = particles()
    box = ["--box", f"{L},{L},{L}"]
    write_csv(tmp_path / "set.csv", x, h, m, rho)
    # SWIFT's gamma of Wendland C2 in 3D from its definition, H / (2 sigma) with sigma^2 the
    # kernel's second moment over D (Dehnen & Aly 2012): W = 21 / (2 pi) (1 - q)^4 (1 + 4 q), q = r / H.
    q = np.linspace(0, 1, 200001)
    w = 21 / (2 * np.pi) * (1 - q) ** 4 * (1 + 4 * q)
    second_moment = np.trapz(4 * np.pi * q**4 * w, q) / 3
    swift_gamma = 1 / (2 * np.sqrt(second_moment))
    write_swift(tmp_path / "swift.hdf5", x, h, m, rho, kernel="Wendland C2")
    doc = run(str(tmp_path / "swift.hdf5"), "--code", "swift")
    assert doc["code"]["h_from"] == "file" and doc["code"]["pair_h"] == "own"
    assert abs(doc["code"]["support_per_h"] - swift_gamma) < 1e-9
    close(doc, run(str(tmp_path / "set.csv"), "--support-per-h", repr(doc["code"]["support_per_h"]), *box), 1e-15)
    # GADGET stores the support itself.
    write_csv(tmp_path / "support.csv", x, 2 * h, m, rho)
    close(run(str(tmp_path / "support.csv"), "--code", "gadget4", *box),
          run(str(tmp_path / "set.csv"), "--support-per-h", "2", *box), 1e-15)
    # The file's kernel is the one asked; a code is not mapped onto another's h.
    write_swift(tmp_path / "cubic.hdf5", x, h, m, rho, kernel="Cubic spline (M4)", kernel_gamma=np.sqrt(10 / 3))
    assert 'h is for its kernel "Cubic spline (M4)" (sphkern\'s cubic_bspline), not wendland_c2' in refused(
        str(tmp_path / "cubic.hdf5"), "--code", "swift")
    assert "gadget2 does not ship it; its kernels are cubic_bspline" in refused(
        str(tmp_path / "set.csv"), "--code", "gadget2", *box, code=2)
    done = subprocess.run([CLI, "particles", "wendland_c2", str(tmp_path / "swift.hdf5"), "--code", "swift",
                           "--support-per-h", "2"], capture_output=True, text=True)
    assert done.returncode == 2 and "--code: gives the support over h; expected no --support-per-h" in done.stderr


def test_a_relaxed_glass_is_written_as_swift_initial_conditions_of_its_kernel(tmp_path):
    out = tmp_path / "glass.hdf5"
    subprocess.run([CLI, "relax", "wendland_c2", "poisson", "--count", "400", "--steps", "3", "--output", str(out)],
                   capture_output=True, text=True, check=True)
    with h5py.File(out, "r") as f:
        gamma = f["HydroScheme"].attrs["Kernel gamma"]
        assert f["HydroScheme"].attrs["Kernel function"] == b"Wendland C2"
        stored = f["PartType0/SmoothingLength"][:]
        # What SWIFT reads as initial conditions (hydro_read_particles, read_ic_single): all there.
        for key in ("Coordinates", "Velocities", "Masses", "SmoothingLength", "InternalEnergy", "ParticleIDs"):
            assert f["PartType0"][key].shape[0] == 400, key
        for key in ("BoxSize", "NumPart_Total", "NumPart_Total_HighWord", "Flag_Entropy_ICs"):
            assert key in f["Header"].attrs, key
        assert not f["PartType0/Velocities"][:].any() and sorted(f["PartType0/ParticleIDs"][:]) == list(range(1, 401))
        # An ideal gas with the relaxation's sound speed c = 1 and gamma = 5/3: u = c^2 / (gamma (gamma - 1)).
        assert np.allclose(f["PartType0/InternalEnergy"][:], 1 / (5 / 3 * (5 / 3 - 1)), rtol=1e-15, atol=0)
    # SWIFT's Wendland C2 in 3D: gamma = sqrt(15 / 4) (kernel_hydro.h: 1.936492).
    assert abs(gamma - np.sqrt(15 / 4)) < 1e-12
    # H = gamma h_SWIFT is sphkern's support R h, with h = 1.2 mean spacings (the default eta) in a unit box.
    assert np.allclose(stored * gamma, 2 * 1.2 * (1 / 400) ** (1 / 3), rtol=1e-12, atol=0)
    assert run(str(out))["source"]["particles"] == 400  # read back with its own kernel
    other = subprocess.run([CLI, "particles", "cubic_bspline", str(out)], capture_output=True, text=True)
    assert other.returncode == 3 and 'are for its kernel "Wendland C2"' in other.stderr, other.stderr


def relax_for(tmp_path, kernel, name, *code, count=600):
    out = tmp_path / name
    done = subprocess.run([CLI, "relax", kernel, "poisson", "--count", str(count), "--steps", "20", "--output", str(out),
                           "--json", *code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return out, json.loads(done.stdout)


def periodic_density(x, support, w, box=(1.0, 1.0, 1.0)):
    """rho_i / m = sum_j W(r_ij, H_i) over the minimum images in the box, i itself included."""
    box = np.asarray(box)
    d = x[:, None, :] - x[None, :, :]
    d -= np.round(d / box) * box
    q = np.sqrt((d**2).sum(axis=2)) / support[:, None]
    return (w(np.minimum(q, 1)) / support[:, None] ** 3).sum(axis=1)


def test_initial_conditions_for_gadget_and_swift_hold_the_codes_own_h(tmp_path):
    # GADGET-2: the weighted neighbour number (4 pi / 3) H^3 rho / m = N_ngb with its cubic
    # spline on the support H, W = 8 / (pi H^3) (1 - 6 u^2 + 6 u^3 | 2 (1 - u)^3).
    out, doc = relax_for(tmp_path, "cubic_bspline", "gadget.hdf5", "--code", "gadget2", "--nngb", "58")
    assert doc["code"] == {"name": "gadget2", "parameter": "nngb", "value": 58.0, "layout": "gadget",
                           "written_h": "sph_density"}
    cubic = lambda u: 8 / np.pi * np.where(u < 0.5, 1 - 6 * u**2 + 6 * u**3, 2 * (1 - u) ** 3)
    with h5py.File(out, "r") as f:
        header = f["Header"].attrs
        # What GADGET-2's read_header_attributes_in_hdf5 reads, Flag_Entropy_ICs into one int.
        for key in ("NumPart_ThisFile", "NumPart_Total", "NumPart_Total_HighWord", "MassTable"):
            assert header[key].shape == (6,), key
        assert header["NumPart_ThisFile"][0] == 600 and header["NumPart_Total"][0] == 600
        assert np.shape(header["Flag_Entropy_ICs"]) == () and header["NumFilesPerSnapshot"] == 1
        assert header["BoxSize"] == 1.0
        part = f["PartType0"]
        x, support = part["Coordinates"][:], part["SmoothingLength"][:]
        assert sorted(part["ParticleIDs"][:]) == list(range(1, 601)) and not part["Velocities"][:].any()
        assert len(set(support)) > 1  # each particle's own
    nngb = 4 * np.pi / 3 * support**3 * periodic_density(x, support, cubic)
    assert np.max(np.abs(nngb - 58)) < 1e-9
    # SWIFT: eta = h (rho / m)^(1/3), H = gamma h, Wendland C2: W = 21 / (2 pi H^3) (1 - q)^4 (1 + 4 q).
    out, _ = relax_for(tmp_path, "wendland_c2", "swift.hdf5", "--code", "swift", "--eta", "1.2348")
    wendland = lambda q: 21 / (2 * np.pi) * (1 - q) ** 4 * (1 + 4 * q)
    with h5py.File(out, "r") as f:
        gamma = f["HydroScheme"].attrs["Kernel gamma"]
        x, h = f["PartType0/Coordinates"][:], f["PartType0/SmoothingLength"][:]
    assert abs(gamma - np.sqrt(15 / 4)) < 1e-12
    eta = h * periodic_density(x, gamma * h, wendland) ** (1 / 3)
    assert np.max(np.abs(eta - 1.2348)) < 1e-9
    # Read back with the code alone: the same h as solving the code's setting on the file.
    alone = run(str(out), "--code", "swift")
    solved = run(str(out), "--code", "swift", "--eta", "1.2348")
    assert abs(alone["h_min"] - solved["h_min"]) < 1e-12 and abs(alone["h_max"] - solved["h_max"]) < 1e-12
    # Tiled copies take their original's h, which holds SWIFT's definition in the larger box too.
    out, _ = relax_for(tmp_path, "wendland_c2", "tiled.hdf5", "--code", "swift", "--eta", "1.2348", "--tile", "2,1,1",
                       count=300)
    with h5py.File(out, "r") as f:
        x, h = f["PartType0/Coordinates"][:], f["PartType0/SmoothingLength"][:]
        assert list(f["Header"].attrs["BoxSize"]) == [2.0, 1.0, 1.0] and len(h) == 600
    assert np.array_equal(h[:300], h[300:])
    eta = h * periodic_density(x, gamma * h, wendland, box=(2, 1, 1)) ** (1 / 3)
    assert np.max(np.abs(eta - 1.2348)) < 1e-9


def test_initial_conditions_for_pysph_are_what_its_load_reads(tmp_path):
    from pysph.solver.utils import load
    out, doc = relax_for(tmp_path, "wendland_c2", "pysph.hdf5", "--code", "pysph", "--hdx", "1.3")
    assert doc["code"]["written_h"] == "run_h"
    fluid = load(str(out))["arrays"]["fluid"]
    with h5py.File(out, "r") as f:
        assert "Header" not in f
    # h = hdx dx with dx = V^(1/3) of the unit box's 600 particles; rho = m / V.
    dx = (1 / 600) ** (1 / 3)
    assert fluid.get_number_of_particles() == 600
    assert np.allclose(fluid.h, 1.3 * dx, rtol=1e-14, atol=0)
    assert np.allclose(fluid.m / fluid.rho, 1 / 600, rtol=1e-14, atol=0)
    assert not fluid.u.any() and sorted(fluid.gid) == list(range(600))
    # sphkern reads it back as PySPH's, h as stored (support 2 h).
    back = run(str(out), "--code", "pysph", "--box", "1,1,1")
    assert abs(back["h_min"] - 1.3 * dx) < 1e-14


def test_initial_conditions_a_code_cannot_hold_are_refused(tmp_path):
    def refused_relax(code, *args, name="ic.hdf5"):
        done = subprocess.run([CLI, "relax", "wendland_c2", *args, "--steps", "2", "--output", str(tmp_path / name),
                               "--code", code], capture_output=True, text=True)
        lines = done.stderr.strip().splitlines()
        assert len(lines) == 1, done.stderr
        assert not (tmp_path / name).exists()
        return done.returncode, lines[0]

    code, line = refused_relax("phantom", "poisson", "--count", "100")
    assert code == 2 and "ic.hdf5: Phantom starts from its own full dumps, not HDF5; expected a name without .h5" in line
    code, line = refused_relax("dualsphysics", "poisson", "--count", "100", "--coefh", "1.0")
    assert code == 2 and ("dualsphysics: sphkern writes HDF5 initial conditions for swift, gadget2, gadget4 and pysph, "
                          "and a Phantom dump for phantom; DualSPHysics starts from files of its own") in line
    code, line = refused_relax("gadget4", "poisson", "--count", "800", "--box", "1,1,2")
    assert code == 3 and "GADGET's periodic box is a cube of side BoxSize; this box is 1 x 1 x 2" in line
    code, line = refused_relax("pysph", "poisson", "--count", "100", name="ic.h5")
    assert code == 2 and "PySPH's load reads a name ending in .hdf5" in line
    code, line = refused_relax("gadget2", "poisson", "--count", "100")
    assert code == 2 and "wendland_c2: gadget2 does not ship it; its kernels are cubic_bspline" in line


def test_assess_on_a_file_of_an_fcc_block_gives_the_lattice_verdict(tmp_path):
    # fcc from its cubic cell of side sqrt(2): nearest neighbours 1 apart, as sphkern's fcc.
    a, cells = np.sqrt(2), 5
    motif = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    corners = np.stack(np.meshgrid(*[np.arange(cells)] * 3, indexing="ij"), axis=-1).reshape(-1, 3)
    x = ((corners[:, None, :] + motif[None, :, :]) * a).reshape(-1, 3)
    np.savetxt(tmp_path / "fcc.csv", x, delimiter=",", header="x,y,z", comments="")
    side = f"{cells * a!r},{cells * a!r},{cells * a!r}"
    done = subprocess.run([CLI, "assess", "wendland_c2", str(tmp_path / "fcc.csv"), "--box", side, "--code", "swift",
                           "--eta", "1.2348", "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    doc = json.loads(done.stdout)
    # The lattice's own route: shells summed at the k where SWIFT's eta holds (eps --code).
    lattice = json.loads(subprocess.run([CLI, "eps", "wendland_c2", "fcc", "--code", "swift", "--eta", "1.2348", "--json"],
                                        capture_output=True, text=True, check=True).stdout)
    particles = doc["particles"]
    assert abs(particles["h_min"] - lattice["k"]) < 1e-9 and abs(particles["h_max"] - lattice["k"]) < 1e-9
    for name in ("eps_rho", "eps_gradp"):
        for stat in ("p1", "p99"):
            assert abs(particles["statistics"][name][stat] - lattice[name]) < 1e-9, (name, stat)
    assert not doc["condition_22"]["holds"]
    assert abs(doc["condition_22"]["margin"] - (0.01 - abs(lattice["eps_gradp"]))) < 1e-9
    assert doc["verdict"].startswith("swift eta 1.2348 with wendland_c2 on ")
    assert "inaccurate (98% of the interior's |eps_gradp|" in doc["verdict"]
    # The block's own lattice at the same setting: the k and the verdict of `assess` on fcc.
    fcc = next(l for l in doc["stability"]["lattices"] if l["lattice"] == "fcc")
    assert abs(fcc["k"] - lattice["k"]) < 1e-12 and fcc["verdict"] == "stable" and "stable on bcc, fcc, hcp" in doc["verdict"]
    # A periodic lattice has no surface: every particle is interior, with I + E = (1 + eps_gradP) I.
    assert doc["interior"]["particles"] == 500 and doc["surface"]["particles"] == 0
    for stat in ("min", "max"):
        assert abs(doc["interior"]["lambda_min"][stat] - (1 + lattice["eps_gradp"])) < 1e-9
    # A lattice's options on a file, and a file without a code's setting, are refused.
    for args, message in ((["--k", "1.2"], "--k needs a lattice"), ([], "a code's setting is assessed; expected --code")):
        done = subprocess.run([CLI, "assess", "wendland_c2", str(tmp_path / "fcc.csv"), "--box", side, *args],
                              capture_output=True, text=True)
        assert done.returncode == 2 and message in done.stderr, done.stderr
    done = subprocess.run([CLI, "assess", "wendland_c2", "fcc", "--k", "1.2", "--box", "1,1,1"], capture_output=True, text=True)
    assert done.returncode == 2 and "--box is for a particle file" in done.stderr


def test_pysph_properties_it_did_not_output_are_absent(tmp_path):
    # PySPH's dump writes a property outside its output arrays as an empty dataset, stored=False.
    x, h, m, rho = particles()
    with h5py.File(tmp_path / "dump.h5", "w") as f:
        arrays = f.create_group("particles/fluid/arrays")
        for key, values in (("x", x[:, 0]), ("y", x[:, 1]), ("z", x[:, 2]), ("h", h), ("m", m), ("rho", np.array([]))):
            arrays[key] = values
            arrays[key].attrs["stored"] = values.size > 0
    write_csv(tmp_path / "no-rho.csv", x, h, m, rho)
    args = ["--support-per-h", str(GAMMA), "--box", f"{L},{L},{L}", "--volume", "uniform"]
    doc = run(str(tmp_path / "dump.h5"), *args)
    assert doc["volume"] == "uniform" and doc["source"]["particles"] == N
    # The same statistics as the set without its densities (uniform volumes need none).
    close(doc, run(str(tmp_path / "no-rho.csv"), *args), 1e-13)
    # A property that is needed and was not output is refused as missing, not as a bad shape.
    assert "volumes (m / rho) need masses and densities in the file; expected densities" in refused(
        str(tmp_path / "dump.h5"), "--support-per-h", str(GAMMA), "--box", f"{L},{L},{L}", "--volume", "file")


def test_broken_hdf5_files_give_one_line(tmp_path):
    x, h, m, rho = particles()
    write_swift(tmp_path / "good.hdf5", x, h, m, rho)
    data = (tmp_path / "good.hdf5").read_bytes()
    (tmp_path / "cut.hdf5").write_bytes(data[: len(data) // 2])
    assert "cut.hdf5" in refused(str(tmp_path / "cut.hdf5"))
    with h5py.File(tmp_path / "nocoords.hdf5", "w") as f:
        f.create_group("PartType0")["Masses"] = m
    assert "/PartType0/Coordinates is missing" in refused(str(tmp_path / "nocoords.hdf5"))
    with h5py.File(tmp_path / "shape.hdf5", "w") as f:
        f.create_group("PartType0")["Coordinates"] = x[:, :2].copy()
    assert "has shape (1500, 2); expected (N, 3)" in refused(str(tmp_path / "shape.hdf5"))
    bad = x.copy()
    bad[42, 1] = np.nan
    write_swift(tmp_path / "nan.hdf5", bad, h, m, rho)
    assert "particle 42 has a non-finite coordinate" in refused(str(tmp_path / "nan.hdf5"))
    zero = m.copy()
    zero[7] = 0
    write_swift(tmp_path / "mass.hdf5", x, h, zero, rho)
    assert "the mass of particle 7 is 0" in refused(str(tmp_path / "mass.hdf5"))
    outside = x.copy()
    outside[3, 0] = 5.0
    write_swift(tmp_path / "outside.hdf5", outside, h, m, rho)
    assert "particle 3 at (5, " in refused(str(tmp_path / "outside.hdf5"))


def write_parts(base, x, h, m, rho, parts, swift=True, tamper=None):
    """One snapshot in `parts` files BASE.0.hdf5 ...: SWIFT's distributed layout (or GADGET's,
    float32 and masses from the MassTable); each part holds a contiguous run of the particles."""
    bounds = np.linspace(0, N, parts + 1).astype(int)
    for k in range(parts):
        lo, hi = bounds[k], bounds[k + 1]
        with h5py.File(f"{base}.{k}.hdf5", "w") as f:
            header = f.create_group("Header")
            header.attrs["BoxSize"] = [L, L, L] if swift else L
            header.attrs["NumFilesPerSnapshot"] = parts
            header.attrs["NumPart_Total"] = np.array([N, 0, 0, 0, 0, 0], dtype=np.uint32)
            header.attrs["NumPart_Total_HighWord"] = np.zeros(6, dtype=np.uint32)
            header.attrs["NumPart_ThisFile"] = np.array([hi - lo, 0, 0, 0, 0, 0], dtype=np.uint32)
            header.attrs["MassTable"] = [0.0] * 6 if swift else [m[0], 0, 0, 0, 0, 0]
            if swift:
                f.create_group("HydroScheme").attrs["Kernel gamma"] = GAMMA
            part = f.create_group("PartType0")
            cast = (lambda a: a) if swift else (lambda a: a.astype(np.float32))
            part["Coordinates"] = cast(x[lo:hi])
            part["SmoothingLengths" if swift else "SmoothingLength"] = cast(h[lo:hi])
            if swift:
                part["Masses"] = m[lo:hi]
            part["Densities" if swift else "Density"] = cast(rho[lo:hi])
            if tamper:
                tamper(k, f)


def test_snapshots_in_several_files_give_the_one_file_result(tmp_path):
    x, h, m, rho = particles()
    write_swift(tmp_path / "whole.hdf5", x, h, m, rho)
    whole = run(str(tmp_path / "whole.hdf5"))
    write_parts(tmp_path / "snap", x, h, m, rho, 4)
    for k in (0, 3):  # any part names the snapshot
        doc = run(str(tmp_path / f"snap.{k}.hdf5"))
        assert doc["source"]["particles"] == N
        assert doc["statistics"] == whole["statistics"]
    # GADGET's multi-part files against its one-file form.
    support = GAMMA * h
    write_gadget(tmp_path / "gadget.hdf5", x, support, m, rho)
    write_parts(tmp_path / "gadget", x, support, m, rho, 3, swift=False)
    assert run(str(tmp_path / "gadget.1.hdf5"), "--support-per-h", "1")["statistics"] == \
        run(str(tmp_path / "gadget.hdf5"), "--support-per-h", "1")["statistics"]
    # An output may not replace a part.
    done = subprocess.run([CLI, "particles", "wendland_c2", str(tmp_path / "snap.0.hdf5"), "--csv",
                           str(tmp_path / "snap.2.hdf5")], capture_output=True, text=True)
    assert done.returncode == 5 and "snap.2.hdf5" in done.stderr


def test_a_broken_snapshot_in_parts_names_the_part(tmp_path):
    x, h, m, rho = particles()
    write_parts(tmp_path / "missing", x, h, m, rho, 3)
    (tmp_path / "missing.1.hdf5").unlink()
    assert "part 1 of the snapshot's 3 files" in refused(str(tmp_path / "missing.0.hdf5"))

    def other_box(k, f):
        if k == 2:
            f["Header"].attrs["BoxSize"] = [2 * L, L, L]
    write_parts(tmp_path / "box", x, h, m, rho, 3, tamper=other_box)
    assert "box.2.hdf5: /Header BoxSize differs" in refused(str(tmp_path / "box.0.hdf5"))

    def short(k, f):
        if k == 1:
            del f["PartType0/Coordinates"], f["PartType0/SmoothingLengths"], f["PartType0/Masses"], f["PartType0/Densities"]
            f["PartType0/Coordinates"] = x[:10]
            f["PartType0/SmoothingLengths"] = h[:10]
            f["PartType0/Masses"] = m[:10]
            f["PartType0/Densities"] = rho[:10]
            f["Header"].attrs["NumPart_ThisFile"] = np.array([10, 0, 0, 0, 0, 0], dtype=np.uint32)
    write_parts(tmp_path / "short", x, h, m, rho, 3, tamper=short)
    assert "hold 1010 particles but /Header NumPart_Total declares 1500" in refused(str(tmp_path / "short.0.hdf5"))

    def this_file(k, f):
        if k == 0:
            f["Header"].attrs["NumPart_ThisFile"] = np.array([7, 0, 0, 0, 0, 0], dtype=np.uint32)
    write_parts(tmp_path / "count", x, h, m, rho, 2, tamper=this_file)
    assert "NumPart_ThisFile[0] is 7 but /PartType0/Coordinates has 750 rows" in refused(str(tmp_path / "count.1.hdf5"))
    # The base names no file: the parts are named instead.
    assert "name one of them, such as" in refused(str(tmp_path / "count.hdf5"))
    # The declared total is checked against the budget before any part's particles are read:
    # `relax` reads a set whole; `particles` measures a snapshot over the budget in slabs, which
    # need a budget too.
    write_parts(tmp_path / "good", x, h, m, rho, 3)
    done = subprocess.run([CLI, "relax", "wendland_c2", str(tmp_path / "good.1.hdf5"), "--nh", "40", "--steps", "1",
                           "--memory-limit", "0.0000001"], capture_output=True, text=True)
    assert done.returncode == 3 and "/PartType0/Coordinates declares 1500 particles in 3 parts" in done.stderr, done.stderr
    assert "leaves nothing for a slab" in refused(str(tmp_path / "good.1.hdf5"), "--memory-limit", "0.0000001")


def pysph_dump(path, arrays):
    """`arrays`: {name: {property: values}}, written by PySPH's own dump (pysph.solver.utils):
    a property it does not output is an empty dataset with stored false."""
    from pysph.base.utils import get_particle_array
    from pysph.solver.utils import dump
    dump(str(path), [get_particle_array(name=name, **props) for name, props in arrays.items()],
         {"dt": 1e-4, "t": 0.0, "count": 0})


def wendland_c2_2d(q, h):
    """PySPH's WendlandQuintic in 2D: 7 / (4 pi h^2) (1 - q/2)^4 (2q + 1), support 2h; and dW/dr."""
    t = np.clip(1 - q / 2, 0, None)
    sigma = 7 / (4 * np.pi * h**2)
    return sigma * t**4 * (2 * q + 1), sigma / h * (-5 * q) * t**3


def brute_force_sums(fluid, others):
    """For each fluid particle i: sum_j V_j W(r_ij, h_i) - 1 (itself included), the neighbour
    count, and h_i sum_j V_j grad_i W_ij, over the fluid and `others` particles."""
    xs = np.concatenate([fluid["x"]] + [o["x"] for o in others])
    ys = np.concatenate([fluid["y"]] + [o["y"] for o in others])
    vol = np.concatenate([fluid["m"] / fluid["rho"]] + [o["m"] / o["rho"] for o in others])
    e0, count, e1 = [], [], []
    for i in range(len(fluid["x"])):
        dx, dy = fluid["x"][i] - xs, fluid["y"][i] - ys
        r = np.hypot(dx, dy)
        h = fluid["h"][i]
        w, dw = wendland_c2_2d(r / h, h)
        e0.append(np.sum(vol * w) - 1)
        count.append(int(np.sum((r > 0) & (r < 2 * h))))
        with np.errstate(invalid="ignore", divide="ignore"):
            g = np.where(r > 0, dw / r, 0.0)
        e1.append([h * np.sum(vol * g * dx), h * np.sum(vol * g * dy)])
    return np.array(e0), np.array(count), np.array(e1)


def wall_and_fluid():
    """The tank of the several-array tests: 20 x 20 fluid particles, h varying by 5%."""
    return fluid_tanks.wall_and_fluid(34, 20, 0.1, 0.05)


def per_particle(path, *args):
    out = path.parent / (path.stem + "-out.csv")
    done = subprocess.run([CLI, "particles", "wendland_c2", str(path), "--support-per-h", "2", "--csv", str(out),
                           "--json", *args], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    rows = np.genfromtxt(out, delimiter=",", names=True)
    return json.loads(done.stdout), rows


def test_pysph_several_arrays_measure_the_first_with_all_as_neighbours(tmp_path):
    fluid, solid = wall_and_fluid()
    pysph_dump(tmp_path / "tank.hdf5", {"fluid": fluid, "solid": solid})
    doc, rows = per_particle(tmp_path / "tank.hdf5", "--array", "fluid,solid")
    n = len(fluid["x"])
    # Measured on the fluid only, in its order; the wall's particles are neighbours.
    assert len(rows) == n and doc["source"]["particles"] == n and doc["source"]["neighbours_only"] == len(solid["x"])
    assert np.array_equal(rows["x"], fluid["x"]) and np.array_equal(rows["h"], fluid["h"])
    e0, count, e1 = brute_force_sums(fluid, [solid])
    assert np.max(np.abs(rows["e0"] - e0)) < 1e-12
    assert np.array_equal(rows["neighbours"], count)
    assert np.max(np.abs(rows["e1_x"] - e1[:, 0])) < 1e-12 and np.max(np.abs(rows["e1_y"] - e1[:, 1])) < 1e-12
    # The statistics are the fluid's: the mean of e0 over its particles.
    assert abs(doc["statistics"]["e0"]["mean"] - np.mean(e0)) < 1e-12
    # The fluid alone: its own sums, which the wall changes near it.
    alone_doc, alone = per_particle(tmp_path / "tank.hdf5", "--array", "fluid")
    e0_alone, count_alone, _ = brute_force_sums(fluid, [])
    assert alone_doc["source"].get("neighbours_only") is None
    assert np.max(np.abs(alone["e0"] - e0_alone)) < 1e-12 and np.array_equal(alone["neighbours"], count_alone)
    assert np.max(np.abs(alone["e0"] - rows["e0"])) > 0.1


def test_pysph_array_lists_are_checked(tmp_path):
    fluid, solid = wall_and_fluid()
    pysph_dump(tmp_path / "tank.hdf5", {"fluid": fluid, "solid": solid})
    line = refused(str(tmp_path / "tank.hdf5"), "--array", "fluid,wall", "--support-per-h", "2")
    assert 'tank.hdf5: no particle array "wall"; the file has fluid, solid' in line
    pysph_dump(tmp_path / "no-h.hdf5", {"fluid": fluid, "solid": solid})
    with h5py.File(tmp_path / "no-h.hdf5", "a") as f:
        del f["particles/solid/arrays/h"]
    assert 'particle array "solid" has no h, which "fluid" has' in refused(
        str(tmp_path / "no-h.hdf5"), "--array", "fluid,solid", "--support-per-h", "2")


def test_dualsphysics_csv_as_its_writer_writes_it(tmp_path):
    # JOutputCsv::SaveCsv: free-text head lines, then each array's name and unit, every field
    # (and every value) followed by the separator; Rho and Mass as DualSPHysics 5.2 names them.
    x, h, m, rho = particles()
    args = ["--h-over-l", "1.2", "--box", f"{L},{L},{L}"]
    with open(tmp_path / "plain.csv", "w") as f:
        f.write("x,y,z,m,rho\n")
        for p, mm, r in zip(x, m, rho):
            f.write(f"{p[0]!r},{p[1]!r},{p[2]!r},{mm!r},{r!r}\n")
    with open(tmp_path / "dsph.csv", "w") as f:
        f.write("Particles of a DualSPHysics case\nPart 0042 at 1.25 s\n")
        f.write("Pos.x [m];Pos.y [m];Pos.z [m];Idp;Vel.x [m/s];Vel.y [m/s];Vel.z [m/s];Rho [kg/m^3];Mass [kg];Type;\n")
        for i, (p, mm, r) in enumerate(zip(x, m, rho)):
            f.write(f"{p[0]!r};{p[1]!r};{p[2]!r};{i};0;0;0;{r!r};{mm!r};3;\n")
    doc = run(str(tmp_path / "dsph.csv"), *args)
    assert doc["volume"] == "file" and doc["source"]["particles"] == N
    assert doc["statistics"] == run(str(tmp_path / "plain.csv"), *args)["statistics"]


def write_splishsplash_vtk(path, x, rho, title="SPlisHSPlasH particle data"):
    """As SPlisHSPlasH's ParticleExporter_VTK writes it: big-endian float points, each particle
    a cell, ids as SCALARS, the exported attributes (velocity, density) as FIELD arrays; no h."""
    n = len(x)
    with open(path, "wb") as f:
        f.write(f"# vtk DataFile Version 4.1\n{title}\nBINARY\nDATASET UNSTRUCTURED_GRID\n".encode())
        f.write(f"POINTS {n} float\n".encode() + x.astype(">f4").tobytes() + b"\n")
        cells = np.column_stack([np.ones(n), np.arange(n)]).astype(">u4")
        f.write(f"CELLS {n} {2 * n}\n".encode() + cells.tobytes() + b"\n")
        f.write(f"CELL_TYPES {n}\n".encode() + np.ones(n).astype(">i4").tobytes() + b"\n")
        f.write(f"POINT_DATA {n}\n".encode())
        f.write(b"SCALARS id unsigned_int 1\nLOOKUP_TABLE id_table\n" + np.arange(n).astype(">u4").tobytes() + b"\n")
        f.write(b"FIELD FieldData 2\n")
        f.write(f"velocity 3 {n} float\n".encode() + np.zeros((n, 3)).astype(">f4").tobytes() + b"\n")
        f.write(f"density 1 {n} float\n".encode() + rho.astype(">f4").tobytes() + b"\n")


def test_a_splishsplash_vtk_file_has_the_support_of_4_particle_radii(tmp_path):
    x, h, m, rho = particles()
    radius = 0.045
    write_splishsplash_vtk(tmp_path / "ParticleData_Fluid_42.vtk", x, rho)
    # The same float positions with the support 4 r as the stored h.
    x32 = x.astype(np.float32).astype(np.float64)
    with open(tmp_path / "same.csv", "w") as f:
        f.write("x,y,z,h\n")
        for p in x32:
            f.write(f"{p[0]!r},{p[1]!r},{p[2]!r},{4 * radius!r}\n")
    box = ["--box", f"{L},{L},{L}"]
    doc = run(str(tmp_path / "ParticleData_Fluid_42.vtk"), "--particle-radius", str(radius), *box)
    close(doc, run(str(tmp_path / "same.csv"), "--support-per-h", "1", *box), 1e-13)
    # The file holds no radius: without one (or --h-over-l, --nh) it is asked for.
    line = refused(str(tmp_path / "ParticleData_Fluid_42.vtk"), *box)
    assert "ParticleData_Fluid_42.vtk: the file holds no h and no particle radius (its support is 4 radii); " \
           "give --particle-radius R" in line, line
    assert run(str(tmp_path / "ParticleData_Fluid_42.vtk"), "--h-over-l", "1.2", *box)["source"]["particles"] == N
    # Another title: not SPlisHSPlasH's, and no radius gives its h.
    write_splishsplash_vtk(tmp_path / "other.vtk", x, rho, title="particles")
    done = subprocess.run([CLI, "particles", "wendland_c2", str(tmp_path / "other.vtk"), "--particle-radius", "0.045",
                           *box], capture_output=True, text=True)
    assert done.returncode == 2 and "--particle-radius: " in done.stderr and "other.vtk" in done.stderr, done.stderr
