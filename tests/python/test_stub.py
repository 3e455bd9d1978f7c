"""sphkern.pyi, the stub that editors and type checkers read beside the module, against the
module itself: every public name of the module is in the stub and every name of the stub is
in the module; each function's parameters (names, order, which are keyword-only) are those of
the signature pybind11 writes on its docstring's first line; each exception class has the
module's bases. The build puts the stub beside the module (build/python), and the install
beside the installed one."""
import ast
import inspect
import pathlib

import pytest

import sphkern

STUB = pathlib.Path(sphkern.__file__).with_name("sphkern.pyi")
TREE = ast.parse(STUB.read_text())


def stub_names():
    names = {}
    for node in TREE.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names[node.name] = node
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names[node.target.id] = node
    return names


STUBBED = stub_names()
PUBLIC = sorted(name for name in vars(sphkern) if not name.startswith("_"))


def parameters(definition):
    """(name, keyword-only) of a def's parameters, self apart."""
    args = definition.args
    return [(a.arg, False) for a in args.args if a.arg != "self"] + [(a.arg, True) for a in args.kwonlyargs]


def module_parameters(function):
    first = function.__doc__.splitlines()[0]
    return parameters(ast.parse(f"def {first}: pass").body[0])


def test_the_stub_is_beside_the_module():
    assert STUB.is_file(), STUB


def test_every_public_name_is_in_the_stub_and_nothing_else():
    assert sorted(n for n in STUBBED if not n.startswith("_")) == PUBLIC
    assert "__version__" in STUBBED


@pytest.mark.parametrize("name", [n for n in PUBLIC if inspect.isroutine(getattr(sphkern, n))])
def test_each_function_has_the_module_s_parameters(name):
    node = STUBBED[name]
    assert isinstance(node, ast.FunctionDef) and node.returns is not None
    assert parameters(node) == module_parameters(getattr(sphkern, name))
    assert all(a.annotation is not None for a in node.args.args + node.args.kwonlyargs)


def test_the_kernel_class_has_the_module_s_members():
    node = STUBBED["Kernel"]
    members = {m.name: m for m in node.body if isinstance(m, ast.FunctionDef)}
    public = sorted(n for n in vars(sphkern.Kernel) if not n.startswith("_"))
    assert sorted(members) == public
    for name in ("w", "dw"):
        assert parameters(members[name]) == module_parameters(getattr(sphkern.Kernel, name))


@pytest.mark.parametrize("name", [n for n in PUBLIC if inspect.isclass(getattr(sphkern, n))
                                  and issubclass(getattr(sphkern, n), BaseException)])
def test_each_exception_has_the_module_s_bases(name):
    bases = [ast.unparse(b) for b in STUBBED[name].bases]
    assert bases == [b.__name__ for b in getattr(sphkern, name).__bases__]
