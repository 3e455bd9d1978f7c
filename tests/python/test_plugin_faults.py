"""A plugin that passes its probe and fails later, inside the module. A crash, abort(), exit()
or _exit() in its code (on any thread, a stack overflow too) raises RuntimeError naming the
plugin file and the function; the plugin is not called again, and everything else in the
module goes on working. A W that never returns still ends the interpreter with exit 4 and one
line (no thread can be stopped inside foreign code). Python's own fault handlers
(faulthandler) are back after every call. Each case runs in its own interpreter."""
import os
import subprocess
import sys

import pytest

BROKEN = os.environ["SPHKERN_BROKEN_PLUGINS"]


def python(code, timeout=60, **env):
    """Runs `code` in a fresh interpreter with the module; returns (exit status, stderr lines)."""
    done = subprocess.run([sys.executable, "-c", "import sphkern\n" + code], capture_output=True, text=True,
                          timeout=timeout, env={**os.environ, **env})
    return done.returncode, [line for line in done.stderr.splitlines() if line.strip()]


@pytest.mark.parametrize("plugin, call, message", [
    ("crash_in_band", "w(0.52, 3)", "crashed with signal 11 (SIGSEGV) in the batch W"),
    ("abort_above_k", "w(0.5, 3, k=1.4)", "crashed with signal 6 (SIGABRT) in the batch W"),
    ("crash_big_batch", "w([0.5] * 200, 3)", "crashed with signal 11 (SIGSEGV) in the batch W"),
    ("overflows_stack", "w(0.5, 3, k=1.4)", "crashed with signal 11 (SIGSEGV) in the batch W"),
    ("exit_in_w", "w(0.5, 3, k=1.4)", "called exit() in the batch W"),
    ("quick_exit_in_w", "w(0.5, 3, k=1.4)", "called exit() in the batch W"),
])
def test_a_plugin_that_crashes_after_its_probe_raises_and_the_module_goes_on(plugin, call, message):
    path = os.path.join(BROKEN, plugin + ".so")
    named = f"{path}: plugin kernel {plugin} {message}"
    status, lines = python(f"""
sphkern.load_plugin({path!r})
k = sphkern.kernel({plugin!r})
assert k.w(0.5, 3) > 0
try:
    k.{call}
    raise SystemExit("not raised")
except RuntimeError as e:
    assert str(e) == {named + "; it is not called again in this process"!r}, str(e)
try:
    k.w(0.5, 3)  # a call that worked before the crash: the plugin is not called again
    raise SystemExit("called again")
except RuntimeError as e:
    assert str(e) == {named + " earlier; it is not called again in this process"!r}, str(e)
assert sphkern.eps("cubic_bspline", "fcc", 1.2)["eps_rho"] == sphkern.eps("cubic_bspline", "fcc", 1.2)["eps_rho"]
print("went on")
""")
    assert status == 0 and lines == [], (status, lines)


def test_a_crash_on_the_engines_threads_raises_once_and_the_next_call_works():
    path = os.path.join(BROKEN, "crash_in_band.so")
    status, lines = python(f"""
import numpy as np
x = np.random.default_rng(1).uniform(0, 1, (20000, 3))
try:
    sphkern.particles({path!r}, x, box=[1, 1, 1], h_over_l=1.3, threads=4)
    raise SystemExit("not raised")
except RuntimeError as e:
    assert "plugin kernel crash_in_band crashed with signal 11 (SIGSEGV)" in str(e), str(e)
r = sphkern.particles("cubic_bspline", x, box=[1, 1, 1], h_over_l=1.3, threads=4)
assert r["e0"].shape == (20000,)
""")
    assert status == 0 and lines == [], (status, lines)


def test_a_plugin_call_that_never_returns_is_stopped_after_the_bound():
    path = os.path.join(BROKEN, "loops_above_k.so")
    status, lines = python(f"sphkern.load_plugin({path!r})\nsphkern.kernel('loops_above_k').w(0.5, 3, k=1.4)",
                           SPHKERN_PLUGIN_TIMEOUT="1")
    assert status == 4, (status, lines)
    assert len(lines) == 1 and "plugin kernel loops_above_k did not return within 1 s" in lines[0], lines


def test_pythons_fault_handler_is_back_after_a_call():
    # faulthandler's report of a crash in plain Python code proves its handler is in place again.
    status, lines = python("import faulthandler, ctypes\nfaulthandler.enable()\n"
                           "assert sphkern.eps('cubic_bspline', 'fcc', 1.2)['eps_rho'].shape == ()\n"
                           "ctypes.string_at(0)")
    assert status == -11, (status, lines)
    assert any("Fatal Python error: Segmentation fault" in line for line in lines), lines


def test_first_calls_from_sixteen_threads_at_once_do_not_deadlock(tmp_path):
    # A fresh interpreter, a cold probe cache: the first calls resolve kernels, probe and load plugins.
    code = """
import threading
barrier = threading.Barrier(16)
results = [None] * 16
def work(i):
    barrier.wait()
    kernel = ["cubic_bspline", "wendland_c4", "liu_quartic", "morris_quintic"][i % 4]
    results[i] = float(sphkern.eps(kernel, ["fcc", "bcc"][i % 2], 1.2)["eps_rho"])
threads = [threading.Thread(target=work, args=(i,)) for i in range(16)]
for t in threads: t.start()
for t in threads: t.join()
single = [float(sphkern.eps(["cubic_bspline", "wendland_c4", "liu_quartic", "morris_quintic"][i % 4],
                            ["fcc", "bcc"][i % 2], 1.2)["eps_rho"]) for i in range(16)]
assert results == single, (results, single)
print("done")
"""
    status, lines = python(code, timeout=120, XDG_CACHE_HOME=str(tmp_path))
    assert status == 0, (status, lines)
