"""A run's snapshots as one series: `sphkern particles KERNEL FILE FILE ...` (or a folder)
measures every snapshot with the same settings, orders them by the time each header gives
(SWIFT's /Header Time, GADGET-2's binary header, Phantom's time, PySPH's solver_data t; file
order where a file has none), and each entry holds exactly the numbers a run on that file
alone gives. Bad series: one line naming the files, exit 3 (or --keep-going); outputs never
replace an input. Run by ctest with SPHKERN_CLI set."""
import json
import os
import subprocess

import numpy as np
import pytest

import test_gadget_binary as gadget
import test_phantom_dump as phantom

h5py = pytest.importorskip("h5py")

CLI = os.environ["SPHKERN_CLI"]
N, L = 512, 1.0  # a full 8^3 lattice in the unit box


def positions(step):
    """A lattice that disorders as the run goes on."""
    rng = np.random.default_rng(7)
    side = 8
    grid = (np.stack(np.meshgrid(*[np.arange(side)] * 3, indexing="ij"), -1).reshape(-1, 3) + 0.5) / side
    return np.mod(grid + 0.1 * step * rng.normal(size=grid.shape) / side, L)


def write_swift(path, step, time, dimension=3):
    x = positions(step)
    with h5py.File(path, "w") as f:
        header = f.create_group("Header")
        header.attrs["BoxSize"] = [L, L, L]
        header.attrs["Dimension"] = dimension
        header.attrs["NumPart_Total"] = [N, 0, 0, 0, 0, 0]
        header.attrs["MassTable"] = [0.0] * 6
        if time is not None:
            header.attrs["Time"] = [time]  # SWIFT writes a one-element array
        f.create_group("HydroScheme").attrs["Kernel gamma"] = 1.936492
        part = f.create_group("PartType0")
        part["Coordinates"] = x if dimension == 3 else np.column_stack([x[:, 0], x[:, 1], np.zeros(N)])
        part["Masses"] = np.full(N, L**3 / N)
    return str(path)


def write_csv(path, step):
    x = positions(step)
    with open(path, "w") as f:
        f.write("x,y,z\n")
        for p in x:
            f.write(f"{p[0]!r},{p[1]!r},{p[2]!r}\n")
    return str(path)


def run(*args, code=0):
    done = subprocess.run([CLI, "particles", "cubic_bspline", *args], capture_output=True, text=True)
    assert done.returncode == code, done.stderr
    return done


def answer(*args):
    return json.loads(run(*args, "--json").stdout)


def computed(doc):
    """What a run computes, without its provenance, inputs and timings."""
    keep = {k: v for k, v in doc.items() if k not in ("provenance", "inputs", "phases", "seconds", "cpu_seconds", "file", "time")}
    keep["source"] = {k: v for k, v in doc["source"].items() if k != "name"}
    return keep


def refused(*args, code=3):
    done = run(*args, code=code)
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("sphkern: error: "), done.stderr
    assert done.stdout == ""
    return lines[0]


def test_entries_are_ordered_by_time_and_equal_single_runs(tmp_path):
    files = [write_swift(tmp_path / f"snap_{k:03d}.hdf5", step, t) for k, (step, t) in enumerate([(2, 0.2), (0, 0.0), (1, 0.1)])]
    doc = answer(*files, "--h-over-l", "1.3")
    assert doc["ordered_by"] == "time" and doc["snapshots"] == 3
    assert [e["file"] for e in doc["series"]] == [files[1], files[2], files[0]]
    assert [e["time"] for e in doc["series"]] == [0.0, 0.1, 0.2]
    for entry in doc["series"]:
        alone = answer(entry["file"], "--h-over-l", "1.3")
        assert computed(entry) == computed(alone)
    # The lattice disorders: the median e0 grows with time.
    medians = [e["statistics"]["e0"]["p50"] for e in doc["series"]]
    assert medians[0] < medians[1] < medians[2]


def test_a_folder_is_its_snapshots(tmp_path):
    run_folder = tmp_path / "run"
    run_folder.mkdir()
    for k, t in enumerate([0.5, 0.25]):
        write_swift(run_folder / f"snap_{k:03d}.hdf5", k, t)
    (run_folder / "notes.txt").write_text("not a snapshot\n")
    doc = answer(str(run_folder), "--h-over-l", "1.3")
    assert [os.path.basename(e["file"]) for e in doc["series"]] == ["snap_001.hdf5", "snap_000.hdf5"]
    text = run(str(run_folder), "--h-over-l", "1.3").stdout
    assert "series of 2 snapshots, ordered by the time in their headers" in text
    assert text.index("snap_001.hdf5") < text.index("snap_000.hdf5")


def test_files_without_times_keep_their_order(tmp_path):
    files = [write_csv(tmp_path / f"{name}.csv", step) for name, step in (("b", 1), ("a", 0))]
    doc = answer(*files, "--box", "1,1,1", "--h-over-l", "1.3")
    assert doc["ordered_by"] == "file order"
    assert [e["file"] for e in doc["series"]] == files and all(e["time"] is None for e in doc["series"])


def test_gadget_binary_snapshots_in_parts_are_one_snapshot_each(tmp_path):
    p = gadget.particles()
    for k, t in enumerate([3.0, 1.0]):
        gadget.write_snapshot(tmp_path / f"snap_{k:03d}", p, files=2, time=t)
    doc = answer(str(tmp_path), "--code", "gadget2", "--nngb", "48")
    assert [os.path.basename(e["file"]) for e in doc["series"]] == ["snap_001.0", "snap_000.0"]
    assert [e["time"] for e in doc["series"]] == [1.0, 3.0]
    assert computed(doc["series"][0]) == computed(answer(str(tmp_path / "snap_001.0"), "--code", "gadget2", "--nngb", "48"))


def test_phantom_dumps_are_ordered_by_their_time(tmp_path):
    p = phantom.particles()
    late = phantom.write_dump(tmp_path / "disc_00001", p, time=12.5)
    early = phantom.write_dump(tmp_path / "disc_00002", p, time=2.5)
    doc = answer(late, early, "--code", "phantom", "--hfact", "1.2")
    assert [e["time"] for e in doc["series"]] == [2.5, 12.5]


def test_pysph_solver_time_orders_the_series(tmp_path):
    files = []
    for k, t in enumerate([0.3, 0.1]):
        path = tmp_path / f"drop_{k}.hdf5"
        with h5py.File(path, "w") as f:
            arrays = f.create_group("particles/fluid/arrays")
            x = positions(k)
            for axis, name in enumerate("xyz"):
                arrays[name] = x[:, axis]
            arrays["h"] = np.full(N, 1.3 * (L**3 / N) ** (1 / 3))
            f.create_group("solver_data").attrs["t"] = t
        files.append(str(path))
    doc = answer(*files, "--box", "1,1,1", "--code", "pysph")
    assert [e["time"] for e in doc["series"]] == [0.1, 0.3]


def test_per_snapshot_tables_are_named_after_each_snapshot(tmp_path):
    files = [write_swift(tmp_path / f"snap_{k:03d}.hdf5", k, 0.1 * k) for k in range(2)]
    out = tmp_path / "out"
    out.mkdir()
    run(*files, "--h-over-l", "1.3", "--csv", str(out / "errors.csv"))
    for k in range(2):
        run(files[k], "--h-over-l", "1.3", "--csv", str(tmp_path / "alone.csv"))
        assert (out / f"errors_snap_{k:03d}.csv").read_text() == (tmp_path / "alone.csv").read_text()


def test_snapshots_of_two_dimensions_are_refused_naming_both(tmp_path):
    a = write_swift(tmp_path / "a.hdf5", 0, 0.0)
    b = write_swift(tmp_path / "b.hdf5", 0, 0.1, dimension=2)
    line = refused(a, b, "--h-over-l", "1.3")
    assert "b.hdf5 is 2D but" in line and "a.hdf5 is 3D" in line


def test_snapshots_of_two_codes_are_refused_naming_both(tmp_path):
    a = write_swift(tmp_path / "a.hdf5", 0, 0.0)
    b = write_csv(tmp_path / "b.csv", 0)
    line = refused(a, b, "--h-over-l", "1.3", "--box", "1,1,1")
    assert "b.csv is a CSV file but" in line and "a.hdf5 is a SWIFT HDF5 file" in line


def test_a_broken_snapshot_stops_the_series_or_is_skipped(tmp_path):
    good = [write_swift(tmp_path / f"snap_{k:03d}.hdf5", k, 0.1 * k) for k in range(2)]
    broken = tmp_path / "snap_002.hdf5"
    broken.write_bytes(b"\x89HDF\r\n\x1a\n" + b"\0" * 64)
    line = refused(*good, str(broken), "--h-over-l", "1.3")
    assert "snap_002.hdf5" in line
    done = run(*good, str(broken), "--h-over-l", "1.3", "--keep-going", "--json")
    doc = json.loads(done.stdout)
    assert doc["snapshots"] == 2 and [f["file"] for f in doc["failed"]] == [str(broken)]
    assert "snap_002.hdf5" in done.stderr


def test_no_output_replaces_an_input_of_the_series(tmp_path):
    # c.csv's table would be errors_c.csv, the series' other input.
    inputs = [write_csv(tmp_path / "c.csv", 0), write_csv(tmp_path / "errors_c.csv", 1)]
    before = open(inputs[1]).read()
    line = refused(*inputs, "--box", "1,1,1", "--csv", str(tmp_path / "errors.csv"), "--h-over-l", "1.3", code=5)
    assert "errors_c.csv" in line and open(inputs[1]).read() == before


def test_a_series_takes_one_h_per_snapshot(tmp_path):
    files = [write_swift(tmp_path / f"snap_{k:03d}.hdf5", k, 0.1 * k) for k in range(2)]
    refused(*files, "--h-over-l-range", "1.2", "1.4", code=2)


def test_the_figure_is_drawn_complete_and_leaves_nothing_beside_it(tmp_path):
    files = [write_swift(tmp_path / f"snap_{k:03d}.hdf5", k, 0.5 * k) for k in range(3)]
    out = tmp_path / "figures"
    out.mkdir()
    run(*files, "--h-over-l", "1.3", "--plot", str(out / "errors.svg"))
    assert os.listdir(out) == ["errors.svg"]
    svg = (out / "errors.svg").read_text()
    assert svg.lstrip().startswith("<?xml") and svg.rstrip().endswith("</svg>")
    for label in ("e0", "eps_rho", "eps_gradp", "median"):
        assert label in svg
    refused(files[0], "--h-over-l", "1.3", "--plot", str(out / "one.svg"), code=2)
    refused(*files, "--h-over-l", "1.3", "--plot", str(out / "errors.gif"), code=2)


def test_a_series_is_a_paraview_collection(tmp_path):
    import xml.etree.ElementTree as ET
    from vtk import vtkXMLUnstructuredGridReader
    from vtk.util.numpy_support import vtk_to_numpy

    files = [write_swift(tmp_path / f"snap_{k:03d}.hdf5", step, t) for k, (step, t) in enumerate([(1, 0.7), (0, 0.2)])]
    out = tmp_path / "view"
    out.mkdir()
    run(*files, "--h-over-l", "1.3", "--vtk", str(out / "run.pvd"))
    assert sorted(os.listdir(out)) == ["run.pvd", "run_snap_000.vtu", "run_snap_001.vtu"]
    sets = ET.parse(out / "run.pvd").getroot().find("Collection").findall("DataSet")
    assert [(float(d.get("timestep")), d.get("file")) for d in sets] == [(0.2, "run_snap_001.vtu"), (0.7, "run_snap_000.vtu")]

    def arrays(path):
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(str(path))
        reader.Update()
        data = reader.GetOutput().GetPointData()
        return {data.GetArrayName(a): vtk_to_numpy(data.GetArray(a)) for a in range(data.GetNumberOfArrays())}

    for k, file in enumerate(files):
        run(file, "--h-over-l", "1.3", "--vtk", str(tmp_path / "alone.vtu"))
        series, alone = arrays(out / f"run_snap_{k:03d}.vtu"), arrays(tmp_path / "alone.vtu")
        assert series.keys() == alone.keys() and "eps_rho" in series
        for name in series:
            assert np.array_equal(series[name], alone[name]), name
    refused(*files, "--h-over-l", "1.3", "--vtk", str(out / "run.vtu"), code=2)
