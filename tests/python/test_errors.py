"""The module's exceptions by kind: every error is a sphkern.Error, each kind also the built-in
exception Python code catches for it (ValueError, LookupError, FileNotFoundError, RuntimeError,
OSError), with the command line's exit code for the same error and one line that names the
argument as the module spells it. Run by ctest with PYTHONPATH=<build>/python and SPHKERN_CLI set."""
import os
import subprocess

import pytest

import sphkern

CLI = os.environ["SPHKERN_CLI"]
BROKEN = os.environ["SPHKERN_BROKEN_PLUGINS"]


def cli_exit(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True).returncode


def test_the_classes_and_their_bases():
    assert issubclass(sphkern.Error, Exception)
    for name, bases in {"BadValue": (ValueError,), "UnknownName": (sphkern.BadValue, LookupError, ValueError),
                        "FileError": (sphkern.BadValue, FileNotFoundError, OSError, ValueError),
                        "PluginError": (RuntimeError,), "OutputError": (OSError,), "CheckFailed": ()}.items():
        cls = getattr(sphkern, name)
        assert issubclass(cls, sphkern.Error) and cls.__module__ == "sphkern" and cls.__doc__
        for base in bases:
            assert issubclass(cls, base), (name, base)


@pytest.mark.parametrize("call, cli", [
    (lambda: sphkern.eps("cubic_splin", "fcc", 1.0), ["eps", "cubic_splin", "fcc", "--k", "1"]),
    (lambda: sphkern.eps("cubic_bspline", "fcx", 1.0), ["eps", "cubic_bspline", "fcx", "--k", "1"]),
    (lambda: sphkern.run("desing", "/tmp/never"), ["run", "desing", "-o", "/tmp/never"]),
    (lambda: sphkern.kernel("cubic_bspline", {"nope": 1}), None),
    (lambda: sphkern.pairing("cubic_bspline", "sc", code="swiftt", value=1.2), None),
])
def test_an_unknown_name_is_a_lookup_error(call, cli):
    with pytest.raises(sphkern.UnknownName) as caught:
        call()
    assert isinstance(caught.value, LookupError) and isinstance(caught.value, ValueError)
    assert caught.value.exit_code == 3
    if cli:
        assert cli_exit(*cli) == caught.value.exit_code
    assert "did you mean" in str(caught.value) or "is unknown" in str(caught.value) or "no parameter" in str(caught.value)


@pytest.mark.parametrize("call, cli", [
    (lambda: sphkern.relax("cubic_bspline", "poisson", count=100, dim=2, method="jiggle"),
     ["relax", "cubic_bspline", "poisson", "--count", "100", "--dim", "2", "--method", "jiggle"]),
    (lambda: sphkern.relax("cubic_bspline", "fcc", size=[3, 3, 3], cell="cubic"),
     ["relax", "cubic_bspline", "fcc", "--size", "3,3,3", "--cell", "cubic"]),
    (lambda: sphkern.stability("cubic_bspline", "fcc", k=1.2, h_model="variable"),
     ["stability", "cubic_bspline", "fcc", "--k", "1.2", "--h-model", "variable"]),
    (lambda: sphkern.eps("cubic_bspline", "fcc", 1.2, axis="q"), ["eps", "cubic_bspline", "fcc", "--k", "1.2", "--axis", "q"]),
    (lambda: sphkern.surface("cubic_bspline", "fcc", 1.2, form="gather"),
     ["surface", "cubic_bspline", "fcc", "--k", "1.2", "--form", "gather"]),
    (lambda: sphkern.particles("cubic_bspline", [[0.1, 0.2], [0.6, 0.7]], box=[1, 1], h_over_l=1.2, volume="cells"),
     None),
])
def test_a_word_outside_a_settings_choices_is_an_unknown_name(call, cli):
    """A word a setting does not know (a method, a cell, an h model, an axis, a form, a volume
    model) is an UnknownName, as an unknown kernel is: a LookupError, and still a ValueError."""
    with pytest.raises(sphkern.UnknownName, match="is unknown|is not a") as caught:
        call()
    assert isinstance(caught.value, LookupError) and isinstance(caught.value, ValueError)
    if cli:
        assert cli_exit(*cli) in (2, 3)


@pytest.mark.parametrize("call", [
    lambda: sphkern.load_lattice("/nonexistent/lattice.json"),
    lambda: sphkern.eps("cubic_bspline", "/nonexistent/lattice.json", 1.0),
    lambda: sphkern.run("/nonexistent/study.json", "/tmp/never"),
    lambda: sphkern.relax("cubic_bspline", "/nonexistent/set.csv", k=1.0),
    lambda: sphkern.relax("cubic_bspline", "/nonexistent/set.hdf5", k=1.0),
    lambda: sphkern.spectrum("/nonexistent/kernel.so", 3),
])
def test_a_missing_file_is_a_file_not_found_error(call):
    with pytest.raises(sphkern.FileError, match="no such") as caught:
        call()
    assert isinstance(caught.value, FileNotFoundError) and "/nonexistent/" in str(caught.value)


def test_a_broken_plugin_is_a_runtime_error():
    with pytest.raises(sphkern.PluginError, match="plugin crashed with signal 11") as caught:
        sphkern.kernel(os.path.join(BROKEN, "crash_in_w.so")).w(0.7, 3)
    assert isinstance(caught.value, RuntimeError) and caught.value.exit_code == 4


def test_an_output_that_cannot_be_written_is_an_os_error(tmp_path):
    with pytest.raises(sphkern.OutputError, match="csv") as caught:
        sphkern.block("cubic_bspline", "sc", 1.2, [3, 3, 3], csv=str(tmp_path))
    assert isinstance(caught.value, OSError)
    assert caught.value.exit_code == cli_exit("block", "cubic_bspline", "sc", "--k", "1.2", "--size", "3,3,3",
                                              "--csv", str(tmp_path)) == 5


# Each message names the argument as the module spells it, what is wrong and what was expected.
@pytest.mark.parametrize("call, words", [
    (lambda: sphkern.spectrum("cubic_bspline", 4), ["dim = 4", "expected"]),
    (lambda: sphkern.spectrum("cubic_bspline", 3, points=0), ["points = 0", "expected"]),
    (lambda: sphkern.spectrum("cubic_bspline", 3, max=0.01), ["max = 0.01", "expected"]),
    (lambda: sphkern.block("cubic_bspline", "sc", 1.2, [3, 3]), ["size", "expected"]),
    (lambda: sphkern.block("cubic_bspline", "sc", 1.2, ["a", 3, 3]), ["size: expected whole numbers"]),
    (lambda: sphkern.block("cubic_bspline", "sc", -1.0, [3, 3, 3]), ["k = -1", "expected"]),
    (lambda: sphkern.pairing("cubic_bspline", "sc"), ["give k", "kmin and kmax"]),
    (lambda: sphkern.pairing("cubic_bspline", "sc", kmin=1.0), ["kmin and kmax"]),
    (lambda: sphkern.pairing("cubic_bspline", "sc", 1.0, noise=0.5), ["noise = 0.5", "expected"]),
    (lambda: sphkern.check(), ["plugin=FILE", "all=True"]),
    (lambda: sphkern.check("cubic_bspline", timeout=0), ["timeout = 0", "expected"]),
    (lambda: sphkern.relax("cubic_bspline", "poisson", count=100, method="push"), ["method", "push", "pressure or shift"]),
    (lambda: sphkern.relax("cubic_bspline", "poisson", count=100, dt=1.0), ["dt = 1", "expected"]),
    (lambda: sphkern.relax("cubic_bspline", "sc", k=1.0), ["needs size"]),
    (lambda: sphkern.relax("cubic_bspline", "poisson", count=100, size=[2, 2, 2]), ["size cuts a lattice"]),
    (lambda: sphkern.relax("cubic_bspline", "poisson", count=100, tile=[2, 2, 2]), ["tile", "expected output"]),
    (lambda: sphkern.relax("cubic_bspline", "poisson", count=100, value=1.2), ["value", "expected code"]),
    (lambda: sphkern.relax("cubic_bspline", "poisson", count=100, rho0=2.0),
     ["rho0 sets what output writes; expected output too"]),
    (lambda: sphkern.relax("cubic_bspline", "poisson", count=100, output="x.csv", u=2.0),
     ["u: x.csv holds x, y[, z], h and m, no internal energy; expected an .h5 or .hdf5 output"]),
    (lambda: sphkern.relax("cubic_bspline", "poisson", count=100, code="swift", value=1.2, nh=50.0),
     ["code swift sets h with value; expected no h_over_l, nh or k beside it"]),
    (lambda: sphkern.run("design", "/tmp/never", format="gif"), ["format gif", "expected svg, png or pdf"]),
    (lambda: sphkern.run("design", reproduce="x.json"), ["reproduce", "expected no study"]),
])
def test_a_bad_value_names_the_keyword(call, words):
    with pytest.raises(sphkern.BadValue) as caught:
        call()
    message = str(caught.value)
    assert "\n" not in message and "--" not in message, message
    for word in words:
        assert word in message, (word, message)
