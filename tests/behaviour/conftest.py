"""The behaviour tables: each case is a command line, the exit code and the one line expected
on standard error (a regular expression), its own pytest id. SPHKERN_CLI names the program,
SPHKERN_BROKEN_PLUGINS the folder of the test plugins."""
import os
import re
import subprocess

import pytest

CLI = os.environ["SPHKERN_CLI"]
BROKEN = os.environ["SPHKERN_BROKEN_PLUGINS"]


def run(args, cwd=None, env_extra=None):
    env = dict(os.environ, SPHKERN_PLUGIN_TIMEOUT="2", **(env_extra or {}))
    return subprocess.run([CLI, *args], capture_output=True, text=True, cwd=cwd, env=env, timeout=60)


def expect(args, code, pattern, cwd=None):
    """The command exits with `code` and writes one line matching `pattern` (or nothing, for '^$')."""
    out = run(args, cwd)
    lines = [line for line in out.stderr.splitlines() if line]
    assert out.returncode == code, f"exit {out.returncode}, stderr: {out.stderr}"
    assert len(lines) <= 1, f"more than one line: {out.stderr}"
    assert re.search(pattern, lines[0] if lines else ""), f"stderr: {out.stderr!r}, expected /{pattern}/"
    return out


@pytest.fixture
def broken():
    return BROKEN
