"""Each command's settings are declared once, in its table (core/requests/settings); the
command line's options and Python's keywords are made from it. Held here against what each
front end shows: every option of `sphkern COMMAND --help`, in its order, with its help and the
default it prints; every keyword of the function's signature with its default; and the
default each docstring's Parameters entry states. A setting added, renamed or given another
default in one place only fails here. Run by ctest with SPHKERN_CLI set."""
import ast
import math
import os
import re
import subprocess

import pytest

import sphkern

CLI = os.environ["SPHKERN_CLI"]


def help_text(*words):
    return subprocess.run([CLI, *words, "--help"], check=True, capture_output=True, text=True).stdout


COMMANDS = [line.split()[0] for line in re.search(r"^Subcommands:\n((?:  .*\n?)+)", help_text(), re.M)
            .group(1).splitlines() if re.match(r"^  \S", line)]


def help_entries(command):
    """(name, default shown or None, help) of each positional and option but --help, in order."""
    text = help_text(command)
    found = []
    for title in ("Positionals", "Options"):
        match = re.search(rf"^{title}:\n((?:[ \t].*\n?|\n(?=[ \t]))+)", text, re.M)
        lines = match.group(1).splitlines() if match else []
        for i, line in enumerate(lines):
            if not re.match(r"^  \S", line):
                continue
            head, _, rest = line[2:].partition("  ")
            words = head.split()
            if not rest.strip() and i + 1 < len(lines) and re.match(r"^ {5,}\S", lines[i + 1]):
                rest = lines[i + 1]  # CLI11 puts the help on the next line after a long head
            name = words[0].split(",")[-1]
            if name == "--help":
                continue
            default = re.search(r"=(\S+)$", words[1]).group(1) if len(words) > 1 and "=" in words[1] else None
            found.append((words[0] if name.startswith("-") else name, default, rest.strip()))
    return found


def signature(function):
    """keyword -> default as text (None without one) from the docstring's first line."""
    definition = ast.parse(f"def {function.__doc__.splitlines()[0]}: pass").body[0]
    args = definition.args.args + definition.args.kwonlyargs
    defaults = [None] * (len(definition.args.args) - len(definition.args.defaults)) + \
        definition.args.defaults + definition.args.kw_defaults
    return {a.arg: (ast.literal_eval(d) if d is not None else "required") for a, d in zip(args, defaults)}


def same_value(shown, declared):
    if isinstance(declared, bool) or declared is None or isinstance(declared, str):
        return shown == declared
    return math.isclose(float(shown), declared, rel_tol=1e-5)  # --help rounds 5/3 to 1.66667


@pytest.mark.parametrize("command", COMMANDS)
def test_the_command_line_shows_the_table(command):
    declared = [s for s in sphkern.settings(command) if s["option"] and not s["hidden"]]
    shown = help_entries(command)
    assert [name for name, _, _ in shown] == [s["option"] for s in declared]
    for (name, default, text), s in zip(shown, declared):
        assert text == s["help"], name
        if s["type"] != "flag" and default is not None:
            assert same_value(default, s["default"]), f"{command} {name}: --help shows {default}, declared {s['default']}"


@pytest.mark.parametrize("command", COMMANDS)
def test_the_function_takes_the_table(command):
    declared = {s["keyword"]: s for s in sphkern.settings(command) if s["keyword"]}
    taken = signature(getattr(sphkern, command))
    assert sorted(taken) == sorted(declared)
    for keyword, default in taken.items():
        s = declared[keyword]
        # A setting without a default may be required in Python where the command line takes
        # another instead (eps's k: --code there, code_k here).
        expected = "required" if s["required"] or (default == "required" and s["default"] is None) else s["default"]
        assert default == expected, f"sphkern.{command}({keyword}=...): {default!r}, declared {expected!r}"


def docstring_defaults(function):
    """name -> the default its Parameters entry states; "kmin, kmax : float, default 0.75 and
    1.25" gives each of the two its own."""
    found = {}
    for line in function.__doc__.splitlines():
        match = re.fullmatch(r"(\w+(?:, \w+)*) : .*?, default (.+)", line)
        if match:
            names, values = match.group(1).split(", "), match.group(2).strip().split(" and ")
            for name, value in zip(names, values if len(values) == len(names) else values * len(names)):
                found[name] = value
    return found


def stated(text):
    """A docstring's default as a value: 100, "voronoi", True, 5/3."""
    fraction = re.fullmatch(r"(\d+)/(\d+)", text)
    if fraction:
        return int(fraction.group(1)) / int(fraction.group(2))
    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return text


@pytest.mark.parametrize("command", COMMANDS)
def test_the_docstring_states_the_declared_defaults(command):
    declared = {s["keyword"]: s["default"] for s in sphkern.settings(command) if s["keyword"]}
    wrong = {}
    for name, text in docstring_defaults(getattr(sphkern, command)).items():
        value = stated(text)
        if name in declared and not (same_value(value, declared[name]) if isinstance(value, (int, float)) and
                                     not isinstance(value, bool) else value == declared[name]):
            wrong[name] = (text, declared[name])
    assert not wrong, f"sphkern.{command}: docstring defaults that are not the declared ones: {wrong}"


GUIDE = os.path.join(os.path.dirname(__file__), "..", "..", "share", "docs", "guide-python.md")


def guide_defaults():
    """(command, keyword, default as written) of each `command(..., keyword=value, ...)` in the guide."""
    text = open(GUIDE, encoding="utf-8").read()
    found = []
    for command, arguments in re.findall(r"`(\w+)\(([^`]*)\)`", text):
        if command in COMMANDS:
            found += [(command, k, v) for k, v in re.findall(r"(\w+)=([^,)]+)", arguments)]
    return found


def test_the_python_guide_gives_the_declared_defaults():
    cases = guide_defaults()
    assert len(cases) > 50
    wrong = []
    for command, keyword, text in cases:
        declared = {s["keyword"]: s["default"] for s in sphkern.settings(command)}
        value = stated(text.strip())
        ok = same_value(value, declared[keyword]) if isinstance(value, (int, float)) and not isinstance(
            value, bool) else value == declared[keyword]
        if not ok:
            wrong.append((command, keyword, text, declared[keyword]))
    assert not wrong


SCHEMA = os.path.join(os.path.dirname(__file__), "..", "..", "share", "schemas", "study.schema.json")


# The study sections that are front ends of a command: where the section sits in a study, a
# study around it, and the schema's entry for it.
STUDY_SECTIONS = {
    "stability": ("/stability", lambda section: {"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"],
                                                 "plots": False, "stability": section},
                  lambda schema: schema["properties"]["stability"]),
    "relax": ("/particles/sources/0/relax",
              lambda section: {"name": "s", "kernels": ["wendland_c2"], "lattices": ["fcc"], "plots": False,
                               "particles": {"sources": [{"poisson": 3, "count": 500,
                                                          "relax": {"kernel": "wendland_c2", **section}}],
                                             "nh": {"min": 30, "max": 60, "steps": 1}}},
              lambda schema: schema["$defs"]["particle_relax"]),
}


def study_rows():
    """(command, row) of every setting a study section takes, from the tables."""
    rows = [(c, s) for c in COMMANDS for s in sphkern.settings(c) if s["study"]]
    assert {c for c, _ in rows} == set(STUDY_SECTIONS), "a section took a command's rows: name it in STUDY_SECTIONS"
    return rows


def schema_entry(section_schema, pointer):
    entry = section_schema
    for token in pointer.strip("/").split("/"):
        entry = entry["properties"][token]
    return entry


def test_the_study_schema_gives_each_study_key_the_declared_bounds():
    """A study section is a front end of its command: its keys are the rows' study keys (path_points
    is stability's --path), and the schema that editors check a study with takes the rows' bounds."""
    import json
    schema = json.load(open(SCHEMA, encoding="utf-8"))
    for command, row in study_rows():
        entry = schema_entry(STUDY_SECTIONS[command][2](schema), row["study"])
        bounds = row["bounds"]
        if row["type"] == "integer":
            assert entry["type"] == "integer", (command, row["key"])
        if not bounds:
            continue
        low = "minimum" if bounds["low"] == "closed" else "exclusiveMinimum"
        assert (entry.get(low), entry.get("maximum")) == (bounds["min"], bounds["max"]), (command, row["key"], entry)


def test_the_study_format_names_each_study_key():
    text = open(os.path.join(os.path.dirname(SCHEMA), "..", "docs", "study-format.md"), encoding="utf-8").read()
    for command, row in study_rows():
        assert f'"{row["study"].split("/")[-1]}"' in text, (command, row["study"])


def nested(pointer, value):
    for token in reversed(pointer.strip("/").split("/")):
        value = {token: value}
    return value


@pytest.mark.parametrize("command,key", [(c, s["key"]) for c, s in study_rows() if s["bounds"]])
def test_a_study_key_out_of_its_rows_bounds_is_refused_at_its_pointer(tmp_path, command, key):
    """Each bounded study key, just past its row's largest value: exit 3, named by its JSON Pointer."""
    import json
    row = next(s for s in sphkern.settings(command) if s["key"] == key)
    too_large = row["bounds"]["max"] + 1
    if row["type"] == "integer":
        too_large = int(too_large)
    at, study_of, _ = STUDY_SECTIONS[command]
    study = tmp_path / "s.json"
    study.write_text(json.dumps(study_of(nested(row["study"], too_large))))
    done = subprocess.run([CLI, "run", str(study), "-o", str(tmp_path / "out")], capture_output=True, text=True)
    assert done.returncode == 3, done.stderr
    shown = str(too_large) if isinstance(too_large, int) else f"{too_large:g}"
    assert f"s.json: {at}{row['study']} = {shown}" in done.stderr, done.stderr
    assert not (tmp_path / "out").exists()


def test_a_table_names_each_setting_once_and_every_command_has_one():
    for command in COMMANDS:
        keys = [s["key"] for s in sphkern.settings(command)]
        assert len(keys) == len(set(keys)), command
    with pytest.raises(sphkern.UnknownName, match=r'unknown command "root" \(did you mean "roots"\?\)'):
        sphkern.settings("root")
    with pytest.raises(TypeError):
        sphkern.settings(3)


def test_an_old_name_is_hidden_and_still_read():
    """particles --eta-range: declared as an old name, out of --help, refused naming the new one."""
    old = [s for s in sphkern.settings("particles") if s["hidden"]]
    assert [s["option"] for s in old] == ["--eta-range"]
    run = subprocess.run([CLI, "particles", "wendland_c2", "poisson", "--count", "100", "--eta-range", "1", "2"],
                         capture_output=True, text=True)
    assert run.returncode == 2 and "--h-over-l-range" in run.stderr


# The least each command needs to reach its checks: positionals, then options (as keywords
# too); a setting read only beside another gets that one (particles' steps: a sweep's).
MINIMAL = {
    "relax": (["wendland_c2", "poisson"], {"count": 100}),
    "pairing": (["wendland_c2", "square"], {"kmin": 1.2, "kmax": 1.3}),
    "spectrum": (["wendland_c2"], {"dim": 3}),
    "surface": (["wendland_c2", "square"], {"k": 1.2}),
    "stability": (["wendland_c2", "square"], {"kmin": 1.0, "kmax": 1.5}),
    "roots": (["wendland_c2", "square"], {"stability": True}),
    "design": (["wendland_c2_shape", "fcc"], {"param": "beta"}),
    "assess": (["cubic_bspline", "square"], {"k": 1.2}),
    "particles": (["wendland_c2", "poisson"], {"count": 100, "dim": 2, "h_over_l": 1.2, "box": "1,1"}),
    "block": (["wendland_c2", "square"], {"k": 1.2, "size": "4,4"}),
}
# Python's spelling of the command line's comma-separated values.
PYTHON_VALUES = {"box": [1, 1], "size": [4, 4]}
# Python's particles takes positions where the command line makes a Poisson set.
PYTHON_POSITIONALS = {"particles": ["wendland_c2", [[0.1, 0.2], [0.6, 0.7]]]}
BESIDE = {("particles", "steps"): {"h_over_l": None, "h_over_l_range": [1.1, 1.3]},
          ("particles", "nh"): {"h_over_l": None},("stability", "path"): {"k": 1.2, "kmin": None, "kmax": None},
          ("stability", "grid"): {"k": 1.2, "kmin": None, "kmax": None}}


def outside(bounds):
    """A value just below and one just above the declared bounds (an open end: the end itself)."""
    low = bounds["min"] if bounds["low"] == "open" else bounds["min"] - (1 if bounds["count"] else abs(bounds["min"]) * 0.5 + 0.5)
    high = bounds["max"] + 1 if bounds["count"] else bounds["max"] * 1.5 + 1
    return [low, high]


def option_words(settings, given):
    words = []
    for key, value in given.items():
        option = next(s["option"] for s in settings if s["key"] == key)
        words += [option] if value is True else [option, *map(str, value)] if isinstance(value, list) else [
            option, str(value)]
    return words


BOUNDED = [(command, s) for command in MINIMAL for s in sphkern.settings(command) if s["bounds"]]


@pytest.mark.parametrize("command,setting", BOUNDED, ids=[f"{c}-{s['key']}" for c, s in BOUNDED])
def test_a_value_outside_the_declared_bounds_is_refused_by_both_front_ends(command, setting):
    """Every bound a table declares is checked, on the command line (exit 2, the option named)
    and in Python (BadValue, the keyword named): the check is made from the table."""
    positionals, base = MINIMAL[command]
    settings = sphkern.settings(command)
    for value in outside(setting["bounds"]):
        value = int(value) if setting["type"] == "integer" else value
        given = {k: v for k, v in {**base, **BESIDE.get((command, setting["key"]), {}), setting["key"]: value}.items()
                 if v is not None}
        if setting["option"]:
            run = subprocess.run([CLI, command, *positionals, *option_words(settings, given)], capture_output=True,
                                 text=True)
            assert run.returncode == 2 and run.stderr.startswith(f"sphkern: error: {setting['option']} "), run.stderr
        if setting["keyword"]:
            with pytest.raises(sphkern.BadValue, match=rf"^{setting['keyword']} = "):
                call_python(command, positionals, given)


def call_python(command, positionals, given):
    """The function as the command line was called: required keywords by position (spectrum's dim)."""
    settings = sphkern.settings(command)
    required = [s["keyword"] for s in settings if s["required"] and not s["positional"]]
    taken = {s["key"]: s["keyword"] for s in settings if s["keyword"]}
    given = {k: PYTHON_VALUES.get(k, v) for k, v in given.items()}
    keywords = {taken[k]: v for k, v in given.items() if k in taken and k not in required}
    return getattr(sphkern, command)(*PYTHON_POSITIONALS.get(command, positionals), *[given[k] for k in required],
                                     **keywords)
