"""Every public function and method of the module has a numpydoc docstring: a summary line,
Parameters (where it takes any), Returns and Examples; the Parameters describe exactly the
parameters of the signature (the first line of __doc__, which pybind11 writes from the
binding), and the signature types them all, none as a bare `object`. The Examples run as
doctests, so that they cannot rot."""
import ast
import doctest
import inspect
import re
import subprocess
import sys

import pytest

import sphkern


def public_callables():
    """(qualified name, docstring) of every public function and method."""
    found = []
    for name, value in sorted(vars(sphkern).items()):
        if name.startswith("_"):
            continue
        if inspect.isclass(value):
            for attribute, member in sorted(vars(value).items()):
                if not attribute.startswith("_") and callable(member):
                    found.append((f"{name}.{attribute}", member.__doc__ or ""))
        elif callable(value):
            found.append((name, value.__doc__ or ""))
    return found


CALLABLES = public_callables()


def signature(name, doc):
    """The parsed first line of the docstring: a def statement without a body."""
    first = doc.splitlines()[0] if doc else ""
    short = name.split(".")[-1]
    assert first.startswith(short + "("), f"{name}: the docstring does not start with its signature: {first!r}"
    return ast.parse(f"def {first}: pass").body[0]


def sections(doc):
    """numpydoc sections: title -> body lines (a title is a line underlined with dashes)."""
    lines = doc.splitlines()
    found, title = {}, None
    for i, line in enumerate(lines):
        if i + 1 < len(lines) and line.strip() and re.fullmatch(r"-{3,}", lines[i + 1].strip()):
            title = line.strip()
            found[title] = []
        elif title and not re.fullmatch(r"-{3,}", line.strip()):
            found[title].append(line)
    return found


def described(lines):
    """The names a Parameters section describes: "name : type" or "a, b : type" at its margin."""
    names = []
    for line in lines:
        match = re.match(r"^(\w+(?:, \w+)*) :", line)
        if match:
            names += match.group(1).split(", ")
    return names


def test_the_module_has_functions_and_a_class():
    names = [name for name, _ in CALLABLES]
    assert "particles" in names and "roots" in names and "Kernel.w" in names and len(names) >= 14


@pytest.mark.parametrize("name, doc", CALLABLES, ids=[name for name, _ in CALLABLES])
def test_every_callable_has_a_numpydoc_docstring(name, doc):
    definition = signature(name, doc)
    arguments = [a for a in definition.args.args + definition.args.kwonlyargs if a.arg != "self"]
    for argument in arguments:
        assert argument.annotation is not None, f"{name}: {argument.arg} has no type"
        assert ast.unparse(argument.annotation) != "object", f"{name}: {argument.arg} is typed object"
    assert definition.returns is not None and ast.unparse(definition.returns) != "object", f"{name}: return type"
    body = doc.split("\n", 1)[1].strip()
    assert body and not body.startswith(("Parameters", "Returns")), f"{name}: no summary line"
    found = sections(doc)
    needed = ["Returns", "Examples"] + (["Parameters"] if arguments else [])
    for title in needed:
        assert title in found and any(line.strip() for line in found[title]), f"{name}: no {title} section"
    assert sorted(described(found.get("Parameters", []))) == sorted(a.arg for a in arguments), (
        f"{name}: the Parameters section does not describe the signature's parameters")


def run_examples(name, doc):
    """Failures and output of the Examples run as doctests, in a fresh interpreter (as a user
    runs them, and so that a kernel an example loads stays out of the other tests' module)."""
    examples = "\n".join(sections(doc)["Examples"])
    assert doctest.DocTestParser().get_examples(examples), f"{name}: no example to run"
    script = ("import doctest, sys, sphkern\n"
              "test = doctest.DocTestParser().get_doctest(sys.stdin.read(), {'sphkern': sphkern}, sys.argv[1], None, 0)\n"
              "runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)\n"
              "sys.exit(runner.run(test).failed)\n")
    done = subprocess.run([sys.executable, "-c", script, name], input=examples, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.parametrize("name, doc", CALLABLES, ids=[name for name, _ in CALLABLES])
def test_the_examples_run(name, doc):
    run_examples(name, doc)


def test_a_wrong_docstring_is_caught():
    """The checks above fail on a parameter left undescribed and on an example that is wrong."""
    name, doc = next((n, d) for n, d in CALLABLES if n == "eps")
    trimmed = re.sub(r"\nsite : int.*?\n(?=params)", "\n", doc, flags=re.S)
    assert "site :" not in trimmed
    with pytest.raises(AssertionError, match="does not describe"):
        test_every_callable_has_a_numpydoc_docstring(name, trimmed)
    with pytest.raises(AssertionError, match="no Examples section"):
        test_every_callable_has_a_numpydoc_docstring(name, doc.split("Examples\n")[0])
    with pytest.raises(AssertionError, match="Expected"):
        test_the_examples_run(name, doc.replace("((2,), 'i')", "((3,), 'i')"))
