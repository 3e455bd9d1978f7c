"""Expression kernels (a JSON file with w, and dw or not): a bad expression, key, dimension or
parameter is exit 3 with the file and the JSON pointer; a wrong constant or derivative is named
by check in the file's own terms."""
import math

import pytest
from conftest import expect, fill, write

# Each case writes its kernel file into its own folder.
FILE_CASES = [
    ("x_syntax", {"x_syntax.json": '{"name": "x", "support": 2, "dimensions": [2], "w": "q <= 1 ? (1 - q"}'},
     ["check", "--plugin", "{w}/x_syntax.json"],
     3, "x_syntax.json: /w: not a valid expression"),
    ("x_var", {"x_var.json": '{"name": "x", "support": 2, "dimensions": [2], "w": "1 - q * beta"}'},
     ["eps", "{w}/x_var.json", "triangular", "--k", "1"],
     3, "x_var.json: /w: not a valid expression.*beta"),
    ("x_zero", {"x_zero.json": '{"name": "x", "support": 2, "dimensions": [2], "w": "0"}'},
     ["eps", "{w}/x_zero.json", "triangular", "--k", "1"],
     3, "x_zero.json: /w: the integral of w over 2D space is not a positive finite number"),
    ("x_inf", {"x_inf.json": '{"name": "x", "support": 2, "dimensions": [2], "w": "1 / (1 - q)"}'},
     ["eps", "{w}/x_inf.json", "triangular", "--k", "1"],
     3, "x_inf.json: /w: "),
    ("x_missing", {"x_missing.json": '{"name": "x", "support": 2, "dimensions": [2]}'},
     ["eps", "{w}/x_missing.json", "triangular", "--k", "1"],
     3, 'x_missing.json: /: missing required key "w"'),
    ("x_dim", {"x_dim.json": '{"name": "x", "support": 2, "dimensions": [4], "w": "1"}'},
     ["eps", "{w}/x_dim.json", "triangular", "--k", "1"],
     3, "x_dim.json: /dimensions/0: value 4 is out of range"),
    ("x_param", {"x_param.json": '{"name": "x", "support": 2, "dimensions": [2], "parameters": [{"name": "a", "default": 5, "min": 0, "max": 1}], "w": "1 - a*q"}'},
     ["eps", "{w}/x_param.json", "triangular", "--k", "1"],
     3, "x_param.json: /parameters/0: expected min <= default <= max"),
    ("x_key", {"x_key.json": '{"name": "x", "support": 2, "dimensions": [2], "w": "1", "derivative": "0"}'},
     ["eps", "{w}/x_key.json", "triangular", "--k", "1"],
     3, 'x_key.json: /: unknown key "derivative"'),
    ("x_ok-check", {"x_ok.json": '{"name": "x_ok", "support": 2, "dimensions": [2, 3], "normalise": true, "w": "q < 2 ? (1 - q/2)^4 * (1 + 2*q) : 0"}'},
     ["check", "--plugin", "{w}/x_ok.json"],
     0, "^$"),
    ("x_ok-no-parameter-beta", {"x_ok.json": '{"name": "x_ok", "support": 2, "dimensions": [2, 3], "normalise": true, "w": "q < 2 ? (1 - q/2)^4 * (1 + 2*q) : 0"}'},
     ["design", "{w}/x_ok.json", "triangular", "--param", "beta"],
     3, 'x_ok has no parameter "beta"'),
    ("composite-and-1d", {"x_1d.json": '{"name": "x_1d", "support": 1, "dimensions": [1], "w": "q < 1 ? 1 - q : 0"}'},
     ["eps", "composite+{w}/x_1d.json", "triangular", "--k", "1"],
     3, "share no dimension"),
    ("design-range-reversed", {},
     ["design", "cubic_bspline+wendland_c2", "triangular", "--param", "alpha", "--range", "5", "1"],
     3, r"parameter range \[5, 1\] is not allowed"),
]


@pytest.mark.parametrize("files,args,code,pattern", [c[1:] for c in FILE_CASES], ids=[c[0] for c in FILE_CASES])
def test_expression_kernel(tmp_path, files, args, code, pattern):
    write(tmp_path, files)
    expect(fill(args, tmp_path), code, pattern)


def test_reference_must_be_text(tmp_path):
    (tmp_path / "x_ref.json").write_text('{"name": "x_ref", "support": 2, "dimensions": [3], "reference": 42,\n'
                                         ' "w": "q < 1 ? 1 - 1.5*q^2 + 0.75*q^3 : (q < 2 ? 0.25*(2-q)^3 : 0)"}\n')
    expect(["check", "--plugin", str(tmp_path / "x_ref.json")], 3, r"x_ref.json: /reference: expected a string, got a number")


# An expression kernel is used as written and its constant checked as a plugin's is:
# Wendland C4 in 3D, support 2, with its constant 495/(256 pi), then with the support-1
# constant 495/(32 pi), 8 times too large in w and dw (check fails, exit 1, and its hint gives
# the constant), then the same with "normalise": true.
def c4(folder, name, constant, keys="", dw_factor="14/3"):
    path = folder / f"{name}.json"
    path.write_text('{"name": "' + name + '", "support": 2, "dimensions": [3], ' + keys + "\n"
                    '  "w": "q < 2 ? ' + constant + ' * (1 - q/2)^6 * (1 + 3*q + 35/12*q^2) : 0",\n'
                    '  "dw": "q < 2 ? -' + constant + " * " + dw_factor + ' * q * (1 - q/2)^5 * (1 + 2.5*q) : 0"}')
    return str(path)


def test_c4_with_its_constant(tmp_path):
    expect(["check", "--plugin", c4(tmp_path, "x_c4", "495/(256*_pi)")], 0, r"^$")


def test_c4_with_a_wrong_constant_gets_the_right_one_in_the_hint(tmp_path):
    path = c4(tmp_path, "x_c4_wrong", "495/(32*_pi)")
    out = expect(["check", "--plugin", path], 1, r"^$").stdout
    # The factor and the right constant, 495/(32 pi R^3) for R = 2, to the ten digits check prints.
    factor, inverse, right = (f"{x:.10g}" for x in (2**3, 2**-3, 495 / (32 * math.pi * 2**3)))
    assert (f'hint (3D normalization): the constant of "w" in {path} is off by a factor {factor} in 3D '
            f'(eps_rho inherits it one to one): multiply "w" and "dw" by {inverse} in 3D, so that W(0) = {right}') in out, out


def test_c4_normalised(tmp_path):
    expect(["check", "--plugin", c4(tmp_path, "x_c4_normalise", "495/(32*_pi)", '"normalise": true,')], 0, r"^$")


def test_normalise_must_be_true_or_false(tmp_path):
    path = c4(tmp_path, "x_c4_yes", "495/(256*_pi)", '"normalise": "yes",')
    expect(["check", "--plugin", path], 3, r"^sphkern: error: .*x_c4_yes.json: /normalise: expected true or false, got a string$")
    expect(["eps", path, "fcc", "--k", "1.2"], 3, r"x_c4_yes.json: /normalise: expected true or false, got a string$")


def test_a_wrong_dw_is_named_in_the_files_terms(tmp_path):
    path = c4(tmp_path, "x_c4_dw", "495/(256*_pi)", "", "4")
    out = expect(["check", "--plugin", path], 1, r"^$").stdout
    assert f'hint (3D derivative): "dw" in {path} is not the derivative of "w"' in out, out
    # No C macro in an expression file's hints.
    assert "SPHKERN_" not in out, out
