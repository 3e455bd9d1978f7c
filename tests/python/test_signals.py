"""The module keeps Python's signal handlers: loading a kernel does not take them over, a long
call stops at Ctrl-C with KeyboardInterrupt and leaves the module usable, and Ctrl-C in plain
Python code still raises KeyboardInterrupt afterwards."""
import os
import signal
import sys
import threading
import time

import numpy as np
import pytest

import sphkern


# Only a guard against a hang: a signal that works ends these waits at once, however loaded
# the machine is; none of them asserts how fast.
HANG_GUARD = 120


def send_later(sig, seconds):
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), sig))
    timer.start()
    return timer


def send_once_called(function, sig, seconds):
    """Sends sig `seconds` after `function` (a C function) is entered, not after a fixed time from
    now: on a loaded machine the call may start late, and the signal must find it running."""
    def profile(frame, event, arg):
        if event == "c_call" and arg is function:
            sys.setprofile(None)
            send_later(sig, seconds)
    sys.setprofile(profile)


def test_loading_kernels_keeps_pythons_handlers():
    sphkern.kernels()
    sphkern.load_plugin(os.path.join(os.environ["SPHKERN_BROKEN_PLUGINS"], "prints_and_ignores_signals.so"))
    handle = sphkern.kernel("wendland_c4")
    assert handle.w(0.5, 3) > 0
    # Ctrl-C in plain Python code is Python's again: KeyboardInterrupt, not a flag in sphkern.
    send_later(signal.SIGINT, 0.2)
    with pytest.raises(KeyboardInterrupt):
        time.sleep(HANG_GUARD)


def test_a_long_call_stops_at_ctrl_c_and_the_module_stays_usable():
    rng = np.random.default_rng(5)
    positions = rng.uniform(0, 1, (3_000_000, 3))
    send_once_called(sphkern.particles, signal.SIGINT, 0.5)
    # The call itself raises KeyboardInterrupt: it stopped at the signal (it would otherwise
    # return a result, and pytest.raises would fail).
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        sphkern.particles("cubic_bspline", positions, box=[1, 1, 1], nh=200)
    sys.setprofile(None)
    assert time.monotonic() - start < HANG_GUARD, "the call ran on long after the signal"
    # The next call is not interrupted by the old signal, and Python's handler is back.
    assert sphkern.eps("cubic_bspline", "fcc", 1.2)["eps_rho"].shape == ()
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    send_later(signal.SIGINT, 0.1)
    with pytest.raises(KeyboardInterrupt):
        time.sleep(HANG_GUARD)
