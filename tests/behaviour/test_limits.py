"""Limits of the machine are named, never blamed on a plugin or a kernel: open files (ulimit -n),
processes (ulimit -u), address space for threads (ulimit -v). Only stdin, stdout and stderr are
open in sphkern, whatever the test runner left open, so that the limit is sphkern's own."""
import os
import re
import resource
import shutil
import subprocess
import tempfile

import pytest
from conftest import CLI


def limit(kind, value):
    return lambda: resource.setrlimit(kind, (value, value))


def limited(args, kind, value, **kwargs):
    return subprocess.run([CLI, *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, close_fds=True,
                          preexec_fn=limit(kind, value), timeout=60, **kwargs)


def test_open_files_limit_when_listing_kernels():
    out = limited(["kernels"], resource.RLIMIT_NOFILE, 4)
    assert "too many open files (the limit is 4, ulimit -n)" in out.stderr and out.returncode == 3, (out.returncode, out.stderr)


@pytest.mark.parametrize("files", [4, 5])
def test_open_files_limit_is_named(files):
    # A limit of the process is named as such: it was "unknown lattice" with an empty list (ulimit -n 4)
    # and "unknown kernel ... (did you mean the same name?)" (ulimit -n 5).
    out = limited(["eps", "cubic_bspline", "fcc", "--k", "1.2"], resource.RLIMIT_NOFILE, files)
    assert re.search(rf"^sphkern: error: .*too many open files \(the limit is {files}, ulimit -n\); raise the limit$",
                     out.stderr, re.M), out.stderr
    assert out.returncode == 3, out.returncode


@pytest.mark.skipif(os.getuid() != 0, reason="needs root to run as another user")
def test_process_limit_is_named():
    cache = tempfile.mkdtemp()
    try:
        os.chmod(cache, 0o777)

        def nobody_with_one_process():
            os.setgroups([])
            os.setgid(65534)
            os.setuid(65534)
            resource.setrlimit(resource.RLIMIT_NPROC, (1, 1))

        out = subprocess.run([CLI, "check", "cubic_bspline"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                             preexec_fn=nobody_with_one_process, env={**os.environ, "XDG_CACHE_HOME": cache}, timeout=60)
        assert re.search(r"cannot start", out.stderr) and out.returncode == 3, (out.returncode, out.stderr)
    finally:
        shutil.rmtree(cache)


def test_threads_the_system_refuses():
    # The parts of the threads the system refuses run on those it allows, with one warning.
    out = limited(["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "8,8,8", "--threads", "1000"],
                  resource.RLIMIT_AS, 600000 * 1024)
    assert out.returncode == 0, out.stderr
    assert re.search(r"^sphkern: warning: cannot start 1000 threads .*the work runs on the threads the system allows$",
                     out.stderr, re.M), out.stderr
