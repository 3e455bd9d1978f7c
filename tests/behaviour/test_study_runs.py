"""Studies that run: a results folder written once (again only with --force), `run --reproduce`
on it and on a changed copy, a code's setting in the particles section, shell lists keyed by R,
a volume coefficient written as text, names relative to the study file, and a lattice a study
reports as not available."""
import csv
import json
import os
import shutil

from conftest import BROKEN, EXAMPLES, LATTICES, expect, run

S_OK = '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "plots": false}'


def test_results_folder_reproduce_and_force(tmp_path):
    (tmp_path / "s_ok.json").write_text(S_OK)
    study, out10 = str(tmp_path / "s_ok.json"), str(tmp_path / "out10")
    expect(["run", study, "-o", out10], 0, r"cases in")
    expect(["run", study, "-o", out10], 5, r"out10: already exists; use --force")
    # run --reproduce: a results file, and nothing else with it.
    expect(["run", "--reproduce", out10 + "/results.json"], 0, r"^$")
    expect(["run", "--reproduce", str(tmp_path / "nowhere.json")], 3, r"nowhere.json")
    (tmp_path / "notresults.json").write_text('{"cases": []}')
    expect(["run", "--reproduce", str(tmp_path / "notresults.json")], 3,
           r'notresults.json: /: missing required key "study_file"')
    expect(["run", study, "--reproduce", out10 + "/results.json"], 2, r"excludes")
    # A value changed in the results file is blamed on the results file, at its own pointer and value.
    d = json.loads((tmp_path / "out10" / "results.json").read_text())
    d["study"]["epsilon"] = -7
    (tmp_path / "tampered.json").write_text(json.dumps(d))
    expect(["run", "--reproduce", str(tmp_path / "tampered.json")], 3,
           r"tampered.json: /study/epsilon: expected a tolerance in \(0, 1\)")
    expect(["run", study, "--format", "svg,gif", "-o", str(tmp_path / "out15")], 2,
           r'--format svg,gif: "gif" is not a figure format, expected svg, png or pdf')
    expect(["run", study, "-o", out10, "--force"], 0, r"cases in")
    # A failed run leaves no output folder behind, partial or not.
    assert sorted(os.listdir(tmp_path)) == ["notresults.json", "out10", "s_ok.json", "tampered.json"]


def test_reproduce_compares_the_particles_section(tmp_path):
    # --reproduce compares the particles section too: a relaxed source reproduces, a number changed there does not.
    (tmp_path / "s_part.json").write_text(
        '{"name": "s", "kernels": ["wendland_c2"], "lattices": ["fcc"], "plots": false, "particles": {"sources": '
        '[{"poisson": 3, "count": 400, "relax": {"kernel": "wendland_c2", "nh": 60, "steps": 3}}], '
        '"nh": {"min": 40, "max": 60, "steps": 1}}}')
    expect(["--log-level", "warn", "run", str(tmp_path / "s_part.json"), "-o", str(tmp_path / "out_part")], 0, r"^$")
    results = tmp_path / "out_part" / "results.json"
    expect(["--log-level", "warn", "run", "--reproduce", str(results)], 0, r"^$")
    d = json.loads(results.read_text())
    d["particles"][0]["points"][0]["statistics"]["e0"]["rms"] *= 1.5
    (tmp_path / "part_changed.json").write_text(json.dumps(d))
    expect(["--log-level", "warn", "run", "--reproduce", str(tmp_path / "part_changed.json")], 1, r"^$")


def test_a_code_setting_in_the_particles_section(tmp_path):
    # A code's setting in place of the particles section's sweep: the numbers of particles --code;
    # a kernel the code lacks is left out.
    (tmp_path / "s_code.json").write_text(
        '{"name": "s", "kernels": ["cubic_bspline", "wendland_c2"], "lattices": ["fcc"], "plots": false, "particles": '
        '{"sources": [{"poisson": 3, "count": 2000, "seed": 3}], "code": {"name": "gadget2", "nngb": 58}}}')
    expect(["--log-level", "warn", "run", str(tmp_path / "s_code.json"), "-o", str(tmp_path / "out_code")], 0,
           r"^sphkern: warning: particles: gadget2 does not ship wendland_c2; it is left out of poisson, 3D, 2000 particles$")
    cli = run(["--log-level", "warn", "particles", "cubic_bspline", "poisson", "--count", "2000", "--seed", "3",
               "--code", "gadget2", "--nngb", "58", "--json"])
    assert cli.returncode == 0, cli.stderr
    s = json.loads((tmp_path / "out_code" / "results.json").read_text())["particles"]
    c = json.loads(cli.stdout)
    assert len(s) == 1 and s[0]["code"].startswith("gadget2 nngb = 58")
    assert s[0]["points"][0]["statistics"]["eps_rho"] == c["statistics"]["eps_rho"]


def test_shell_lists_keyed_by_r_as_a_number(tmp_path):
    # Shell lists are keyed by R as a number: "2.0" is the list of R = 2.
    for name, key in (("s_key2", "2"), ("s_key20", "2.0")):
        (tmp_path / f"{name}.json").write_text(
            '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["triangular"], "k": {"samples": 21}, "plots": false, '
            '"modes": [{"name": "p", "shells": {"' + key + '": [1, "sqrt(3)", 2]}}]}')
        expect(["run", str(tmp_path / f"{name}.json"), "-o", str(tmp_path / f"out_{name[2:]}")], 0, r"cases in")
    assert (tmp_path / "out_key2" / "curves.csv").read_bytes() == (tmp_path / "out_key20" / "curves.csv").read_bytes()


def test_a_volume_coefficient_written_as_text(tmp_path):
    # A volume coefficient written as text is a number all the same.
    (tmp_path / "s_ap_text.json").write_text(
        '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "volume_coefficients": ["0.75", 0.75], '
        '"k": {"samples": 21}, "plots": false}')
    expect(["run", str(tmp_path / "s_ap_text.json"), "-o", str(tmp_path / "out_ap_text")], 0, r"cases in")
    with open(tmp_path / "out_ap_text" / "curves.csv") as f:
        rows = [r for r in csv.DictReader(f) if r["volume_coefficient"] == "0.75"]
    assert len(rows) == 42 and rows[:21] == rows[21:] and rows[0]["a_p"] == "0.75"


def test_names_relative_to_the_study_file(tmp_path):
    # Relative names in a study are relative to the study file, run from elsewhere; a file
    # whose name has a '+' is that file, not a blend.
    beside, elsewhere = tmp_path / "beside", tmp_path / "elsewhere"
    (beside / "sub").mkdir(parents=True)
    elsewhere.mkdir()
    d = json.loads((LATTICES / "sc.json").read_text())
    d["name"] = "mine"
    (beside / "my-lattice.json").write_text(json.dumps(d))
    shutil.copy(os.path.join(BROKEN, "abi1_cubic.so"), beside / "x+y.so")
    (beside / "s.json").write_text('{"name": "s", "kernels": ["x+y.so", "cubic_bspline+wendland_c2"], '
                                   '"lattices": ["my-lattice.json"], "k": {"samples": 11}}')
    out = run(["run", "../beside/s.json", "--no-plots", "-o", "out"], cwd=elsewhere)
    assert out.returncode == 0, out.stderr
    r = json.loads((elsewhere / "out" / "results.json").read_text())
    assert {c["lattice"] for c in r["cases"]} == {"mine"}, r["cases"][0]["lattice"]
    assert len(r["cases"]) == 2


def test_a_lattice_without_one_density_is_not_available_in_a_study(tmp_path):
    # In a study a lattice whose sites do not see one SPH density is reported as not available,
    # and the study completes.
    (tmp_path / "s_lieb.json").write_text(
        '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["' + str(EXAMPLES / "lieb.json") + '", "square"], '
        '"stability": {"k": {"steps": 10}}}')
    run(["run", str(tmp_path / "s_lieb.json"), "--no-plots", "-o", str(tmp_path / "out_lieb")])
    assert ("not available: the sites of lattice lieb do not see one SPH density"
            in (tmp_path / "out_lieb" / "report.md").read_text())
    r = json.loads((tmp_path / "out_lieb" / "results.json").read_text())
    s = {x["lattice"]: x for x in r["stability"]}
    assert "refused" in s["lieb"] and s["square"]["stable_intervals"], s.keys()
