"""Outputs: no shell between sphkern and a path; --force replaces only a folder sphkern wrote;
concurrent runs into one folder; staging folders of dead runs; parent folders a failed run made;
single files written only over regular files, never over an input of the run nor each other,
keeping their permissions; a full disk and a file-size limit: exit 5 and nothing left behind
(a path too long: test_long_path.py)."""
import os
import resource
import shutil
import stat
import subprocess
import tempfile
from pathlib import Path

import pytest
from conftest import CLI, LATTICES, expect, run

S_OK = '{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "plots": false}'
BLOCK = ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "4,4,4"]


@pytest.fixture
def s_ok(tmp_path):
    (tmp_path / "s_ok.json").write_text(S_OK)
    return str(tmp_path / "s_ok.json")


def test_quotes_in_paths_are_only_names(tmp_path):
    # No shell: quotes and shell syntax in the output path or the working folder are only names.
    (tmp_path / "s_plot.json").write_text('{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "k": {"samples": 11}}')
    here = tmp_path / "it's here"
    here.mkdir()
    out = run(["run", str(tmp_path / "s_plot.json"), "-o", "x';touch PWNED;'"], cwd=here)
    assert (here / "x';touch PWNED;'" / "plots" / "fcc-default.svg").is_file(), out.stderr
    # No command injected.
    assert not (here / "PWNED").exists() and not Path("PWNED").exists()


def test_force_replaces_only_a_folder_sphkern_wrote(tmp_path, s_ok):
    (tmp_path / "project").mkdir()
    (tmp_path / "project" / "thesis.tex").write_text("keep\n")
    expect(["run", s_ok, "-o", str(tmp_path / "project"), "--force"], 5,
           r"project: exists and is not a results folder sphkern wrote")
    assert (tmp_path / "project" / "thesis.tex").is_file()
    expect(["run", s_ok, "-o", str(tmp_path / "out10")], 0, r"cases in")
    (tmp_path / "link-to-results").symlink_to(tmp_path / "out10")
    expect(["run", s_ok, "-o", str(tmp_path / "link-to-results"), "--force"], 5,
           r"link-to-results: exists and is not a results folder sphkern wrote")
    # --force on a link keeps the link.
    assert (tmp_path / "link-to-results").is_symlink()


def test_concurrent_runs_into_one_folder(tmp_path, s_ok):
    # Concurrent runs into one folder: exactly one wins, the others say the folder exists.
    runs = [subprocess.Popen([CLI, "run", s_ok, "-o", str(tmp_path / "out_race")], stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True) for _ in range(4)]
    results = [(p.wait(timeout=60), p.stderr.read()) for p in runs]
    for p in runs:
        p.stderr.close()
    codes = sorted(code for code, _ in results)
    assert codes == [0, 5, 5, 5], results
    # The losers say why.
    assert any("out_race: already exists" in err for _, err in results), results


def test_a_dead_runs_staging_folder_is_removed(tmp_path, s_ok):
    # A dead run's staging folder (its pid is gone) is removed by the next run; a look-alike
    # that sphkern did not write (no marker) is left alone.
    stale, foreign = tmp_path / ".out_stale.partial-999999999-abcdef", tmp_path / ".out_stale.partial-999999998-foreign"
    stale.mkdir()
    foreign.mkdir()
    (stale / ".sphkern-output").touch()
    expect(["run", s_ok, "-o", str(tmp_path / "out_stale")], 0, r"cases in")
    assert not stale.exists()
    assert foreign.is_dir()


def test_a_failed_run_removes_the_parents_it_created(tmp_path):
    (tmp_path / "s_late.json").write_text('{"name": "s", "kernels": ["no_such_kernel"], "lattices": ["fcc"], "plots": false}')
    expect(["run", str(tmp_path / "s_late.json"), "-o", str(tmp_path / "new1/new2/out")], 3, r'unknown kernel "no_such_kernel"')
    assert not (tmp_path / "new1").exists()


def test_single_files_only_over_regular_files(tmp_path):
    # Single files are written only over regular files.
    target = tmp_path / "target.txt"
    target.write_text("original\n")
    (tmp_path / "link.csv").symlink_to(target)
    expect([*BLOCK, "--csv", str(tmp_path / "link.csv")], 5, r"link.csv: is not a regular file")
    # A link's target is untouched.
    assert target.read_text() == "original\n" and (tmp_path / "link.csv").is_symlink()
    os.mkfifo(tmp_path / "pipe.vtk")
    expect([*BLOCK, "--vtk", str(tmp_path / "pipe.vtk")], 5, r"pipe.vtk: is not a regular file")
    assert stat.S_ISFIFO((tmp_path / "pipe.vtk").stat().st_mode)
    expect([*BLOCK, "--csv", str(target)], 0, r"^$")
    # A regular file is replaced, no partial left.
    assert not target.read_bytes().startswith(b"original")
    assert not [e for e in os.listdir(tmp_path) if "target.txt.partial" in e]


def test_an_output_never_replaces_an_input_nor_another_output(tmp_path):
    # Outputs never replace an input of the run, nor each other.
    shutil.copy(LATTICES / "fcc.json", tmp_path / "in.json")
    expect(["block", "cubic_bspline", str(tmp_path / "in.json"), "--k", "1.2", "--size", "4,4,4", "--csv",
            str(tmp_path / "in.json")], 5, r"--csv .*in.json: is a file this run reads")
    # The lattice file read survives --csv aimed at it.
    assert (tmp_path / "in.json").read_bytes() == (LATTICES / "fcc.json").read_bytes()
    expect([*BLOCK, "--vtk", str(tmp_path / "two.out"), "--csv", str(tmp_path) + "/./two.out"], 5,
           r"--csv .*two.out: --vtk names the same file")
    expect([*BLOCK, "--csv", ""], 2, r"--csv: an empty value")
    expect([*BLOCK, "--vtk", ""], 2, r"--vtk: an empty value")


@pytest.mark.skipif(os.getuid() != 0 or not shutil.which("setpriv"), reason="needs root to run as another user")
def test_a_read_only_file_is_refused_for_a_user_who_may_not_write_it():
    # As another user, as the shell would judge it: a read-only file is not replaced.
    work = Path(tempfile.mkdtemp())
    try:
        work.chmod(0o777)
        (work / "readonly.csv").write_text("kept\n")
        (work / "readonly.csv").chmod(0o444)
        out = subprocess.run(["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", CLI, *BLOCK, "--csv",
                              str(work / "readonly.csv")], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                             timeout=60)
        assert "is read-only for this user" in out.stderr, out.stderr
        assert (work / "readonly.csv").read_text() == "kept\n"
    finally:
        shutil.rmtree(work)


def test_a_replaced_output_keeps_its_permissions(tmp_path):
    expect([*BLOCK, "--csv", str(tmp_path / "mode.csv")], 0, r"^$")
    (tmp_path / "mode.csv").chmod(0o640)
    expect([*BLOCK, "--csv", str(tmp_path / "mode.csv")], 0, r"^$")
    assert stat.S_IMODE((tmp_path / "mode.csv").stat().st_mode) == 0o640


def file_size_limit():
    resource.setrlimit(resource.RLIMIT_FSIZE, (64 * 1024, 64 * 1024))  # ulimit -f 64


def test_a_file_size_limit(tmp_path, s_ok):
    # A file-size limit (ulimit -f): the write fails with one line and exit 5, nothing is left.
    (tmp_path / "fsz").mkdir()
    out = subprocess.run([CLI, "block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "20,20,20", "--csv",
                          str(tmp_path / "fsz/big.csv")], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                         preexec_fn=file_size_limit, timeout=60)
    assert out.returncode == 5 and len([line for line in out.stderr.splitlines() if line]) == 1, (out.returncode, out.stderr)
    assert not os.listdir(tmp_path / "fsz")
    out = subprocess.run([CLI, "run", s_ok, "-o", str(tmp_path / "fsz/out")], stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, text=True, preexec_fn=file_size_limit, timeout=60)
    # On a study: exit 5, no folder.
    assert out.returncode == 5 and not os.listdir(tmp_path / "fsz"), (out.returncode, out.stderr)


@pytest.mark.parametrize("args", [
    ["kernels", "--json"], ["lattices", "--json"], ["relax", "wendland_c2", "poisson", "--count", "200", "--steps", "1", "--json"],
    ["particles", "cubic_bspline", "poisson", "--count", "200", "--json"], ["eps", "cubic_bspline", "fcc", "--k", "1.2", "--json"]],
    ids=["kernels", "lattices", "relax", "particles", "eps"])
def test_a_full_disk_on_standard_output(args):
    # Results that cannot reach standard output (a full disk) are an output error, exit 5, in every
    # command: a write that fmt reports by throwing was once taken for a bad input (exit 3).
    with open("/dev/full", "w") as full:
        out = subprocess.run([CLI, *args], stdout=full, stderr=subprocess.PIPE, text=True, timeout=60)
    assert out.returncode == 5 and out.stderr == "sphkern: error: cannot write the results to standard output\n", \
        (out.returncode, out.stderr)

