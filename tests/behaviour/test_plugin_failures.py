"""Plugins that fail: at load (a wrong ABI, a crash, an endless loop, no entry point, not a
library, an undefined symbol, a duplicate name), or later, at a q, k or batch size the probe did
not try (exit 4 naming the file, the kernel and the function); non-finite values."""
import json
import os

import pytest
from conftest import BROKEN, expect, fill, run, table

# Plugins named on the command line.
CASES = [
    ("wrong-abi", ["kernels", "--plugin", "{broken}/wrong_abi.so"],
     4, "wrong_abi.so: invalid kernel descriptor: ABI version 999"),
    ("crash-in-probe", ["kernels", "--plugin", "{broken}/crash_in_w.so"],
     4, "crash_in_w.so: plugin crashed with signal 11"),
    ("endless-loop-in-probe", ["eps", "{broken}/endless_loop.so", "triangular", "--k", "1"],
     4, "endless_loop.so: plugin did not finish within 2 s"),
    ("no-entry-point", ["check", "--plugin", "{broken}/no_entry.so"],
     4, "no_entry.so: not a sphkern kernel plugin"),
    ("not-a-library", ["check", "--plugin", "{broken}/not-a-plugin.so"],
     4, "not-a-plugin.so: not a loadable shared library"),
    ("undefined-symbol", ["check", "--plugin", "{broken}/undefined_symbol.so"],
     4, "undefined_symbol.so: not a loadable shared library: undefined symbol: sphkern_test_function_nobody_defines$"),
    ("duplicate-name", ["kernels", "--plugin", "{broken}/duplicate_name.so"],
     4, 'two plugins are named "cubic_bspline"'),
    ("check-unnormalised", ["check", "--plugin", "{broken}/unnormalised.so"], 1, "^$"),
    ("check-cubic_bspline", ["check", "cubic_bspline"], 0, "^$"),
    ("check-super_gaussian-strict", ["check", "super_gaussian", "--strict"], 1, "^$"),
    ("check-super_gaussian", ["check", "super_gaussian"], 0, "^$"),
    # Numbers: nothing non-finite, nothing from a kernel outside its valid parameters.
    ("eps-nan-band",
     ["eps", "nan_band", "fcc", "--k", "1.4184397163120568", "--plugin", "{broken}/nan_band.so"],
     4, "kernel nan_band .*: W is not finite at q = 0.70"),
    ("roots-nan-band",
     ["roots", "nan_band", "fcc", "--kmin", "1.40", "--kmax", "1.45", "--plugin", "{broken}/nan_band.so"],
     4, "kernel nan_band .*: W is not finite at q = 0.70"),
    # On a particle set the q that is at fault is among a particle's neighbours: named, exit 4 (it
    # was blamed on h, exit 3, when a sample of q missed the band).
    ("particles-nan-band",
     ["particles", "nan_band", "poisson", "--count", "3000", "--nh", "60", "--plugin", "{broken}/nan_band.so"],
     4, "kernel nan_band .*: W is not finite at q = 0.70"),
    ("eps-sign-flip-default", ["eps", "sign_flip", "fcc", "--k", "1.2", "--plugin", "{broken}/sign_flip.so"],
     0, "^$"),
    ("eps-sign-flip-p3",
     ["eps", "sign_flip", "fcc", "--k", "1.2", "--set", "p=3", "--plugin", "{broken}/sign_flip.so"],
     4, r"kernel sign_flip\(p=3\) .*: its 3D normalisation is -1 at k = 1.2, expected a finite positive integral"),
    ("block-sign-flip-p3",
     ["block", "sign_flip", "fcc", "--k", "1.2", "--size", "4,4,4", "--set", "p=3", "--plugin", "{broken}/sign_flip.so"],
     4, "its 3D normalisation is -1"),
    ("eps-k-1e-300", ["eps", "cubic_bspline", "fcc", "--k", "1e-300"],
     3, "k = 1e-300 is outside what this kernel and lattice can be evaluated at"),
    ("eps-k-1e-300-json", ["eps", "cubic_bspline", "fcc", "--k", "1e-300", "--json"], 3, "k = 1e-300 is outside"),
    # Plugins that pass their probe and fail later, at a q, k or batch size the probe did not try:
    # exit 4 and one line naming the file, the kernel and the function; nothing left behind.
    ("crash-in-band", ["spectrum", "{broken}/crash_in_band.so", "--dim", "3"],
     4, r"crash_in_band.so: plugin kernel crash_in_band crashed with signal 11 \(SIGSEGV\) in W; nothing was written"),
    ("crash-in-fused",
     ["particles", "{broken}/crash_in_fused.so", "poisson", "--dim", "3", "--count", "2000", "--nh", "30"],
     4, r"crash_in_fused.so: plugin kernel crash_in_fused crashed with signal 11 \(SIGSEGV\) in the fused W and dW; nothing was written"),
    ("abort-above-k", ["eps", "{broken}/abort_above_k.so", "fcc", "--k", "1.4"],
     4, r"abort_above_k.so: plugin kernel abort_above_k crashed with signal 6 \(SIGABRT\) in .*W; nothing was written"),
    ("exit-in-w", ["eps", "{broken}/exit_in_w.so", "fcc", "--k", "1.4"],
     4, r"exit_in_w.so: plugin kernel exit_in_w called exit\(\) or pthread_exit\(\) in .*W; nothing was written"),
    ("quick-exit-in-w", ["eps", "{broken}/quick_exit_in_w.so", "fcc", "--k", "1.4"],
     4, r"quick_exit_in_w.so: plugin kernel quick_exit_in_w called exit\(\) or pthread_exit\(\) in .*W; nothing was written"),
    ("loops-above-k", ["eps", "{broken}/loops_above_k.so", "fcc", "--k", "1.4"],
     4, r"loops_above_k.so: plugin kernel loops_above_k did not return within 2 s \(endless loop"),
    ("overflows-stack", ["eps", "{broken}/overflows_stack.so", "fcc", "--k", "1.4"],
     4, r"overflows_stack.so: plugin kernel overflows_stack crashed with signal 11 \(SIGSEGV\) in W"),
]


@table(CASES)
def test_plugin(args, code, pattern):
    expect(fill(args), code, pattern)


def eps_gradp(gravity):
    out = run(["eps", "cubic_bspline", "fcc", "--k", "1.2", "--gravity", gravity, "--json"])
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)["eps_gradp"]


def test_gravity_length_does_not_matter():
    unit = eps_gradp("1,1,0")
    assert eps_gradp("1e200,1e200,0") == unit
    assert eps_gradp("1e-300,1e-300,0") == unit


@pytest.mark.parametrize("plugin", ["exit_in_w", "quick_exit_in_w", "abort_above_k", "loops_above_k"])
def test_failing_plugin_in_a_study_leaves_no_folder(tmp_path, plugin):
    (tmp_path / f"s_{plugin}.json").write_text(
        '{"name": "s", "kernels": ["' + os.path.join(BROKEN, plugin + ".so") + '"], "lattices": ["fcc"], '
        '"k": {"min": 0.75, "max": 1.5, "samples": 301}, "plots": false}')
    expect(["run", str(tmp_path / f"s_{plugin}.json"), "-o", str(tmp_path / f"made_{plugin}/a/b/out")], 4,
           rf"{plugin}.so: plugin kernel {plugin} ")
    # No staging folder, no folder the run made.
    assert not (tmp_path / f"made_{plugin}").exists()

