"""Plugins that fail at load (a wrong ABI, a crash, an endless loop, no entry point, not a
library, an undefined symbol, a duplicate name) or give non-finite values: exit 4 naming the
file; check's verdict on a plugin; numbers never non-finite, whatever k or gravity. Plugins that
fail later: test_plugin_late_failures.py."""
import json

from conftest import expect, fill, run, table

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

