"""`run --force -o T` while another process keeps exchanging a user's folder with T (renameat2,
RENAME_EXCHANGE): whatever the timing, the user's file must survive, in its folder or at T.
A check made only before sphkern's own exchange lost it within a few tries.
Usage: force_race.py SPHKERN [TRIES]"""
import ctypes
import os
import subprocess
import sys
import tempfile
import threading

libc = ctypes.CDLL(None, use_errno=True)
RENAME_EXCHANGE, AT_FDCWD = 2, -100


def exchange(a, b):
    return libc.renameat2(AT_FDCWD, a.encode(), AT_FDCWD, b.encode(), RENAME_EXCHANGE)


sphkern = sys.argv[1]
tries = int(sys.argv[2]) if len(sys.argv) > 2 else 200
with tempfile.TemporaryDirectory() as work:
    study = os.path.join(work, "s.json")
    with open(study, "w") as f:
        f.write('{"name": "s", "kernels": ["cubic_bspline"], "lattices": ["fcc"], "plots": false}')
    results, user = os.path.join(work, "results"), os.path.join(work, "user")
    run = lambda *extra: subprocess.run([sphkern, "run", study, "-o", results, *extra], capture_output=True)
    run()
    os.makedirs(user)
    with open(os.path.join(user, "thesis.tex"), "w") as f:
        f.write("mine")
    for t in range(tries):
        stop = threading.Event()
        racer = threading.Thread(target=lambda: [exchange(user, results) for _ in iter(stop.is_set, True)])
        racer.start()
        done = run("--force")
        stop.set()
        racer.join()
        if done.returncode not in (0, 5):
            sys.exit(f"try {t}: exit {done.returncode}: {done.stderr.decode()}")
        here = [p for p in (user, results) if os.path.exists(os.path.join(p, "thesis.tex"))]
        if not here:
            sys.exit(f"try {t}: the user's file is gone ({done.stderr.decode().strip()})")
        if here[0] == results:
            exchange(user, results)  # the user's folder back at its place
        if not os.path.isdir(results):
            run()
    print(f"{tries} tries: the user's file survived every one")
