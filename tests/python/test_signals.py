"""The module keeps Python's signal handlers: loading a kernel does not take them over, a long
call stops at Ctrl-C with KeyboardInterrupt and leaves the module usable, and Ctrl-C in plain
Python code still raises KeyboardInterrupt afterwards."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import sphkern


def send_later(sig, seconds):
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), sig))
    timer.start()
    return timer


def test_loading_kernels_keeps_pythons_handlers():
    sphkern.kernels()
    sphkern.load_plugin(os.path.join(os.environ["SPHKERN_BROKEN_PLUGINS"], "prints_and_ignores_signals.so"))
    handle = sphkern.kernel("wendland_c4")
    assert handle.w(0.5, 3) > 0
    # Ctrl-C in plain Python code is Python's again: KeyboardInterrupt, not a flag in sphkern.
    send_later(signal.SIGINT, 0.2)
    with pytest.raises(KeyboardInterrupt):
        time.sleep(5)


def test_a_long_call_stops_at_ctrl_c_and_the_module_stays_usable():
    rng = np.random.default_rng(5)
    positions = rng.uniform(0, 1, (3_000_000, 3))
    send_later(signal.SIGINT, 0.5)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        sphkern.particles("cubic_bspline", positions, box=[1, 1, 1], nh=200)
    assert time.monotonic() - start < 10  # it stopped; it would run far longer otherwise
    # The next call is not interrupted by the old signal, and Python's handler is back.
    assert sphkern.eps("cubic_bspline", "fcc", 1.2)["eps_rho"].shape == ()
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    send_later(signal.SIGINT, 0.1)
    with pytest.raises(KeyboardInterrupt):
        time.sleep(5)
