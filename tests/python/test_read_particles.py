"""sphkern.read_particles gives a file's arrays and header as the readers see them: the values
written here by h5py (SWIFT's layout, with its Time) and as CSV, the box, the time, and one
error kind for a missing file. Run by ctest with the module on PYTHONPATH."""
import numpy as np
import pytest

import sphkern

h5py = pytest.importorskip("h5py")


def test_a_swift_snapshot_reads_as_written(tmp_path):
    rng = np.random.default_rng(3)
    x, h, m, rho = rng.uniform(0, 2, (50, 3)), rng.uniform(0.1, 0.2, 50), rng.uniform(1, 2, 50), rng.uniform(0.5, 1, 50)
    with h5py.File(tmp_path / "s.hdf5", "w") as f:
        f.create_group("Header").attrs.update({"BoxSize": [2.0, 2.0, 2.0], "NumPart_Total": [50, 0, 0, 0, 0, 0],
                                               "MassTable": [0.0] * 6, "Time": [1.25]})
        f.create_group("HydroScheme").attrs["Kernel gamma"] = 1.825742
        part = f.create_group("PartType0")
        part["Coordinates"], part["SmoothingLengths"], part["Masses"], part["Densities"] = x, h, m, rho
    d = sphkern.read_particles(str(tmp_path / "s.hdf5"))
    assert d["dimension"] == 3 and d["time"] == 1.25 and d["support_per_h"] == 1.825742
    for name, want in (("positions", x), ("h", h), ("masses", m), ("densities", rho)):
        assert np.array_equal(d[name], want), name
    assert np.array_equal(d["box"], 2 * np.eye(3))


def test_a_csv_takes_a_box_and_has_no_time(tmp_path):
    (tmp_path / "p.csv").write_text("x,y\n0.25,0.5\n1.75,0.5\n")
    d = sphkern.read_particles(str(tmp_path / "p.csv"), box=[1.5, 1])
    assert d["time"] is None and d["h"] is None and d["box"].tolist() == [[1.5, 0], [0, 1]]
    # Wrapped into the box, as the measures see it.
    assert np.allclose(d["positions"], [[0.25, 0.5], [0.25, 0.5]], rtol=0, atol=1e-15)
    with pytest.raises(FileNotFoundError):
        sphkern.read_particles(str(tmp_path / "none.csv"))


def write_run(tmp_path, times):
    """A run's SWIFT snapshots at these times, 400 random particles each."""
    rng = np.random.default_rng(5)
    files = []
    for k, t in enumerate(times):
        path = tmp_path / f"snap_{k:03d}.hdf5"
        with h5py.File(path, "w") as f:
            f.create_group("Header").attrs.update({"BoxSize": [1.0, 1.0, 1.0], "NumPart_Total": [400, 0, 0, 0, 0, 0],
                                                   "MassTable": [0.0] * 6, "Time": [t]})
            part = f.create_group("PartType0")
            part["Coordinates"], part["Masses"] = rng.uniform(0, 1, (400, 3)), np.full(400, 1 / 400)
        files.append(str(path))
    return files


def test_particles_takes_a_file_or_a_runs_files_as_the_command_line(tmp_path):
    import json
    import os
    import subprocess
    cli = os.environ.get("SPHKERN_CLI") or os.path.join(os.path.dirname(sphkern.__file__), "..", "sphkern")
    files = write_run(tmp_path, [0.4, 0.1])
    one = sphkern.particles("cubic_bspline", files[0], h_over_l=1.3)
    series = sphkern.particles("cubic_bspline", files, h_over_l=1.3)
    assert [s["time"] for s in series] == [0.1, 0.4] and series[1]["statistics"] == one["statistics"]
    assert np.array_equal(series[1]["e0"], one["e0"])
    if os.path.exists(cli):
        doc = json.loads(subprocess.run([cli, "particles", "cubic_bspline", files[0], "--h-over-l", "1.3", "--json"],
                                        capture_output=True, text=True, check=True).stdout)
        assert doc["statistics"] == one["statistics"]


def test_bad_arguments_name_the_keyword(tmp_path):
    (tmp_path / "p.csv").write_text("x,y\n0.25,0.5\n0.75,0.5\n")
    with pytest.raises(sphkern.BadValue, match=r"^neighbours_by: \"weight\", expected \"number\" or \"mass\"$"):
        sphkern.particles("cubic_bspline", str(tmp_path / "p.csv"), box=[1, 1], code="swift", value=1.2,
                          neighbours_by="weight")
    with pytest.raises(sphkern.BadValue, match=r"^neighbours_by: what a code's density solve counts"):
        sphkern.particles("cubic_bspline", str(tmp_path / "p.csv"), box=[1, 1], h_over_l=1.2, neighbours_by="mass")
    with pytest.raises(FileNotFoundError):
        sphkern.particles("cubic_bspline", [str(tmp_path / "none.csv"), str(tmp_path / "p.csv")], box=[1, 1], h_over_l=1.2)
    with pytest.raises(sphkern.BadValue, match="box"):
        sphkern.read_particles(str(tmp_path / "p.csv"), box=[1, -1])


def test_a_series_skips_a_broken_snapshot_with_keep_going_and_warns_naming_it(tmp_path):
    files = write_run(tmp_path, [0.2, 0.1])
    broken = tmp_path / "snap_009.hdf5"
    broken.write_bytes(b"\x89HDF\r\n\x1a\n" + b"\0" * 64)
    with pytest.raises(sphkern.Error, match="snap_009.hdf5"):
        sphkern.particles("cubic_bspline", files + [str(broken)], h_over_l=1.3)
    with pytest.warns(RuntimeWarning, match=r"^skipped .*snap_009\.hdf5: "):
        series = sphkern.particles("cubic_bspline", files + [str(broken)], h_over_l=1.3, keep_going=True)
    alone = [sphkern.particles("cubic_bspline", f, h_over_l=1.3) for f in files]
    assert [s["time"] for s in series] == [0.1, 0.2]
    assert [s["statistics"] for s in series] == [alone[1]["statistics"], alone[0]["statistics"]]
    with pytest.raises(sphkern.Error, match="none of the 1 snapshots"), pytest.warns(RuntimeWarning):
        sphkern.particles("cubic_bspline", [str(broken)], h_over_l=1.3, keep_going=True)


def test_a_series_figure_is_the_command_lines(tmp_path):
    import os
    import subprocess
    files = write_run(tmp_path, [0.5, 0.0, 1.0])
    out = tmp_path / "figures"
    out.mkdir()
    sphkern.particles("cubic_bspline", files, h_over_l=1.3, plot=str(out / "errors.svg"))
    assert os.listdir(out) == ["errors.svg"]
    svg = (out / "errors.svg").read_text()
    assert svg.lstrip().startswith("<?xml") and svg.rstrip().endswith("</svg>")
    cli = os.environ.get("SPHKERN_CLI")
    if cli:
        subprocess.run([cli, "particles", "cubic_bspline", *files, "--h-over-l", "1.3", "--plot", str(out / "cli.svg")],
                       capture_output=True, check=True)
        assert (out / "cli.svg").read_text() == svg
    with pytest.raises(sphkern.BadValue, match=r"^plot .*\.gif: expected a figure file ending in \.svg, \.png or \.pdf$"):
        sphkern.particles("cubic_bspline", files, h_over_l=1.3, plot=str(out / "errors.gif"))
    with pytest.raises(sphkern.BadValue, match=r"^plot: a series' figure"):
        sphkern.particles("cubic_bspline", files[0], h_over_l=1.3, plot=str(out / "one.svg"))
    assert sorted(os.listdir(out)) == (["cli.svg", "errors.svg"] if cli else ["errors.svg"])
