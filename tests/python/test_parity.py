"""The module against the command line, option by option: every command of `sphkern --help` is
a function of the module, and every option and positional of `sphkern COMMAND --help` is a
keyword of that function, named as the option with _ for - (--max-move: max_move), or is
listed below with the reason it has none (a front end's own option, or another name the
module gives it everywhere). The parameters are read from the signature pybind11 writes on
the first line of each docstring. Run by ctest with SPHKERN_CLI set."""
import ast
import os
import re
import subprocess

import pytest

import sphkern

CLI = os.environ["SPHKERN_CLI"]

# Options that no command's function takes as a keyword of that name, and why.
EVERY_COMMAND = {
    "--json": "the command line's output format: every function returns the document",
    "--plugin": "load_plugin(path) loads a plugin for every function, and a plugin file names its kernel",
    "--set": "params, a dict of the kernel's parameters",
}
# The codes' parameters by their own names (code_options.cpp): the module takes code= and value=.
CODE_PARAMETERS = {name: "value, the code's parameter beside code" for name in
                   ("--eta", "--hfact", "--nngb", "--hdx", "--coefh", "--particle-radius")}
# A reason that starts with "not yet" is a gap of the module, counted apart.
NOT_YET = "not yet in the module"
BY_COMMAND = {
    "lattices": {"--radius": "shells(lattice, radius) gives a lattice's shells up to a radius"},
    "eps": {"--ap": "a_p, as every function names it", "--code": "code_k(kernel, lattice, code, value) gives a code's k"},
    "assess": {"--ap": "a_p, as every function names it"},
    "roots": {"--ap": "a_p, as every function names it"},
    "surface": {"--ap": "a_p, as every function names it"},
    "design": {"--ap": "a_p, as every function names it"},
    "block": {"--ap": "a_p, as every function names it"},
    "particles": {**{o: "particles takes positions (and box) as arrays; relax takes a source by name" for o in
                     ("--size", "--cell", "--sigma", "--seed", "--count", "--dim", "--array")},
                  "--csv": "the per-particle arrays are returned", "--vtk": "the per-particle arrays are returned",
                  "--k": "particles takes positions, not a lattice (h = k d needs one)",
                  "--memory-limit": "the positions given are in memory already"},
    "relax": {"--eta": "value with code=\"swift\" (SWIFT's eta); sphkern's own ratio is h_over_l"},
}
# Positionals the function takes under another name.
POSITIONALS = {
    "lattices": {"lattice": "lattices() lists the shipped lattices; load_lattice(path) reads one file"},
    "particles": {"source": "positions, an array of shape (N, 2) or (N, 3), a file or a list of files",
                  "more": "positions takes a file or a list of a run's files"},
}


def help_text(*words):
    return subprocess.run([CLI, *words, "--help"], check=True, capture_output=True, text=True).stdout


def entries(text, title):
    """The first word of each entry under "Title:" in CLI11's help (two-space indented)."""
    match = re.search(rf"^{title}:\n((?:[ \t].*\n?|\n(?=[ \t]))+)", text, re.M)
    return [line.split()[0] for line in match.group(1).splitlines() if re.match(r"^  \S", line)] if match else []


def options_of(text):
    """The long name of every option but --help ("-o,--output" gives --output), and the positionals."""
    options = []
    for entry in entries(text, "Options"):
        names = [n for n in entry.split(",") if n.startswith("--")]
        if names and names[-1] != "--help":
            options.append(names[-1])
    return options, entries(text, "Positionals")


def keywords(function):
    """The parameter names of the signature on the docstring's first line."""
    first = function.__doc__.splitlines()[0]
    definition = ast.parse(f"def {first}: pass").body[0]
    return [a.arg for a in definition.args.args + definition.args.kwonlyargs]


COMMANDS = entries(help_text(), "Subcommands")


def without_keyword(command):
    """(option, reason) for each option of the command that its function takes under no keyword of its name."""
    options, _ = options_of(help_text(command))
    names = set(keywords(getattr(sphkern, command)))
    missing = []
    for option in options:
        if option[2:].replace("-", "_") in names:
            continue
        reason = BY_COMMAND.get(command, {}).get(option) or EVERY_COMMAND.get(option) or CODE_PARAMETERS.get(option)
        missing.append((option, reason))
    return missing


def test_every_command_is_a_function():
    assert len(COMMANDS) == 17
    absent = [c for c in COMMANDS if not callable(getattr(sphkern, c, None))]
    assert not absent, f"commands without a function: {absent}"


@pytest.mark.parametrize("command", COMMANDS)
def test_every_option_has_a_keyword_or_a_reason(command):
    unexplained = [option for option, reason in without_keyword(command) if reason is None]
    assert not unexplained, f"sphkern {command}: options without a keyword and without a reason: {unexplained}"


@pytest.mark.parametrize("command", COMMANDS)
def test_every_positional_is_a_parameter(command):
    _, positionals = options_of(help_text(command))
    names = keywords(getattr(sphkern, command))
    assert [p for p in positionals if p not in names and p not in POSITIONALS.get(command, {})] == []


@pytest.mark.parametrize("command", COMMANDS)
def test_every_reason_is_for_an_option_the_command_has(command):
    options, _ = options_of(help_text(command))
    stale = [o for o in BY_COMMAND.get(command, {}) if o not in options]
    assert not stale, f"sphkern {command}: reasons for options it does not have: {stale}"


def test_the_count_of_options_without_a_keyword():
    """The front end's own options, the other names and the gaps, counted: a new one is a decision, made here."""
    missing = {c: without_keyword(c) for c in COMMANDS}
    total = sum(len(m) for m in missing.values())
    gaps = sorted(f"{c} {o}" for c, m in missing.items() for o, reason in m if reason and reason.startswith(NOT_YET))
    print(f"\noptions without a keyword of their name: {total}, of which not yet in the module: {len(gaps)}: {gaps}")
    assert (total, len(gaps)) == (EXPECTED_WITHOUT_KEYWORD, EXPECTED_GAPS)


# --json (16 commands), --plugin (15), --set (12), the codes' parameters by their own names (34,
# value beside code), --ap (6, a_p), 14 taken otherwise (particles' source options, files the
# arrays replace, eps --code as code_k, lattices --radius as shells, relax --eta); no gaps.
EXPECTED_WITHOUT_KEYWORD = 97
EXPECTED_GAPS = 0
