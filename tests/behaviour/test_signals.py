"""Every command stops at a signal with exit 130 and leaves nothing: no output folder, no
staging folder, no half-written file. Each command here runs for seconds when left alone (and
then exits 0 or 4), so 130 shows that it stopped at the signal; the time it took is printed,
not judged."""
import os

import h5py
import numpy
import pytest
from conftest import leftovers, signal_when

S_LONG = ('{"name": "s", "kernels": ["cubic_bspline", "morris_quintic", "liu_quartic", "wendland_c4"], '
          '"lattices": ["fcc", "bcc", "sc", "hcp"], "volume_coefficients": ["voronoi", "ball", "cube"], '
          '"k": {"samples": 40000}, "plots": false}')


@pytest.mark.parametrize("sig", ["INT", "TERM", "HUP"])
def test_run_stopped(tmp_path, sig):
    (tmp_path / "s_long.json").write_text(S_LONG)
    code, elapsed, err, _ = signal_when("staging results in", [sig], ["run", str(tmp_path / "s_long.json"), "-o",
                                                                     str(tmp_path / "out_long")], tmp_path)
    assert code == 130 and not leftovers(tmp_path, "out_long"), (code, elapsed, err, os.listdir(tmp_path))
    if sig == "HUP":
        assert "hung up (SIGHUP): nothing was written" in err, err


def test_a_second_signal_ends_at_once(tmp_path):
    # A second signal ends the process at once, and still removes the staging folder.
    (tmp_path / "s_long.json").write_text(S_LONG)
    code, elapsed, err, _ = signal_when("staging results in", ["INT", "INT"], ["run", str(tmp_path / "s_long.json"), "-o",
                                                                              str(tmp_path / "out_long")], tmp_path)
    assert code == 130 and not leftovers(tmp_path, "out_long"), (code, elapsed, err, os.listdir(tmp_path))


COMMANDS = [
    ("block", "evaluating a block", "TERM",
     ["block", "cubic_bspline", "fcc", "--k", "1.2", "--size", "160,160,160", "--csv", "{w}/block.csv"], "block.csv"),
    ("spectrum", "running spectrum", "INT", ["spectrum", "wendland_c2", "--dim", "3", "--points", "100000", "--max", "1000"], None),
    ("surface", "running surface", "TERM", ["surface", "cubic_bspline", "fcc", "--k", "30", "--layers", "2000"], None),
    ("particles", "particles and [0-9]+ ghosts on", "TERM",
     ["particles", "cubic_bspline", "fcc", "--size", "120,120,120", "--k", "1.3", "--csv", "{w}/psig.csv"], "psig.csv"),
    ("relax", "relaxing [0-9]+ particles", "TERM",
     ["relax", "wendland_c2", "poisson", "--count", "200000", "--nh", "100", "--steps", "1000", "--output", "{w}/rsig.h5"],
     "rsig.h5"),
    ("design", "running design", "INT", ["design", "wendland_c2_shape", "fcc", "--param", "beta", "--kmin", "0.5", "--kmax", "8"],
     None),
]


@pytest.mark.parametrize("ready,sig,args,output", [c[1:] for c in COMMANDS], ids=[c[0] for c in COMMANDS])
def test_command_stopped(tmp_path, ready, sig, args, output):
    code, elapsed, err, _ = signal_when(ready, [sig], [a.replace("{w}", str(tmp_path)) for a in args], tmp_path)
    assert code == 130, (code, elapsed, err)
    if output:
        # Stopped, it writes no file.
        assert not leftovers(tmp_path, output), os.listdir(tmp_path)


def test_particles_in_slabs_stopped(tmp_path):
    # A snapshot over the budget, measured in slabs: no CSV and no spill folder left.
    with h5py.File(tmp_path / "slabsig.h5", "w") as f:
        f.create_group("Header").attrs["BoxSize"] = [1.0, 1.0, 1.0]
        f.create_dataset("PartType0/Coordinates", data=numpy.random.default_rng(6).random((400000, 3)))
    (tmp_path / "slabtmp").mkdir()
    code, elapsed, err, _ = signal_when(
        "in [0-9]+ slabs along axis", ["TERM"],
        ["particles", "cubic_bspline", str(tmp_path / "slabsig.h5"), "--nh", "60", "--memory-limit", "0.08", "--csv",
         str(tmp_path / "slabsig.csv")], tmp_path, env_extra={"TMPDIR": str(tmp_path / "slabtmp")})
    assert code == 130, (code, elapsed, err)
    assert not leftovers(tmp_path, "slabsig.csv")
    assert not os.listdir(tmp_path / "slabtmp")


def test_stability_stopped_on_the_high_symmetry_path(tmp_path):
    # Stability at a large k: each wave vector sums about 270000 neighbours, and the search along the
    # high-symmetry path makes some 2000 such sums before its caller checks again (at k = 60 a
    # SIGTERM took 255 s). Every sum now answers: the search itself stops, it never finishes.
    code, elapsed, err, whole = signal_when("zone scan: minima along the high-symmetry path", ["TERM"],
                                            ["stability", "cubic_bspline", "fcc", "--k", "20", "--threads", "1"], tmp_path)
    assert code == 130 and "the high-symmetry path searched" not in whole, (code, elapsed, err)
    # A hang guard of 60 s, not a speed test.
    assert elapsed < 60000, elapsed
