"""ParaView's XML formats: `particles --vtk F.vtu` and `block --vtk F.vtu` read back with VTK's
own reader equal the same run's --csv bit for bit (points, every array, the names), .vtk stays
legacy and any other extension is refused; `relax --history F.pvd` writes a collection of one
.vtu per step (VTK 9.1 has no .pvd reader: its XML is parsed and each file read).
Run by ctest with SPHKERN_CLI set."""
import csv
import json
import os
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

vtk_xml = pytest.importorskip("vtkmodules.vtkIOXML")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

CLI = os.environ["SPHKERN_CLI"]


def run(*args, code=0):
    done = subprocess.run([CLI, *args], capture_output=True, text=True)
    assert done.returncode == code, done.stderr
    return done


def refused(*args, code):
    lines = run(*args, code=code).stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("sphkern: error: "), lines
    return lines[0]


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return {name: np.array([float(r[name]) for r in rows]) for name in rows[0]}


def read_vtu(path):
    """The points (n x 3) and the point arrays by name, in the file's order."""
    reader = vtk_xml.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    arrays = {data.GetArrayName(k): vtk_to_numpy(data.GetArray(k)) for k in range(data.GetNumberOfArrays())}
    assert grid.GetNumberOfCells() == grid.GetNumberOfPoints()
    assert all(grid.GetCellType(i) == 1 for i in range(grid.GetNumberOfCells()))  # VTK_VERTEX
    return vtk_to_numpy(grid.GetPoints().GetData()), arrays


def same(a, b):
    """Bit for bit: -0.0 and 0.0 differ, NaN equals NaN."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def check_particles(table, points, arrays, dim):
    axes = "xyz"[:dim]
    assert list(arrays) == ["id", "h", "volume", "neighbours", "e0", "eps_rho", "eps_gradp", "e1", "m1"]
    assert points.shape == (len(table["id"]), 3)
    for k, axis in enumerate(axes):
        assert same(points[:, k], table[axis]), axis
    if dim == 2:
        assert not points[:, 2].any()
    for name in ["id", "h", "volume", "neighbours", "e0", "eps_rho", "eps_gradp"]:
        assert arrays[name].dtype == np.float64 and same(arrays[name], table[name]), name
    for name in ["e1", "m1"]:
        assert arrays[name].shape == (len(table["id"]), 3)
        for k, axis in enumerate(axes):
            assert same(arrays[name][:, k], table[f"{name}_{axis}"]), f"{name}_{axis}"
        if dim == 2:
            assert not arrays[name][:, 2].any()


@pytest.mark.parametrize("source", [["poisson", "--count", "700", "--seed", "3"],
                                    ["triangular", "--size", "12,10", "--sigma", "0.05", "--seed", "5", "--k", "1.3"]],
                         ids=["poisson-3d", "triangular-2d"])
def test_particles_vtu_equals_csv(tmp_path, source):
    run("particles", "wendland_c2", *source, "--csv", str(tmp_path / "p.csv"), "--vtk", str(tmp_path / "p.vtu"))
    table = read_csv(tmp_path / "p.csv")
    points, arrays = read_vtu(tmp_path / "p.vtu")
    check_particles(table, points, arrays, 2 if "triangular" in source else 3)
    head = (tmp_path / "p.vtu").read_bytes()[:300].decode("ascii", "replace")
    assert 'type="UnstructuredGrid"' in head and 'byte_order="LittleEndian"' in head and 'header_type="UInt64"' in head


def test_vtk_stays_legacy_and_other_names_are_refused(tmp_path):
    run("particles", "wendland_c2", "poisson", "--count", "200", "--vtk", str(tmp_path / "p.vtk"))
    assert (tmp_path / "p.vtk").read_text().startswith("# vtk DataFile Version 3.0\n")
    for command in (["particles", "wendland_c2", "poisson", "--count", "200"],
                    ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "4,4,4"]):
        line = refused(*command, "--vtk", str(tmp_path / "p.txt"), code=2)
        assert "--vtk" in line and "p.txt" in line and ".vtk" in line and ".vtu" in line, line
        assert not (tmp_path / "p.txt").exists()


def test_block_vtu_equals_csv(tmp_path):
    run("block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "5,4,3", "--vtk", str(tmp_path / "b.vtu"),
        "--csv", str(tmp_path / "b.csv"))
    table = read_csv(tmp_path / "b.csv")
    points, arrays = read_vtu(tmp_path / "b.vtu")
    assert list(arrays) == ["layer", "eps_rho", "eps_gradp"]
    for k, axis in enumerate("xyz"):
        assert same(points[:, k], table[axis]), axis
    for name in arrays:
        assert same(arrays[name], table[name]), name


def read_pvd(path):
    """(timestep, file) per DataSet, the file beside the .pvd."""
    root = ET.parse(path).getroot()
    assert root.get("type") == "Collection"
    return [(float(d.get("timestep")), path.parent / d.get("file")) for d in root.iter("DataSet")]


@pytest.mark.parametrize("method", ["pressure", "shift"])
def test_relax_history_pvd(tmp_path, method):
    done = run("relax", "wendland_c2", "poisson", "--count", "300", "--dim", "2", "--nh", "20", "--steps", "6",
               "--method", method, "--history", str(tmp_path / "run.pvd"), "--output", str(tmp_path / "glass.csv"),
               "--json")
    history = json.loads(done.stdout)["history"]
    series = read_pvd(tmp_path / "run.pvd")
    assert [f.name for _, f in series] == [f"run_{k}.vtu" for k in range(7)]
    assert [t for t, _ in series] == [s["time"] if method == "pressure" else s["step"] for s in history]
    names = ["id", "e0", "e1", "displacement"] + (["velocity"] if method == "pressure" else [])
    for (_, file), step in zip(series, history):
        points, arrays = read_vtu(file)
        assert list(arrays) == names and points.shape == (300, 3) and not points[:, 2].any()
        # The history's RMS errors are these arrays'.
        assert np.sqrt(np.mean(arrays["e0"] ** 2)) == pytest.approx(step["rms_e0"], rel=1e-12, abs=1e-300)
        assert np.sqrt(np.mean(np.sum(arrays["e1"] ** 2, axis=1))) == pytest.approx(step["rms_e1"], rel=1e-12)
    # The last step's points are the set --output wrote.
    relaxed = read_csv(tmp_path / "glass.csv")
    points, _ = read_vtu(series[-1][1])
    assert same(points[:, 0], relaxed["x"]) and same(points[:, 1], relaxed["y"])


def test_relax_history_pvd_on_divergence_and_in_the_way(tmp_path):
    line = refused("relax", "wendland_c2", "poisson", "--count", "500", "--gamma", "1000", "--steps", "50",
                   "--history", str(tmp_path / "d.pvd"), code=3)
    assert "d.pvd" in line
    series = read_pvd(tmp_path / "d.pvd")
    assert series and all(f.exists() for _, f in series)
    assert not (tmp_path / f"d_{len(series):02d}.vtu").exists()
    # A folder where a step's file would go: refused before the run, nothing written.
    (tmp_path / "w_3.vtu").mkdir()
    line = refused("relax", "wendland_c2", "poisson", "--count", "200", "--steps", "5", "--history",
                   str(tmp_path / "w.pvd"), code=5)
    assert "--history" in line and "w_3.vtu" in line and "folder" in line, line
    assert not (tmp_path / "w.pvd").exists() and not (tmp_path / "w_0.vtu").exists()
