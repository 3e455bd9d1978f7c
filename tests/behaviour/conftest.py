"""The behaviour tables: each case is a command line, the exit code and the one line expected
on standard error (a regular expression), its own pytest id. SPHKERN_CLI names the program,
SPHKERN_BROKEN_PLUGINS the folder of the test plugins.

In a table's arguments "{w}" is the case's own folder (a fresh tmp_path, or the module's folder
where the cases share their input files), "{broken}" the test plugins' folder, "{examples}" the
example lattices, "{lattices}" the shipped lattices and "{data}" tests/data."""
import json
import os
import re
import subprocess
from pathlib import Path

import pytest

CLI = os.environ["SPHKERN_CLI"]
BROKEN = os.environ["SPHKERN_BROKEN_PLUGINS"]
ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"
LATTICES = ROOT / "lattices"
EXAMPLES = LATTICES / "examples"


def run(args, cwd=None, env_extra=None, **kwargs):
    """Runs sphkern; bytes that are not UTF-8 in its output come back escaped (\\xff)."""
    env = {**os.environ, "SPHKERN_PLUGIN_TIMEOUT": "2", **(env_extra or {})}
    kwargs.setdefault("timeout", 60)
    return subprocess.run([CLI, *args], capture_output=True, text=True, errors="backslashreplace", cwd=cwd, env=env,
                          **kwargs)


def expect(args, code, pattern, cwd=None, env_extra=None):
    """The command exits with `code` and writes one line matching `pattern` (or nothing, for '^$')."""
    out = run(args, cwd, env_extra)
    lines = [line for line in out.stderr.splitlines() if line]
    assert out.returncode == code, f"exit {out.returncode}, stderr: {out.stderr}"
    assert len(lines) <= 1, f"more than one line: {out.stderr}"
    assert re.search(pattern, lines[0] if lines else ""), f"stderr: {out.stderr!r}, expected /{pattern}/"
    return out


def text_of(*args):
    """What the command prints on stdout; it must exit 0."""
    out = run(list(args))
    assert out.returncode == 0, out.stderr
    return out.stdout


def json_of(*args):
    """The command's JSON document (give --json among the arguments)."""
    return json.loads(text_of(*args))


def fill(args, work=None):
    """The arguments with the folders of the module docstring put in."""
    names = {"{broken}": BROKEN, "{examples}": str(EXAMPLES), "{lattices}": str(LATTICES), "{data}": str(DATA)}
    if work is not None:
        names["{w}"] = str(work)
    out = []
    for arg in args:
        for name, value in names.items():
            arg = arg.replace(name, value)
        out.append(arg)
    return out


def table(cases):
    """parametrize over rows (id, args, code, pattern), each row its own pytest id."""
    return pytest.mark.parametrize("args,code,pattern", [c[1:] for c in cases], ids=[c[0] for c in cases])


def write(folder, files):
    """Writes {name: text} into folder (text with "{w}" etc. filled in); returns the folder."""
    for name, text in files.items():
        path = Path(folder) / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(fill([text], folder)[0])
    return folder


@pytest.fixture
def broken():
    return BROKEN


def signal_when(ready, signals, args, work, env_extra=None):
    """Starts sphkern with debug logs, waits (up to 20 s) for a line of its log matching `ready`,
    then sends the signals. Returns the exit status, the milliseconds from the signal to the exit,
    standard error without its debug lines, and standard error whole."""
    import signal as signals_module
    import time
    # A signal sent before sphkern installs its handlers is lost or kills it with the default
    # action: wait for the log line that says the work has begun.
    err_path, out_path = Path(work) / "signal.err", Path(work) / "signal.out"
    env = {**os.environ, "SPHKERN_PLUGIN_TIMEOUT": "2", **(env_extra or {})}
    with open(out_path, "w") as out, open(err_path, "w") as err:
        process = subprocess.Popen([CLI, "--log-level", "debug", *args], stdout=out, stderr=err, env=env)
    try:
        for _ in range(400):
            if re.search(ready, err_path.read_text(errors="replace"), re.M) or process.poll() is not None:
                break
            time.sleep(0.05)
        for name in signals:
            if process.poll() is None:
                process.send_signal(getattr(signals_module, "SIG" + name))
        start = time.monotonic()
        code = process.wait(timeout=120)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    elapsed = int((time.monotonic() - start) * 1000)
    if code < 0:
        code = 128 - code  # ended by the signal itself: its status as a shell reports it (SIGINT: 130)
    whole = err_path.read_text(errors="replace")
    return code, elapsed, "\n".join(line for line in whole.splitlines() if "debug:" not in line), whole


def leftovers(work, name):
    """What a run into `name` left in `work`: the folder itself or its staging folder."""
    return [entry for entry in os.listdir(work) if re.match(r"^\.?" + re.escape(name) + r"(\.partial|$)", entry)]
