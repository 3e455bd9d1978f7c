"""Several sites (indices out of range, empty lists, terminations that do not exist, a study of
every site) and the resolution axes: h_over_l = k / a_p^(1/D) (sc, a_p = 1: h_over_l = k; fcc:
a_p = 1/sqrt(2)); nh windows from fcc's coordination shells 12, 6, 24, 12, 24, 8, 48 at 1,
sqrt 2, sqrt 3, 2, sqrt 5, sqrt 6, sqrt 7."""
import json
import os

import pytest
from conftest import EXAMPLES, expect, fill, run, table, write

CASES = [
    ("roots-honeycomb-site-2", ["roots", "cubic_bspline", "{examples}/honeycomb.json", "--site", "2"],
     3, "--site: site 2 does not exist; lattice honeycomb has sites 0 to 1"),
    ("surface-honeycomb-site-7", ["surface", "cubic_bspline", "{examples}/honeycomb.json", "--k", "1.2", "--site", "7"],
     3, "error: --site: site 7 does not exist; lattice honeycomb has sites 0 to 1$"),
    ("surface-honeycomb-termination-2",
     ["surface", "cubic_bspline", "{examples}/honeycomb.json", "--k", "1.2", "--termination", "2"],
     3, r"termination 2 does not exist; lattice honeycomb has 2 plane type\(s\) normal to this gravity, 0 to 1"),
    ("roots-axis-time", ["roots", "cubic_bspline", "fcc", "--axis", "time"],
     3, '--axis "time" is unknown, expected k, h_over_l or nh'),
    ("roots-nh-13-to-17", ["roots", "cubic_bspline", "fcc", "--axis", "nh", "--kmin", "13", "--kmax", "17"],
     3, "no k has between 13 and 17 neighbours inside the support on fcc"),
    ("eps-axis-nh-one-value", ["eps", "cubic_bspline", "fcc", "--k", "30", "--axis", "nh"],
     3, "--axis nh names a window, not one value"),
    ("lattices-honeycomb", ["lattices", "{examples}/honeycomb.json"], 0, "^$"),
    ("lattices-no-such-file", ["lattices", "{w}/nosuch.json"], 3, "nosuch.json: no such file"),
]


@table(CASES)
def test_site_or_axis(tmp_path, args, code, pattern):
    expect(fill(args, tmp_path), code, pattern)


STUDY_CASES = [
    ("study-site-5",
     {"s_sites.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["{examples}/honeycomb.json"], "sites": [0, 5], "plots": false}'},
     ["run", "{w}/s_sites.json", "-o", "{w}/out_sites"],
     3, "s_sites.json: /sites: sites: site 5 does not exist; lattice honeycomb has sites 0 to 1"),
    ("study-sites-empty",
     {"s_nosites.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "sites": [], "plots": false}'},
     ["run", "{w}/s_nosites.json", "-o", "{w}/out_sites"],
     3, "s_nosites.json: /sites: empty array, expected at least 1"),
    ("study-sites-some",
     {"s_badsites.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "sites": "some", "plots": false}'},
     ["run", "{w}/s_badsites.json", "-o", "{w}/out_sites"],
     3, 's_badsites.json: /sites: expected "all" or an array of site indices'),
    ("study-axis-tau",
     {"s_axis.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "k": {"axis": "tau"}, "plots": false}'},
     ["run", "{w}/s_axis.json", "-o", "{w}/out_axis"],
     3, 's_axis.json: /k/axis: axis "tau" is unknown, expected k, h_over_l or nh'),
    ("study-axis-eta",
     {"s_oldeta.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "k": {"axis": "eta"}, "plots": false}'},
     ["run", "{w}/s_oldeta.json", "-o", "{w}/out_oldeta"],
     3, 's_oldeta.json: /k/axis: axis "eta" is the old name of sphkern.s own'),
]


@pytest.mark.parametrize("files,args,code,pattern", [c[1:] for c in STUDY_CASES], ids=[c[0] for c in STUDY_CASES])
def test_study_sites_or_axis(tmp_path, files, args, code, pattern):
    write(tmp_path, files)
    expect(fill(args, tmp_path), code, pattern)
    assert sorted(os.listdir(tmp_path)) == sorted(files)


def test_a_study_of_every_site(tmp_path):
    (tmp_path / "s_allsites.json").write_text(
        '{"name": "s", "kernels": ["cubic_bspline", "morris_quintic"], "lattices": ["' + str(EXAMPLES / "honeycomb.json") +
        '", "fcc"], "sites": "all", "lateral": true, "plots": false}')
    expect(["run", str(tmp_path / "s_allsites.json"), "-o", str(tmp_path / "out_allsites")], 0, r"cases in")
    # The study reports every site and both verdicts.
    assert "Each site on its own (along gravity / every direction)" in (tmp_path / "out_allsites" / "report.md").read_text()


def window(*args):
    out = run(["roots", *args, "--json"])
    assert out.returncode == 0, out.stderr
    return "%.12f %.12f" % tuple(json.loads(out.stdout)[0]["k_range"])


def test_h_over_l_on_sc_is_k():
    assert window("cubic_bspline", "sc", "--axis", "h_over_l", "--kmin", "0.8", "--kmax", "1.2") == "0.800000000000 1.200000000000"


def test_h_over_l_on_fcc():
    assert window("cubic_bspline", "fcc", "--axis", "h_over_l", "--kmin", "1", "--kmax", "1.4") == \
        "%.12f %.12f" % (2 ** (-1 / 6), 1.4 * 2 ** (-1 / 6))


def test_nh_on_fcc_42_to_78_neighbours():
    assert window("cubic_bspline", "fcc", "--axis", "nh", "--kmin", "30", "--kmax", "100")[:14] == "%.12f" % (3 ** 0.5 / 2)


def test_a_study_on_the_h_over_l_axis_says_so(tmp_path):
    (tmp_path / "s_eta.json").write_text(
        '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc", "sc"], '
        '"k": {"axis": "h_over_l", "min": 0.9, "max": 1.5, "samples": 51}, "plots": false}')
    expect(["run", str(tmp_path / "s_eta.json"), "-o", str(tmp_path / "out_eta")], 0, r"cases in")
    assert "for some h_over_l in [0.9, 1.5]" in (tmp_path / "out_eta" / "report.md").read_text()


def test_a_user_lattice_described():
    # Two sites with three nearest neighbours each.
    out = run(["lattices", str(EXAMPLES / "honeycomb.json"), "--json"])
    d = json.loads(out.stdout)[0]
    assert d["sites"] == 2 and [s["shells"][0]["count"] for s in d["site_details"]] == [3, 3], d
