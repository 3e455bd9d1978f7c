"""check, spectrum, block, pairing, relax, run and studies against the command line: the same
request gives the same document as `sphkern COMMAND --json` (the same numbers, to 1e-13; the
timings apart), the same files, and the arrays the document lists; with independent values
where there are any. Run by ctest with PYTHONPATH=<build>/python and SPHKERN_CLI set."""
import csv
import json
import os
import subprocess

import numpy as np
import pytest

import sphkern

CLI = os.environ["SPHKERN_CLI"]
BROKEN = os.environ["SPHKERN_BROKEN_PLUGINS"]


def cli_json(*args):
    """The command's document without its provenance and inputs (the module's have neither)."""
    done = subprocess.run([CLI, *args, "--json"], capture_output=True, text=True)
    assert done.returncode in (0, 1), done.stderr
    document = json.loads(done.stdout)
    for item in document if isinstance(document, list) else [document]:
        assert item.pop("provenance")["sphkern_version"] == sphkern.__version__
        item.pop("inputs", None)
    return document


def close(a, b, skip=()):
    """Equal numbers to 1e-13 (relative to 1 + |b|) inside any JSON-like structure, keys in skip apart."""
    if isinstance(b, dict):
        assert a.keys() == b.keys()
        for key in b:
            if key not in skip:
                close(a[key], b[key], skip)
    elif isinstance(b, list):
        assert len(a) == len(b)
        for x, y in zip(a, b):
            close(x, y, skip)
    elif isinstance(b, float) or isinstance(a, float):
        assert abs(a - b) <= 1e-13 * (1 + abs(b)), (a, b)
    else:
        assert a == b


def test_studies_lists_what_the_command_lists():
    assert sphkern.studies() == cli_json("studies")
    assert {"potapov2021", "design"} <= {s["name"] for s in sphkern.studies()}


@pytest.mark.parametrize("kernel, dim", [("cubic_bspline", 3), ("wendland_c2", 2), ("super_gaussian", 1)])
def test_spectrum_is_the_command_s_with_its_curve_as_an_array(kernel, dim):
    mine = sphkern.spectrum(kernel, dim, max=30.0, points=300)
    theirs = cli_json("spectrum", kernel, "--dim", str(dim), "--max", "30", "--points", "300")
    curve = mine.pop("curve")
    assert isinstance(curve, np.ndarray) and curve.shape == (301, 2)
    np.testing.assert_allclose(curve, np.asarray(theirs.pop("curve")), rtol=1e-13, atol=1e-15)
    close(mine, theirs)
    # A normalised kernel's transform is 1 at kappa h = 0 (the super-Gaussian is cut at its support).
    assert curve[0, 0] == 0 and abs(curve[0, 1] - 1) < (1e-3 if kernel == "super_gaussian" else 1e-6)


def test_spectrum_of_the_cubic_spline_in_1d_is_its_closed_form():
    """W^(x) = (sin(x/2) / (x/2))^4 in 1D for the M4 spline of support 2 h: four boxes of width h convolved."""
    curve = sphkern.spectrum("cubic_bspline", 1, max=10.0, points=100)["curve"]
    x = curve[1:, 0]
    np.testing.assert_allclose(curve[1:, 1], (np.sin(x / 2) / (x / 2)) ** 4, atol=1e-8)


BLOCK_TIMINGS = ("seconds", "pair_interactions_per_second", "threads", "fused_passes")


def test_block_is_the_command_s_with_per_particle_arrays(tmp_path):
    mine = sphkern.block("wendland_c4", "fcc", 1.3, [7, 7, 5], periodic=True, form="difference", threads=1)
    csv_file = tmp_path / "block.csv"
    theirs = cli_json("block", "wendland_c4", "fcc", "--k", "1.3", "--size", "7,7,5", "--periodic", "--form",
                      "difference", "--threads", "1", "--csv", str(csv_file))
    arrays = {key: mine.pop(key) for key in ("positions", "layer", "eps_rho", "eps_gradp")}
    close(mine, theirs, skip=BLOCK_TIMINGS)
    n = mine["particles"]
    assert arrays["positions"].shape == (n, 3) and arrays["layer"].shape == (n,)
    with open(csv_file) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == n
    columns = rows[0].keys()
    for name in ("eps_rho", "eps_gradp"):
        key = next(c for c in columns if c.lower().replace("gradP", "gradp").startswith(name))
        np.testing.assert_allclose(arrays[name], [float(r[key]) for r in rows], rtol=1e-9, atol=1e-14)
    # Each layer's extremes are those of its particles.
    for layer in mine["layers"]:
        chosen = arrays["eps_rho"][arrays["layer"] == layer["layer"]]
        assert chosen.size == layer["particles"]
        assert abs(chosen.min() - layer["eps_rho_min"]) < 1e-14 and abs(chosen.max() - layer["eps_rho_max"]) < 1e-14


def test_block_deep_inside_is_the_lattice_s_bulk():
    """Far below the free top, a particle's density error is eps's on the infinite lattice."""
    k = 1.2
    b = sphkern.block("cubic_bspline", "sc", k, [6, 6, 12], periodic=True)
    deepest = b["eps_rho"][b["layer"] == b["layer"].max() // 2]
    bulk = sphkern.eps("cubic_bspline", "sc", k)["eps_rho"]
    np.testing.assert_allclose(deepest, bulk, atol=1e-12)


def test_block_writes_the_command_s_files(tmp_path):
    sphkern.block("cubic_bspline", "sc", 1.2, [3, 3, 3], vtk=str(tmp_path / "a.vtk"), csv=str(tmp_path / "a.csv"))
    subprocess.run([CLI, "block", "cubic_bspline", "sc", "--k", "1.2", "--size", "3,3,3", "--vtk",
                    str(tmp_path / "b.vtk"), "--csv", str(tmp_path / "b.csv")], check=True, capture_output=True)
    assert (tmp_path / "a.vtk").read_bytes() == (tmp_path / "b.vtk").read_bytes()
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes()


def test_pairing_is_the_command_s():
    mine = sphkern.pairing("cubic_bspline", "sc", kmin=0.9, kmax=1.3, samples=3, duration=3.0, threads=1)
    theirs = cli_json("pairing", "cubic_bspline", "sc", "--kmin", "0.9", "--kmax", "1.3", "--samples", "3",
                      "--duration", "3", "--threads", "1")
    close(mine, theirs)
    assert [p["k"] for p in mine["points"]] == pytest.approx([0.9, 1.1, 1.3])


def test_pairing_with_a_code_s_setting_is_the_command_s():
    mine = sphkern.pairing("wendland_c2", "fcc", code="swift", value=1.2348, duration=2.0, threads=1)
    theirs = cli_json("pairing", "wendland_c2", "fcc", "--code", "swift", "--eta", "1.2348", "--duration", "2",
                      "--threads", "1")
    close(mine, theirs)
    assert mine["code"]["name"] == "swift"


def without_timings(document):
    for item in document:
        item.pop("seconds", None)
    return document


def test_check_is_the_command_s():
    mine = sphkern.check(["wendland_c2", "wendland_c4"])
    theirs = cli_json("check", "wendland_c2", "wendland_c4")
    close(mine, theirs)
    assert [r["verdict"] for r in mine] == ["ok", "ok"]


def test_a_failed_check_raises_with_the_documents():
    plugin = os.path.join(BROKEN, "unnormalised.so")
    with pytest.raises(sphkern.CheckFailed, match="failed") as caught:
        sphkern.check(plugin=plugin)
    assert caught.value.exit_code == 1
    assert [r["verdict"] for r in caught.value.results] == ["fail"]
    close(caught.value.results, cli_json("check", "--plugin", plugin))


RELAX_TIMINGS = ("phases", "seconds", "cpu_seconds")


def test_relax_is_the_command_s(tmp_path):
    mine = sphkern.relax("cubic_bspline", "poisson", count=300, dim=2, steps=15, threads=1,
                         output=str(tmp_path / "a.csv"), history=str(tmp_path / "a-history.csv"))
    theirs = cli_json("relax", "cubic_bspline", "poisson", "--count", "300", "--dim", "2", "--steps", "15",
                      "--threads", "1", "--output", str(tmp_path / "b.csv"), "--history", str(tmp_path / "b-history.csv"))
    positions = mine.pop("positions")
    mine["output"].pop("file"), theirs["output"].pop("file")
    close(mine, theirs, skip=RELAX_TIMINGS)
    assert positions.shape == (300, 2)
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes()
    assert (tmp_path / "a-history.csv").read_bytes() == (tmp_path / "b-history.csv").read_bytes()
    with open(tmp_path / "a.csv") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    np.testing.assert_allclose(positions[:, 0], [float(r["x"]) for r in rows], rtol=1e-12)


def test_relax_s_series_history_is_the_command_s(tmp_path):
    """Both front ends run one relaxation: a .pvd history is a ParaView series from Python too."""
    args = dict(count=200, dim=2, steps=3, threads=1)
    (tmp_path / "a").mkdir(), (tmp_path / "b").mkdir()
    sphkern.relax("cubic_bspline", "poisson", history=str(tmp_path / "a" / "run.pvd"), **args)
    cli_json("relax", "cubic_bspline", "poisson", "--count", "200", "--dim", "2", "--steps", "3", "--threads", "1",
             "--history", str(tmp_path / "b" / "run.pvd"))
    names = sorted(os.listdir(tmp_path / "a"))
    assert names == ["run.pvd", "run_0.vtu", "run_1.vtu", "run_2.vtu", "run_3.vtu"]
    assert names == sorted(os.listdir(tmp_path / "b"))
    for name in names:
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes(), name


def test_relax_names_the_rectangular_cell_for_a_primitive_block(tmp_path):
    with pytest.raises(ValueError, match="; cell='rectangular' cuts the block from the lattice's rectangular cell$"):
        sphkern.relax("wendland_c2", "fcc", size=[3, 3, 3], k=1.2, steps=1, threads=1, output=str(tmp_path / "a.h5"))


def test_relax_of_a_disturbed_lattice_block_is_the_command_s():
    mine = sphkern.relax("wendland_c2", "sc", size=[6, 6, 6], sigma=0.02, k=1.2, method="shift", steps=5,
                         threads=1)
    theirs = cli_json("relax", "wendland_c2", "sc", "--size", "6,6,6", "--sigma", "0.02", "--k", "1.2",
                      "--method", "shift", "--steps", "5", "--threads", "1")
    assert mine.pop("positions").shape == (216, 3)
    close(mine, theirs, skip=RELAX_TIMINGS)


def test_run_is_the_command_s(tmp_path):
    mine = sphkern.run("design", str(tmp_path / "a"), no_plots=True)
    done = subprocess.run([CLI, "run", "design", "-o", str(tmp_path / "b"), "--no-plots"], capture_output=True,
                          text=True, check=True)
    assert mine["summary"] == done.stdout
    assert mine["folder"] == str(tmp_path / "a") and mine["figures"] == []
    a, b = (json.loads((tmp_path / x / "results.json").read_text()) for x in "ab")
    assert len(a["cases"]) == mine["cases"]
    close(a["cases"], b["cases"], skip=("seconds",))
    again = sphkern.run(reproduce=str(tmp_path / "a" / "results.json"))
    assert again["agreed"] is True
    reproduced = subprocess.run([CLI, "run", "--reproduce", str(tmp_path / "a" / "results.json")],
                                capture_output=True, text=True, check=True)
    assert again["report"] == reproduced.stdout


def test_run_keeps_an_existing_folder_unless_forced(tmp_path):
    sphkern.run("design", str(tmp_path / "a"), no_plots=True)
    with pytest.raises(sphkern.OutputError) as caught:
        sphkern.run("design", str(tmp_path / "a"), no_plots=True)
    assert isinstance(caught.value, OSError) and caught.value.exit_code == 5
    assert sphkern.run("design", str(tmp_path / "a"), no_plots=True, force=True)["cases"] > 0


def test_run_without_gnuplot_warns_that_the_figures_are_skipped(tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path))
    with pytest.warns(RuntimeWarning, match="gnuplot not found"):
        r = sphkern.run("design", str(tmp_path / "a"))
    assert r["figures"] == [] and (tmp_path / "a" / "results.json").is_file()
