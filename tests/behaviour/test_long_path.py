"""A long output path: the folders made on the way down are removed when the run fails (its own
file: making and removing some 2000 nested folders takes seconds)."""
import os

from conftest import expect


def test_a_path_too_long_leaves_no_folder(tmp_path):
    (tmp_path / "s_ok.json").write_text('{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "plots": false}')
    s_ok = str(tmp_path / "s_ok.json")
    (tmp_path / "longpath").mkdir()
    expect(["run", s_ok, "-o", str(tmp_path / "longpath") + "/d" * 2100 + "/out"], 5, r"cannot create")
    assert not os.listdir(tmp_path / "longpath")
