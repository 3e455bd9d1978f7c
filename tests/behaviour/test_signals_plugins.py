"""Signals while someone else holds the process: a plugin that ignores SIGINT in its probe, one
that ignores the signals once loaded, one whose call loops, and gnuplot drawing a figure. Each
still ends with exit 130 and leaves nothing behind."""
import os
import stat

import pytest
from conftest import BROKEN, leftovers, signal_when


def test_hanging_plugin_probe_interrupted(tmp_path):
    # A plugin that ignores SIGINT and hangs in its probe: sphkern stops the probe itself.
    code, elapsed, err, _ = signal_when("probing .*hangs_ignoring_sigint", ["INT"],
                                        ["kernels", "--plugin", os.path.join(BROKEN, "hangs_ignoring_sigint.so")], tmp_path,
                                        env_extra={"SPHKERN_PLUGIN_TIMEOUT": "60"})
    assert code == 130, (code, elapsed, err)


def test_plugin_ignoring_sigint_still_interruptible(tmp_path):
    # A plugin that ignores the signals once loaded: the handlers are taken back after loading.
    code, elapsed, err, _ = signal_when("evaluating a block", ["INT"],
                                        ["block", "noisy", "fcc", "--k", "1.2", "--size", "160,160,160", "--csv",
                                         str(tmp_path / "noisy.csv"), "--plugin",
                                         os.path.join(BROKEN, "prints_and_ignores_signals.so")], tmp_path)
    assert code == 130, (code, elapsed, err)


def test_interrupt_during_gnuplot(tmp_path):
    # An interrupt while gnuplot runs is an interrupt (130), and gnuplot is stopped too.
    (tmp_path / "fakebin").mkdir()
    gnuplot = tmp_path / "fakebin" / "gnuplot"
    gnuplot.write_text(f'#!/bin/sh\necho $$ >"{tmp_path}/fake-gnuplot.pid"\nsleep 30\n')
    gnuplot.chmod(gnuplot.stat().st_mode | stat.S_IXUSR)
    (tmp_path / "s_plot.json").write_text('{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "k": {"samples": 11}}')
    code, elapsed, err, _ = signal_when("started .*gnuplot", ["INT"],
                                        ["run", str(tmp_path / "s_plot.json"), "-o", str(tmp_path / "out_plot")], tmp_path,
                                        env_extra={"PATH": f"{tmp_path}/fakebin:{os.environ['PATH']}"})
    assert code == 130 and not leftovers(tmp_path, "out_plot"), (code, err, os.listdir(tmp_path))
    pid = int((tmp_path / "fake-gnuplot.pid").read_text())
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)


@pytest.mark.parametrize("sig", ["INT", "TERM", "HUP"])
def test_signal_inside_a_looping_plugin_call(tmp_path, sig):
    # A signal while a plugin call loops and ignores it: exit 130 within a second (the time is printed).
    (tmp_path / "s_loops_above_k.json").write_text(
        '{"name": "s", "kernels": ["' + os.path.join(BROKEN, "loops_above_k.so") + '"], "lattices": ["fcc"], '
        '"k": {"min": 0.75, "max": 1.5, "samples": 301}, "plots": false}')
    code, elapsed, err, _ = signal_when("loops_above_k has been in W for 1 s", [sig],
                                        ["run", str(tmp_path / "s_loops_above_k.json"), "-o", str(tmp_path / "out_loop")],
                                        tmp_path, env_extra={"SPHKERN_PLUGIN_TIMEOUT": "60"})
    assert code == 130 and not leftovers(tmp_path, "out_loop"), (code, elapsed, err, os.listdir(tmp_path))
    if sig == "HUP":
        # The interrupt names the plugin call.
        import re
        assert re.search(r"hung up \(SIGHUP\) while .*loops_above_k.so: plugin kernel loops_above_k was in", err), err
