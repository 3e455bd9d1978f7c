#!/usr/bin/env python3
"""Every command line a document shows runs: each sphkern command in a fenced sh, console,
bash or shell block, in the order of the document, in a scratch folder
that sees the repository's top-level folders (so share/..., lattices/... resolve and outputs
stay there), with the program under test in place of "sphkern". A comment "# exit N" on the
line is the exit status expected (default 0); in a console block the lines after a
"$ sphkern ..." line must each be a line it printed (on stdout or stderr; "..." alone
stands for lines left out, inside a line for any text), so figures shown that way are checked. Each fenced python block runs as a script
against the built module, when there is one. A block whose info string has the word
"excerpt" (```sh excerpt) is only shown: a line needing files that are not there, or one
that runs too long for the suite. Any other command outside an excerpt is an error. A block
with the word file=NAME in its info string (```json file=my-lattice.json) is written to NAME
in the scratch folder first, so that the commands after it can read it. In README.md and
the guides every figure of two or more significant digits in the prose and tables must be
one that a command of the document printed (rounded as written), or typed on one of its
command lines; a table marked <!-- table: python3 share/scripts/NAME.py build/sphkern --> is
the script's, compared by docs_table.py.
Usage: docs_commands.py SOURCE_DIR SPHKERN DOCUMENT [PYTHON_MODULE_DIR]"""
import os
import re
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from markdown_docs import blocks, unchecked_figures  # noqa: E402

SHELLS = {"sh", "console", "bash", "shell"}
# The quick start's two commands: CI runs the second (.ci/run), and the first is the
# default study, which the test default_study runs.
BUILT_ELSEWHERE = {"bash share/bootstrap.sh run", "bash share/bootstrap.sh test"}
LIMIT = 300  # seconds: a guard against a hang, far above any command the docs run

root, sphkern, document = Path(sys.argv[1]).resolve(), str(Path(sys.argv[2]).resolve()), Path(sys.argv[3]).resolve()
module = str(Path(sys.argv[4]).resolve()) if len(sys.argv) > 4 else ""


def commands(info, body):
    """(offset, argument vector, expected status, lines shown as its output) of each command
    line, continuations joined. In a console block only lines that start with "$ " are
    commands; the lines after one are (part of) its output, "..." standing for lines left out."""
    out, pending = [], None
    for offset, line in enumerate(body):
        if pending is not None:
            pending = (pending[0], pending[1] + " " + line.strip())
        elif info[0] == "console" and not line.startswith("$ "):
            if out and line.strip() not in ("", "..."):
                out[-1][3].append(line.strip())
            continue
        elif line.strip() and not line.lstrip().startswith("#"):
            pending = (offset, line.removeprefix("$ "))
        else:
            continue
        if pending[1].endswith("\\"):
            pending = (pending[0], pending[1][:-1])
            continue
        comment = re.search(r"#.*\bexit (\d+)", pending[1])
        out.append((pending[0], shlex.split(pending[1], comments=True), int(comment.group(1)) if comment else 0, []))
        pending = None
    return out


def shown_as(line):
    """A line shown as output, with "..." standing for any text."""
    return re.compile(".*".join(re.escape(part.strip()) for part in line.split("...")))


def run(argv, where, expected, shown, scratch, env):
    """(problem or None, what it printed on stdout and stderr)."""
    began = time.monotonic()
    try:
        done = subprocess.run(argv, cwd=scratch, env=env, capture_output=True, text=True, timeout=LIMIT)
    except subprocess.TimeoutExpired:
        return f"{where}: still running after {LIMIT} s; mark its block ```sh excerpt", ""
    printed = done.stdout + done.stderr
    took.append((time.monotonic() - began, where))
    if done.returncode != expected:
        tail = "\n    ".join(done.stderr.strip().splitlines()[-5:])
        return f"{where}: exit {done.returncode}, expected {expected}\n    {tail}", printed
    lines = [line.strip() for line in printed.splitlines()]
    missing = [line for line in shown if not any(shown_as(line).fullmatch(p) for p in lines)]
    if missing:
        return f"{where}: the document shows output it did not print:\n    " + "\n    ".join(missing), printed
    return None, printed


text = document.read_text()
name = document.relative_to(root)
env = dict(os.environ, PYTHONPATH=module) if module else dict(os.environ)
problems, ran, excerpts, printed, typed, took = [], 0, 0, [], set(), []
with tempfile.TemporaryDirectory() as scratch:
    for entry in root.iterdir():  # the sources, not build trees or results a user ran there
        if not entry.name.startswith((".", "build", "sphkern-results")):
            os.symlink(entry, Path(scratch) / entry.name)
    for info, start, body in blocks(text):
        language = info[0] if info else ""
        for word in info:
            if word.startswith("file=") and re.fullmatch(r"[\w.-]+", word[5:]):
                (Path(scratch) / word[5:]).write_text("\n".join(body) + "\n")
        if language in SHELLS or language == "python":
            typed.update(token for line in body for token in re.findall(r"[-\w.]+", line))
        if "excerpt" in info:
            excerpts += 1
            continue
        if language in SHELLS:
            for offset, argv, expected, shown in commands(info, body):
                where = f"{name}:{start + offset}: {shlex.join(argv)}"
                if argv[0] != "sphkern":
                    if shlex.join(argv) not in BUILT_ELSEWHERE:
                        problems.append(f"{where}: not a sphkern command; mark its block ```sh excerpt if it is only shown")
                    continue
                if set(argv) & {"|", ">", ">>", "<", "&&", "||", ";", "&"}:
                    problems.append(f"{where}: shell syntax is not run; one command per line, or mark its block ```sh excerpt")
                    continue
                ran += 1
                problem, out = run([sphkern, *argv[1:]], where, expected, shown, scratch, env)
                printed.append(out)
                problems += [problem] if problem else []
        elif language == "python" and module:
            script = Path(scratch) / "example.py"
            script.write_text("\n".join(body) + "\n")
            ran += 1
            problem, out = run([sys.executable, str(script)], f"{name}:{start}: the python block", 0, [], scratch, env)
            printed.append(out)
            problems += [problem] if problem else []
if name.name == "README.md" or name.name.startswith("guide-"):
    for line, figure in unchecked_figures(text, "\n".join(printed), typed):
        problems.append(f"{name}:{line}: {figure}: no command of the document prints this figure; "
                        "show the command that does, or write a setting as `code`")
if problems:
    print("\n".join(problems), file=sys.stderr)
    sys.exit(f"{name}: {len(problems)} of {ran} commands failed")
slowest = max(took, default=(0, "none"))
print(f"{name}: {ran} commands ran, {excerpts} excerpts shown only; the slowest, {slowest[0]:.1f} s: {slowest[1]}")
