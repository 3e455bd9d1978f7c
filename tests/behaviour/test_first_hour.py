"""The first hour's typos get the right word (item 3 of the first-hour issue): an unknown command
or option is named with the nearest one, a value that is not a number with the form expected,
the extra words in the order typed, a misspelt source with the sources there are."""
import pytest
from conftest import expect

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
