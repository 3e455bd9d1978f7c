"""Plugins that pass their probe and fail later, at a q, k or batch size the probe did not try:
exit 4 and one line naming the file, the kernel and the function; nothing left behind, in a
command or in a study."""
import os

import pytest
from conftest import BROKEN, expect, fill, table

CASES = [
    ("crash-in-band", ["spectrum", "{broken}/crash_in_band.so", "--dim", "3"],
     4, r"crash_in_band.so: plugin kernel crash_in_band crashed with signal 11 \(SIGSEGV\) in W; nothing was written"),
    ("crash-in-fused",
     ["particles", "{broken}/crash_in_fused.so", "poisson", "--dim", "3", "--count", "2000", "--nh", "30"],
     4, r"crash_in_fused.so: plugin kernel crash_in_fused crashed with signal 11 \(SIGSEGV\) in the fused W and dW; nothing was written"),
    ("abort-above-k", ["eps", "{broken}/abort_above_k.so", "fcc", "--k", "1.4"],
     4, r"abort_above_k.so: plugin kernel abort_above_k crashed with signal 6 \(SIGABRT\) in .*W; nothing was written"),
    ("exit-in-w", ["eps", "{broken}/exit_in_w.so", "fcc", "--k", "1.4"],
     4, r"exit_in_w.so: plugin kernel exit_in_w called exit\(\) or pthread_exit\(\) in .*W; nothing was written"),
    ("quick-exit-in-w", ["eps", "{broken}/quick_exit_in_w.so", "fcc", "--k", "1.4"],
     4, r"quick_exit_in_w.so: plugin kernel quick_exit_in_w called exit\(\) or pthread_exit\(\) in .*W; nothing was written"),
    ("loops-above-k", ["eps", "{broken}/loops_above_k.so", "fcc", "--k", "1.4"],
     4, r"loops_above_k.so: plugin kernel loops_above_k did not return within 2 s \(endless loop"),
    ("overflows-stack", ["eps", "{broken}/overflows_stack.so", "fcc", "--k", "1.4"],
     4, r"overflows_stack.so: plugin kernel overflows_stack crashed with signal 11 \(SIGSEGV\) in W"),
]


@table(CASES)
def test_plugin_failing_later(args, code, pattern):
    expect(fill(args), code, pattern)


@pytest.mark.parametrize("plugin", ["exit_in_w", "quick_exit_in_w", "abort_above_k", "loops_above_k"])
def test_failing_plugin_in_a_study_leaves_no_folder(tmp_path, plugin):
    (tmp_path / f"s_{plugin}.json").write_text(
        '{"name": "s", "kernels": ["' + os.path.join(BROKEN, plugin + ".so") + '"], "lattices": ["fcc"], '
        '"k": {"min": 0.75, "max": 1.5, "samples": 301}, "plots": false}')
    expect(["run", str(tmp_path / f"s_{plugin}.json"), "-o", str(tmp_path / f"made_{plugin}/a/b/out")], 4,
           rf"{plugin}.so: plugin kernel {plugin} ")
    # No staging folder, no folder the run made.
    assert not (tmp_path / f"made_{plugin}").exists()

