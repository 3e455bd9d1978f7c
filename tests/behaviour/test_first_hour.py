"""The first hour (the first-hour issue). Typos get the right word: an unknown command or option
is named with the nearest one, a value that is not a number with the form expected, the extra
words in the order typed, a misspelt source with the sources there are. Then what a newcomer
meets next: a study's paths, read from the study's folder, and `run --reproduce` from any
folder; the guide's own study outside the repository; relax's density and internal energy;
the words of the shipped studies; check's columns; the options a budget names; a SWIFT file
without /HydroScheme; a particle source too sparse for its N_H refused before any section."""
import json
import re
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest
from conftest import expect, run

CASES = [
    ("command", ["rots"], 2, r'^sphkern: error: unknown command "rots" \(did you mean "roots"\?\); the commands are run, '),
    ("command-case", ["Roots", "cubic_bspline", "fcc"], 2, r'unknown command "Roots" \(did you mean "roots"\?\)'),
    ("option", ["roots", "cubic_bspline", "fcc", "--stabilty"], 2,
     r'^sphkern: error: roots: unknown option "--stabilty" \(did you mean "--stability"\?\)'),
    ("option-with-value", ["roots", "cubic_bspline", "fcc", "--k-max", "1.5"], 2,
     r'roots: unknown option "--k-max" \(did you mean "--kmax"\?\)'),
    ("not-a-number", ["roots", "cubic_bspline", "fcc", "--kmin", "abc"], 2,
     r"^sphkern: error: --kmin abc: expected a number \(such as 1\.2 or 2e-3\)$"),
    ("extra-words-in-order", ["eps", "cubic_bspline", "fcc", "--k", "1.2", "one", "two"], 2,
     r"eps: the arguments one two were not expected"),
    ("source", ["particles", "cubic_bspline", "poison", "--count", "100"], 3,
     r'^sphkern: error: unknown source "poison" \(did you mean "poisson"\?\); expected poisson, a lattice \(bcc, '),
]


@pytest.mark.parametrize("args,code,pattern", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_typo(args, code, pattern):
    expect(args, code, pattern)


def test_a_repeatable_option_takes_one_word_each_time(broken):
    import os
    plugin = os.path.join(broken, "changes_folder.so")
    expect(["eps", "--plugin", plugin, "changes_folder", "fcc", "--k", "1.2"], 0, r"^$")
    expect(["eps", "--set", "beta=2", "wendland_c2_shape", "fcc", "--k", "1.2"], 0, r"^$")
    expect(["eps", "wendland_c2_shape", "fcc", "--k", "1.2", "--set", "beta=2", "--plugin", plugin, "--plugin",
            os.path.join(broken, "closes_descriptors.so")], 0, r"^$")


def test_sphkerns_own_option_after_the_command_is_placed():
    expect(["relax", "cubic_bspline", "fcc", "--k", "1.2", "--log-level", "warn"], 2,
           r"^sphkern: error: --log-level is sphkern's own option: give it before the command \(sphkern --log-level VALUE relax")


def test_a_memory_limit_below_one_byte_is_not_taken_for_none():
    expect(["particles", "cubic_bspline", "poisson", "--count", "100", "--nh", "40", "--memory-limit", "5e-324"], 2,
           r"^sphkern: error: --memory-limit 5e-324: less than one byte; expected 0")


ROOT = Path(__file__).resolve().parents[2]

POWER_KERNEL = {"name": "power_c2", "support": 2, "dimensions": [2, 3], "normalise": True,
                "parameters": [{"name": "p", "default": 4, "min": 3, "max": 8}],
                "w": "q < 2 ? (1 - q/2)^p * (1 + p*q/2) : 0"}
STRETCHED = {"name": "stretched", "dimension": 3, "basis": [[1, 0, 0], [0.5, 0.8660254037844386, 0], [0, 0, 1.7]],
             "motif": [[0, 0, 0], [0.3333333333333333, 0.3333333333333333, 0.5]]}


def write_study_tree(top):
    """top/plugin/power.json, top/mine/stretched.json, top/mine/grains.csv and top/mine/s.json naming
    them as they sit beside it; returns the study file."""
    (top / "plugin").mkdir(parents=True)
    (top / "mine").mkdir()
    (top / "plugin" / "power.json").write_text(json.dumps(POWER_KERNEL))
    (top / "mine" / "stretched.json").write_text(json.dumps(STRETCHED))
    rng = np.random.default_rng(4)
    rows = "\n".join(f"{x!r},{y!r},{z!r}" for x, y, z in rng.random((400, 3)))
    (top / "mine" / "grains.csv").write_text("x,y,z\n" + rows + "\n")
    study = {"name": "paths", "kernels": ["wendland_c2", {"kernel": "../plugin/power.json", "set": {"p": 5}}],
             "lattices": ["fcc", "stretched.json"], "k": {"min": 1.0, "max": 2.0, "samples": 11},
             "particles": {"sources": [{"lattice": "stretched.json", "size": [6, 6, 4]},
                                       {"file": "grains.csv", "box": [1, 1, 1]}],
                           "nh": {"min": 60, "max": 80, "steps": 1}}}
    (top / "mine" / "s.json").write_text(json.dumps(study))
    return top / "mine" / "s.json"


def test_a_study_runs_and_reproduces_from_any_folder(tmp_path):
    write_study_tree(tmp_path / "files")
    for folder in ("elsewhere", "third/deeper"):
        (tmp_path / folder).mkdir(parents=True)
    out = run(["run", "../files/mine/s.json", "--no-plots", "-o", "out"], cwd=tmp_path / "elsewhere")
    assert out.returncode == 0, out.stderr
    results = json.loads((tmp_path / "elsewhere" / "out" / "results.json").read_text())
    assert results["study_file"] == str(tmp_path / "files" / "mine" / "s.json")
    again = run(["run", "--reproduce", "../../elsewhere/out/results.json"], cwd=tmp_path / "third" / "deeper")
    assert again.returncode == 0, again.stderr
    assert again.stdout.startswith("reproduced: all "), again.stdout


def test_a_missing_file_of_a_study_is_named_as_tried(tmp_path):
    study = write_study_tree(tmp_path / "files")
    (tmp_path / "files" / "plugin" / "power.json").unlink()
    tried = re.escape(str(tmp_path / "files" / "plugin" / "power.json"))
    expect(["run", str(study), "--no-plots", "-o", str(tmp_path / "out")], 3, rf"/kernels/1: .*{tried}")


def test_the_guides_own_study_runs_outside_the_repository(tmp_path):
    sys.path.insert(0, str(ROOT / "tests" / "cli"))
    from markdown_docs import blocks
    text = (ROOT / "share" / "docs" / "guide-lattices-and-studies.md").read_text()
    found = blocks(text)
    files = [(w[5:], body) for info, _, body in found for w in info if w.startswith("file=")]
    names = [name for name, _ in files]
    assert {"stretched-hcp.json", "my-study.json"} <= set(names), names
    for name, body in files[:names.index("my-study.json") + 1]:
        (tmp_path / name).write_text("\n".join(body) + "\n")
    body = next(body for info, _, body in found if info == ["sh"] and any("my-study.json" in line for line in body))
    for line in body:
        argv = line.split()
        assert argv[0] == "sphkern", line
        out = run(argv[1:], cwd=tmp_path)
        assert out.returncode == 0, f"{line}: {out.stderr}"
    assert (tmp_path / "my-study-results" / "results.json").is_file()


def relaxed(tmp_path, name, *extra):
    out = run(["relax", "wendland_c2", "poisson", "--count", "300", "--nh", "60", "--steps", "2", "--output",
               str(tmp_path / name), *extra])
    assert out.returncode == 0, out.stderr
    return tmp_path / name


def test_relax_writes_the_density_and_internal_energy_asked_for(tmp_path):
    with h5py.File(relaxed(tmp_path, "ic.h5", "--rho0", "2.5", "--u", "3.25"), "r") as f:
        masses, u = f["/PartType0/Masses"][:], f["/PartType0/InternalEnergy"][:]
        volume = np.prod(f["/Header"].attrs["BoxSize"])
    assert np.allclose(masses.sum(), 2.5 * volume, rtol=1e-12)
    assert np.all(u == 3.25)
    with h5py.File(relaxed(tmp_path, "default.h5"), "r") as f:
        assert np.allclose(f["/PartType0/Masses"][:].sum(), 1.0 * np.prod(f["/Header"].attrs["BoxSize"]), rtol=1e-12)
        assert np.allclose(f["/PartType0/InternalEnergy"][:], 0.9, rtol=1e-12)  # c^2 / (gamma (gamma - 1)), gamma 5/3
    with h5py.File(relaxed(tmp_path, "ic.hdf5", "--code", "pysph", "--rho0", "4"), "r") as f:
        assert np.all(f["/particles/fluid/arrays/rho"][:] == 4)
    csv = relaxed(tmp_path, "ic.csv", "--rho0", "0.5").read_text().splitlines()
    masses = [float(line.split(",")[-1]) for line in csv if line and not line.startswith("#") and line[0] not in "xX"]
    assert len(masses) == 300 and np.isclose(sum(masses), 0.5, rtol=1e-12)  # the unit box of the Poisson source


RELAX = ["relax", "wendland_c2", "poisson", "--count", "300", "--nh", "60", "--steps", "2"]
INITIAL_STATE_CASES = [
    ("rho0-zero", [*RELAX, "--output", "x.h5", "--rho0", "0"], 2, r"^sphkern: error: --rho0 0: expected a positive finite number"),
    ("u-negative", [*RELAX, "--output", "x.h5", "--u", "-1"], 2, r"^sphkern: error: --u -1: expected a positive finite number"),
    ("u-infinite", [*RELAX, "--output", "x.h5", "--u", "inf"], 2, r"^sphkern: error: --u inf: expected a positive finite number"),
    ("rho0-without-output", [*RELAX, "--rho0", "2"], 2, r"^sphkern: error: --rho0 sets what --output writes; expected --output too$"),
    ("u-in-csv", [*RELAX, "--output", "x.csv", "--u", "2"], 2, r"^sphkern: error: --u: x.csv holds x, y\[, z\], h and m, no internal energy; expected an .h5 or .hdf5 --output \(or a Phantom dump\)$"),
]


@pytest.mark.parametrize("args,code,pattern", [c[1:] for c in INITIAL_STATE_CASES], ids=[c[0] for c in INITIAL_STATE_CASES])
def test_relax_initial_state_is_checked(args, code, pattern, tmp_path):
    out = run(args, cwd=tmp_path)
    lines = [line for line in out.stderr.splitlines() if line]
    assert out.returncode == code and len(lines) == 1 and re.search(pattern, lines[0]), out.stderr
    assert not list(tmp_path.iterdir())


def test_the_lattices_3d_title_says_h_over_l_not_eta():
    title = json.loads((ROOT / "share" / "studies" / "lattices-3d.json").read_text())["title"]
    assert "eta" not in title and "h/l" in title, title


def test_checks_columns_start_alike():
    out = run(["check", "cubic_bspline"])
    assert out.returncode == 0, out.stderr
    rows = [line for line in out.stdout.splitlines() if re.match(r"^  \dD ", line)]
    names = {re.match(r"^  \dD (\S+)", line).group(1) for line in rows}
    assert {"gradient_moment", "second_derivative", "normalization"} <= names, names
    status = {re.match(r"^  \dD \S+ +", line).end() for line in rows}
    detail = {re.match(r"^  \dD \S+ +\S+ +", line).end() for line in rows}
    assert len(status) == 1 and len(detail) == 1, out.stdout


def test_the_zone_scan_budget_names_its_options():
    expect(["stability", "cubic_bspline", "fcc", "--k", "1.2", "--grid", "400"], 3,
           r"^sphkern: error: the stability zone scan asks for neighbours x wave vectors = \d+, more than the limit of "
           r"500000000; make it smaller: a smaller --k or --grid$")


def test_a_file_without_hydroscheme_is_told_of_code_swift(tmp_path):
    path = tmp_path / "noscheme.h5"
    g = (np.arange(6) + 0.5) / 6
    x = np.array(np.meshgrid(g, g, g, indexing="ij")).reshape(3, -1).T
    with h5py.File(path, "w") as f:
        f.create_group("Header").attrs["BoxSize"] = [1.0, 1.0, 1.0]
        part = f.create_group("PartType0")
        part["Coordinates"] = x
        part["SmoothingLengths"] = np.full(len(x), 0.2)
    expect(["particles", "wendland_c2", str(path)], 3,
           r"the file's smoothing lengths need a convention: --support-per-h X, .*--code NAME, the code that wrote it "
           r"\(--code swift: SWIFT's kernel gamma of the kernel\), or give --h-over-l E or --nh N$")
    out = run(["particles", "wendland_c2", str(path), "--code", "swift"])
    assert out.returncode == 0, out.stderr


def test_a_poisson_source_too_sparse_for_its_nh_fails_before_any_section(tmp_path):
    study = {"name": "sparse", "kernels": ["wendland_c2"], "lattices": ["fcc"], "k": {"samples": 11},
             "stability": {"k": {"min": 1.0, "max": 2.0, "steps": 4}},
             "particles": {"sources": [{"poisson": 3, "count": 2000}], "nh": {"min": 1, "max": 60, "steps": 2}}}
    (tmp_path / "s.json").write_text(json.dumps(study))
    out = run(["--log-level", "info", "run", "s.json", "--no-plots", "-o", "out"], cwd=tmp_path)
    lines = [line for line in out.stderr.splitlines() if line]
    assert out.returncode == 3, out.stderr
    assert re.search(r"^sphkern: error: s.json: /particles/sources/0: .*particle \d+ has no neighbour inside its support",
                     lines[-1]), out.stderr
    assert not any("stability" in line for line in lines), out.stderr  # no section ran before the refusal
    assert not (tmp_path / "out").exists()


def test_a_code_setting_is_left_to_the_run_where_a_kernel_the_code_lacks_is_left_out(tmp_path):
    study = {"name": "code", "kernels": ["cubic_bspline", "wendland_c2"], "lattices": ["fcc"], "k": {"samples": 11},
             "particles": {"sources": [{"poisson": 3, "count": 2000}], "code": {"name": "gadget2", "nngb": 58}}}
    (tmp_path / "s.json").write_text(json.dumps(study))
    expect(["--log-level", "warn", "run", "s.json", "--no-plots", "-o", "out"], 0,
           r"^sphkern: warning: particles: gadget2 does not ship wendland_c2; it is left out of poisson", cwd=tmp_path)


def test_particle_figures_are_named_after_their_sources_and_label_their_sweep(tmp_path):
    study = write_study_tree(tmp_path / "files")
    out = run(["run", str(study), "-o", str(tmp_path / "out")])
    assert out.returncode == 0, out.stderr
    figures = sorted(p.name for p in (tmp_path / "out" / "plots").glob("particles-*.svg"))
    # The file source by its own name, not its path; the lattice source by its label.
    assert "particles-grains.svg" in figures and not any("files" in f or "tmp" in f for f in figures), figures
    script = (tmp_path / "out" / "plots" / "particles-grains.gp").read_text()
    assert "set xtics ('60' 60, '80' 80)" in script  # N_H 60 to 80: labelled at the sweep's values
    assert script.count("unset key") == 1  # one legend for the figure


def test_a_studys_progress_says_which_part_it_estimates_and_what_follows(tmp_path):
    # An estimate covers the part that runs: the parts after it are named, not timed, since
    # their cost is not known until they run (a stability part of seconds before a particle
    # part of minutes made "about 6 s left" read as the study's end).
    (tmp_path / "parts.json").write_text(json.dumps({
        "name": "parts", "kernels": ["cubic_bspline", "wendland_c2"], "lattices": ["fcc"],
        "k": {"min": 1.2, "max": 1.4, "samples": 5},
        "stability": {"k": {"min": 1.2, "max": 1.4, "steps": 2}, "grid": 4},
        "particles": {"sources": [{"poisson": 3, "count": 500, "seed": 1}], "nh": {"min": 40, "max": 60, "steps": 1}}}))
    out = run(["run", "parts.json", "--no-plots", "-o", "out"], cwd=tmp_path, env_extra={"SPHKERN_PROGRESS_SECONDS": "0"})
    assert out.returncode == 0, out.stderr
    lines = out.stderr.splitlines()
    for part, scope in [("study parts, accuracy: 1/2", "in this part (1 of 3), then stability and particles"),
                        ("stability: 1/2", "in this part (2 of 3), then particles"),
                        ("particles: 1/2", "in this part (3 of 3)")]:
        line = next(line for line in lines if part in line)
        assert re.search(r"about \d+ s left " + re.escape(scope) + "$", line), line
