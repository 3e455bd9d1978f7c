"""Study files that cannot run: an empty or unknown kernel list, a bad k interval, volume
coefficient, key, lattice, shell list, plugin, surface, stability, sweep, reference table or
relax section. Each is refused before any section runs (exit 3, or 4 for a plugin that crashes),
named by its JSON pointer, and leaves no output folder behind, partial or not."""
import os

import pytest
from conftest import BROKEN, LATTICES, expect, fill, write


def relax_study(relax):
    """A study whose poisson source is relaxed first, with `relax` as its "relax" section."""
    return ('{"name": "s", "kernels": ["wendland_c2"], "lattices": ["fcc"], "plots": false, "particles": '
            '{"sources": [{"poisson": 3, "count": 500, "relax": ' + relax + '}], "nh": {"min": 30, "max": 60, "steps": 1}}}')


def early_study(rest):
    """A study of the plugin that aborts above k = 1.3 (exit 4 had its bulk section run), with `rest`."""
    return ('{"name": "s", "kernels": ["' + BROKEN + '/abort_above_k.so"], "lattices": ["fcc"], '
            '"k": {"min": 0.75, "max": 1.5, "samples": 301}, "plots": false, ' + rest + "}")


# A study's value out of range is an input error (exit 3), named by its JSON path.
CASES = [
    # Studies.
    ("kernels-empty", {"s_kernels.json": '{"name": "s", "kernels": [], "lattices": ["fcc"]}'},
     ["run", "{w}/s_kernels.json", "-o", "{w}/out1"],
     3, "s_kernels.json: /kernels: empty array"),
    ("kernel-misspelt",
     {"s_kernel.json": '{"name": "s", "kernels": ["cubic_bsplin"], "lattices": ["fcc"]}'},
     ["run", "{w}/s_kernel.json", "-o", "{w}/out2"],
     3, r's_kernel.json: /kernels/0: unknown kernel "cubic_bsplin" \(did you mean "cubic_bspline"\?\)'),
    ("kernel-2d-on-fcc", {"s_dim.json": '{"name": "s", "kernels": ["composite"], "lattices": ["fcc"]}'},
     ["run", "{w}/s_dim.json", "-o", "{w}/out3"],
     3, "s_dim.json: /kernels/0: kernel composite is defined in 2D only"),
    ("k-interval-reversed",
     {"s_k.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "k": {"min": 1.3, "max": 1.0}}'},
     ["run", "{w}/s_k.json", "-o", "{w}/out4"],
     3, r"s_k.json: /k: k interval: \[1.3, 1\] is not allowed"),
    ("volume-coefficient-zero",
     {"s_ap.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "volume_coefficients": [0]}'},
     ["run", "{w}/s_ap.json", "-o", "{w}/out5"],
     3, "s_ap.json: /volume_coefficients/0: expected a positive volume coefficient"),
    ("key-misspelt",
     {"s_key.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "epsilom": 0.01}'},
     ["run", "{w}/s_key.json", "-o", "{w}/out6"],
     3, r's_key.json: /: unknown key "epsilom" \(did you mean "epsilon"\?\)'),
    ("lattice-unknown", {"s_lat.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcx"]}'},
     ["run", "{w}/s_lat.json", "-o", "{w}/out7"],
     3, 's_lat.json: /lattices/0: unknown lattice "fcx"'),
    ("shell-radius-text",
     {"s_shell.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["triangular"], "modes": [{"name": "p", "shells": {"2": [1, "sqrt(x)"]}}]}'},
     ["run", "{w}/s_shell.json", "-o", "{w}/out8"],
     3, "s_shell.json: /modes/0/shells/2/1: expected a shell radius"),
    ("no-shell-list-for-R",
     {"s_nor.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["triangular"], "modes": [{"name": "p", "shells": {"3": [1]}}]}'},
     ["run", "{w}/s_nor.json", "-o", "{w}/out9"],
     3, "s_nor.json: /modes/0/shells: no shell list for kernel cubic_bspline with support R = 2"),
    ("plugin-crash",
     {"s_plugin.json": '{"name": "s", "kernels": ["{broken}/crash_in_w.so"], "lattices": ["fcc"]}'},
     ["run", "{w}/s_plugin.json", "-o", "{w}/out11"],
     4, "crash_in_w.so: plugin crashed with signal 11"),
    ("surface-form",
     {"s_surface.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "surface": {"forms": ["up"]}}'},
     ["run", "{w}/s_surface.json", "-o", "{w}/out12"],
     3, 's_surface.json: /surface/forms/0: gradient form "up" is unknown'),
    ("stability_gamma_zero",
     {"s_gamma.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"gamma": 0}}'},
     ["run", "{w}/s_gamma.json", "-o", "{w}/out12"],
     3, "s_gamma.json: /stability/gamma: "),
    ("stability_k",
     {"s_stability_k.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"k": {"min": 1.2, "max": 1.1}}}'},
     ["run", "{w}/s_stability_k.json", "-o", "{w}/out12"],
     3, "s_stability_k.json: /stability/k/max: expected max > min"),
    ("stability_key",
     {"s_stability_key.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"gama": 1.4}}'},
     ["run", "{w}/s_stability_key.json", "-o", "{w}/out12"],
     3, 's_stability_key.json: /stability: unknown key "gama"'),
    # Each field of the stability section, refused with its pointer.
    ("stability_dispersion_k", {"s_stability_field.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"dispersion_k": "worst"}}'},
     ["run", "{w}/s_stability_field.json", "-o", "{w}/out12"], 3,
     's_stability_field.json: /stability/dispersion_k: expected a number or "best"'),
    ("stability_grid", {"s_stability_field.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"grid": 1}}'},
     ["run", "{w}/s_stability_field.json", "-o", "{w}/out12"], 3,
     r"s_stability_field.json: /stability/grid = 1, expected 2 to 400$"),
    ("stability_path_points", {"s_stability_field.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"path_points": 1}}'},
     ["run", "{w}/s_stability_field.json", "-o", "{w}/out12"], 3,
     r"s_stability_field.json: /stability/path_points = 1, expected 2 to 100000$"),
    ("stability_k_steps", {"s_stability_field.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"k": {"steps": 0}}}'},
     ["run", "{w}/s_stability_field.json", "-o", "{w}/out12"], 3,
     r"s_stability_field.json: /stability/k/steps = 0, expected 1 to 2000$"),
    ("stability_k_max", {"s_stability_field.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"k": {"min": 0.9}}}'},
     ["run", "{w}/s_stability_field.json", "-o", "{w}/out12"], 3,
     's_stability_field.json: /stability/k: missing required key "max"'),
    ("stability_gamma_text", {"s_stability_field.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"gamma": "x"}}'},
     ["run", "{w}/s_stability_field.json", "-o", "{w}/out12"], 3,
     "s_stability_field.json: /stability/gamma: expected a number, got a string"),
    ("roots-stability-steps-0", {}, ["roots", "cubic_bspline", "fcc", "--stability", "--steps", "0"],
     2, "error: --steps 0, expected 1 to 2000$"),
    ("stability_budget",
     {"s_stability_budget.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "stability": {"grid": 200, "k": {"steps": 2000}}}'},
     ["run", "{w}/s_stability_budget.json", "-o", "{w}/out12"],
     3, "kernels x lattices x stability k samples x wave vectors"),
    ("sweep-no-parameter",
     {"s_sweep.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "sweeps": [{"kernel": "cubic_bspline", "parameter": "beta", "range": [0, 1]}]}'},
     ["run", "{w}/s_sweep.json", "-o", "{w}/out13"],
     3, 's_sweep.json: /sweeps/0: kernel cubic_bspline has no parameter "beta"'),
    ("sweep-range-reversed",
     {"s_range.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "sweeps": [{"kernel": "a+b", "parameter": "alpha", "range": [1, 0]}]}'},
     ["run", "{w}/s_range.json", "-o", "{w}/out14"],
     3, r"s_range.json: /sweeps/0/range: expected \[min, max\] with min < max"),
    # A code's setting in place of the particles section's sweep: one of them, with the code's own keys.
    ("code-and-nh",
     {"s_code2.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "plots": false, "particles": {"sources": [{"poisson": 3, "count": 500}], "code": {"name": "gadget2", "nngb": 58}, "nh": {"min": 40, "max": 60}}}'},
     ["run", "{w}/s_code2.json", "-o", "{w}/out_code2"],
     3, 's_code2.json: /particles: expected one of "nh", "h_over_l" and "code"'),
    ("code-unknown-key",
     {"s_code3.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "plots": false, "particles": {"sources": [{"poisson": 3, "count": 500}], "code": {"name": "gadget2", "eta": 1.2}}}'},
     ["run", "{w}/s_code3.json", "-o", "{w}/out_code3"],
     3, 's_code3.json: /particles/code: unknown key "eta"'),
    ("code-nngb-negative",
     {"s_code4.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "plots": false, "particles": {"sources": [{"poisson": 3, "count": 500}], "code": {"name": "gadget2", "nngb": -1}}}'},
     ["run", "{w}/s_code4.json", "-o", "{w}/out_code4"],
     3, "s_code4.json: /particles/code/nngb"),
    # JSON: duplicate keys, every access with file and path.
    ("dupdeep",
     {"s_dupdeep.json": '{"name": "s", "kernels": [{"kernel": "wendland_c2_shape", "set": {"beta": 1}}, {"kernel": "cubic_bspline", "set": {"x": 1, "x": 2}}], "lattices": ["fcc"]}'},
     ["run", "{w}/s_dupdeep.json", "-o", "{w}/out_dup"],
     3, 's_dupdeep.json: /kernels/1/set: duplicate key "x"'),
    ("reference-missing-key",
     {"s_ref.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "compare_with": "ref_missing.json", "plots": false}',
      "ref_missing.json": '{"source": "s", "lattice": "fcc", "volume_coefficient": "voronoi", "mode": "default", "rows": [{"kernel": "cubic_bspline", "k": 1.0, "eps_rho": 0}]}'},
     ["run", "{w}/s_ref.json", "-o", "{w}/out_ref"],
     3, 'ref_missing.json: /rows/0: missing required key "eps_gradp"'),
    ("reference-wrong-type",
     {"s_ref2.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "compare_with": "ref_type.json", "plots": false}',
      "ref_type.json": '{"source": "s", "lattice": "fcc", "volume_coefficient": "voronoi", "mode": "default", "rows": [{"kernel": "cubic_bspline", "no_root": 1}]}'},
     ["run", "{w}/s_ref2.json", "-o", "{w}/out_ref"],
     3, "ref_type.json: /rows/0/no_root: expected true or false, got a number"),
    ("kernel-twice",
     {"s_twice.json": '{"name": "s", "kernels": ["cubic_bspline", "liu_quartic", "cubic_bspline"], "lattices": ["fcc"], "plots": false}'},
     ["run", "{w}/s_twice.json", "-o", "{w}/out_twice"],
     3, r's_twice.json: /kernels/2: kernel "cubic_bspline" is listed twice \(also at /kernels/0\)'),
    # A study source relaxed first: every field of "relax" refused with its JSON path.
    ("relax-kernel", {"s_rk.json": relax_study('{"kernel": "quintic"}')}, ["run", "{w}/s_rk.json", "-o", "{w}/out_rk"],
     3, 's_rk.json: /particles/sources/0/relax: kernel: "quintic" is not one of the study.s kernels'),
    ("relax-method", {"s_rm.json": relax_study('{"kernel": "wendland_c2", "method": "jiggle"}')},
     ["run", "{w}/s_rm.json", "-o", "{w}/out_rm"],
     3, 's_rm.json: /particles/sources/0/relax/method: "jiggle" is unknown, expected pressure or shift'),
    ("relax-nh-and-h_over_l", {"s_rh.json": relax_study('{"kernel": "wendland_c2", "nh": 100, "h_over_l": 1.2}')},
     ["run", "{w}/s_rh.json", "-o", "{w}/out_rh"],
     3, 's_rh.json: /particles/sources/0/relax: expected one of "nh" and "h_over_l"'),
    ("relax-steps", {"s_rs.json": relax_study('{"kernel": "wendland_c2", "steps": 0}')},
     ["run", "{w}/s_rs.json", "-o", "{w}/out_rs"],
     3, "s_rs.json: /particles/sources/0/relax/steps = 0, expected 1 to 10000000"),
    ("relax-h_over_l", {"s_re.json": relax_study('{"kernel": "wendland_c2", "h_over_l": 0}')},
     ["run", "{w}/s_re.json", "-o", "{w}/out_re"],
     3, r"s_re.json: /particles/sources/0/relax/h_over_l = 0: expected a number in \(0, 100\]"),
    ("sweep_order",
     {"s_sweep_order.json": '{"name": "s", "kernels": ["wendland_c2"], "lattices": ["fcc"], "plots": false, "particles": {"sources": [{"poisson": 3, "count": 500}], "nh": {"min": 60, "max": 30}}}'},
     ["run", "{w}/s_sweep_order.json", "-o", "{w}/out_so"],
     3, r"s_sweep_order.json: /particles/nh: \[60, 30\]: expected min < max"),
    ("relax-unknown-key", {"s_ru.json": relax_study('{"kernel": "wendland_c2", "colour": 1}')},
     ["run", "{w}/s_ru.json", "-o", "{w}/out_ru"],
     3, 's_ru.json: /particles/sources/0/relax: unknown key "colour"'),
    # A study's value out of range stays an input error (exit 3), named by its JSON path.
    ("relax-h_over_l-zero", {"s_reta.json": relax_study('{"kernel": "wendland_c2", "h_over_l": 0}')},
     ["run", "{w}/s_reta.json", "-o", "{w}/out_reta"],
     3, "s_reta.json: /particles/sources/0/relax.*expected"),
    ("relax-eta", {"s_reold.json": relax_study('{"kernel": "wendland_c2", "eta": 1.2}')},
     ["run", "{w}/s_reold.json", "-o", "{w}/out_reold"],
     3, 's_reold.json: /particles/sources/0/relax/eta: "eta" is the old name of sphkern.s own h over the mean spacing; expected "h_over_l"'),
    # A study's inputs are all resolved before its first section: a bad reference table, sweep
    # kernel, shell list or relax kernel is refused (exit 3) although the bulk section would
    # abort the run (abort_above_k aborts in W above k = 1.3: exit 4 had it run) or take long,
    # and no output folder is left.
    ("early_ref",
     {"s_early_ref.json": early_study('"compare_with": "ref_early.json"'),
      "ref_early.json": '{"source": "s", "lattice": "fcc", "volume_coefficient": "voronoi", "mode": "default", "rows": [{"kernel": "abort_above_k", "k": 1.0, "eps_rho": 0, "eps_gradp": "x"}]}'},
     ["run", "{w}/s_early_ref.json", "-o", "{w}/out_early_ref"],
     3, "ref_early.json: /rows/0/eps_gradp: expected a number, got a string"),
    ("early_case",
     {"s_early_case.json": early_study('"compare_with": "ref_nocase.json"'),
      "ref_nocase.json": '{"source": "s", "lattice": "fcc", "volume_coefficient": "voronoi", "mode": "default", "rows": [{"kernel": "cubic_bspline", "k": 1.0, "eps_rho": 0, "eps_gradp": 0}]}'},
     ["run", "{w}/s_early_case.json", "-o", "{w}/out_early_case"],
     3, "ref_nocase.json: /rows/0: the study has no case cubic_bspline / fcc / voronoi / mode default"),
    ("early_sweep",
     {"s_early_sweep.json": early_study('"sweeps": [{"kernel": "no_such_kernel", "parameter": "beta", "range": [0, 1]}]')},
     ["run", "{w}/s_early_sweep.json", "-o", "{w}/out_early_sweep"],
     3, 's_early_sweep.json: /sweeps/0: unknown kernel "no_such_kernel"'),
    ("early_param",
     {"s_early_param.json": early_study('"sweeps": [{"kernel": "wendland_c2_shape", "parameter": "alpha", "range": [0, 1]}]')},
     ["run", "{w}/s_early_param.json", "-o", "{w}/out_early_param"],
     3, 's_early_param.json: /sweeps/0: kernel wendland_c2_shape has no parameter "alpha"'),
    ("early_shells",
     {"s_early_shells.json": early_study('"modes": [{"name": "p", "shells": {"3": [1]}}]')},
     ["run", "{w}/s_early_shells.json", "-o", "{w}/out_early_shells"],
     3, "s_early_shells.json: /modes/0/shells: no shell list for kernel abort_above_k with support R = 2"),
    ("early_relax",
     {"s_early_relax.json": early_study('"particles": {"sources": [{"poisson": 3, "count": 500, "relax": {"kernel": "quintic"}}], "nh": {"min": 30, "max": 60, "steps": 1}}')},
     ["run", "{w}/s_early_relax.json", "-o", "{w}/out_early_relax"],
     3, 's_early_relax.json: /particles/sources/0/relax: kernel: "quintic" is not one of the study.s kernels'),
    ("early_surface",
     {"s_early_surface.json": early_study('"surface": {"volume_coefficient": "voronio"}')},
     ["run", "{w}/s_early_surface.json", "-o", "{w}/out_early_surface"],
     3, r's_early_surface.json: /surface/volume_coefficient: lattice fcc has no volume coefficient "voronio" \(did you mean "voronoi"\?\)'),
    ("early_size",
     {"s_early_size.json": early_study('"particles": {"sources": [{"lattice": "fcc", "size": [4, 4]}], "nh": {"min": 30, "max": 60, "steps": 1}}')},
     ["run", "{w}/s_early_size.json", "-o", "{w}/out_early_size"],
     3, "s_early_size.json: /particles/sources/0: size: the lattice is 3D, expected 3 cell counts"),
    ("early_cell",
     {"s_early_cell.json": early_study('"particles": {"sources": [{"lattice": "fcc", "size": [4, 4, 4], "cell": "cubic"}], "nh": {"min": 30, "max": 60, "steps": 1}}')},
     ["run", "{w}/s_early_cell.json", "-o", "{w}/out_early_cell"],
     3, 's_early_cell.json: /particles/sources/0/cell: "cubic" is unknown, expected primitive or rectangular'),
    ("early_file",
     {"s_early_file.json": early_study('"particles": {"sources": [{"file": "early_nan.csv"}], "nh": {"min": 30, "max": 60, "steps": 1}}'),
      "early_nan.csv": "x,y,z\n0,0,0\n0.5,nan,0\n"},
     ["run", "{w}/s_early_file.json", "-o", "{w}/out_early_file"],
     3, "early_nan.csv.*(y|id 1|particle 1)"),
    # The same with a bulk section that runs for seconds (16 x 3 cases of 40000 samples): refused first, nothing left.
    ("early_long",
     {"s_early_long.json": '{"name": "s", "kernels": ["cubic_bspline", "morris_quintic", "liu_quartic", "wendland_c4"], "lattices": ["fcc", "bcc", "sc", "hcp"], "volume_coefficients": ["voronoi", "ball", "cube"], "k": {"samples": 40000}, "plots": false, "compare_with": "ref_early.json"}',
      "ref_early.json": '{"source": "s", "lattice": "fcc", "volume_coefficient": "voronoi", "mode": "default", "rows": [{"kernel": "abort_above_k", "k": 1.0, "eps_rho": 0, "eps_gradp": "x"}]}'},
     ["run", "{w}/s_early_long.json", "-o", "{w}/out_early_long"],
     3, "ref_early.json: /rows/0/eps_gradp: expected a number, got a string"),
    # Shell lists are keyed by R as a number: two keys for one R are refused.
    ("key_twice",
     {"s_key_twice.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["triangular"], "plots": false, "modes": [{"name": "p", "shells": {"2": [1], "2.0": [1, 2]}}]}'},
     ["run", "{w}/s_key_twice.json", "-o", "{w}/out_key_twice"],
     3, "s_key_twice.json: /modes/0/shells/2.0: a second shell list for R = 2.0, expected one per R"),
    # A kernel named in continue_past_support that the study does not have (it used to be ignored).
    ("continue",
     {"s_continue.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["triangular"], "plots": false, "modes": [{"name": "p", "shells": {"2": [1]}, "continue_past_support": ["cubic_bsplin"]}]}'},
     ["run", "{w}/s_continue.json", "-o", "{w}/out_continue"],
     3, r's_continue.json: /modes/0/continue_past_support/0: "cubic_bsplin" is not one of the study.s kernels \(did you mean "cubic_bspline"\?\)'),
    ("ap_text0",
     {"s_ap_text0.json": '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "volume_coefficients": ["voronoi", "0"]}'},
     ["run", "{w}/s_ap_text0.json", "-o", "{w}/out_ap_text0"],
     3, "s_ap_text0.json: /volume_coefficients/1: expected a positive volume coefficient up to 1e6"),
]


@pytest.mark.parametrize("files,args,code,pattern", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_study_refused(tmp_path, files, args, code, pattern):
    write(tmp_path, files)
    expect(fill(args, tmp_path), code, pattern)
    # A failed run leaves no output folder behind, partial or not.
    assert sorted(os.listdir(tmp_path)) == sorted(files)


def test_two_lattices_of_one_name(tmp_path):
    # A copy of fcc under another file name is still named fcc.
    fcc = (LATTICES / "fcc.json").read_text()
    import re
    (tmp_path / "fcc-copy.json").write_text(re.sub(r'"title": *"[^"]*"', '"title": "a copy"', fcc))
    (tmp_path / "s_samename.json").write_text(
        '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc", "' + str(tmp_path) + '/fcc-copy.json"], "plots": false}')
    expect(["run", str(tmp_path / "s_samename.json"), "-o", str(tmp_path / "out_same")], 3,
           r's_samename.json: /lattices/1: lattice name "fcc" is already used by /lattices/0')
    assert not (tmp_path / "out_same").exists()
