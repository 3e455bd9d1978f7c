"""A relaxation that the pairing instability merges (round 5, item 15): the run names the step
and the cause, not the input, and keeps the history up to it."""
from conftest import expect


def test_pairing_merge_names_the_step_not_the_input(tmp_path):
    history = tmp_path / "history.csv"
    expect(["--log-level", "warn", "relax", "cubic_bspline", "fcc", "--size", "9,5,4", "--cell", "rectangular", "--sigma", "0.001", "--k", "1.35",
            "--method", "pressure", "--steps", "3000", "--history", str(history)], 3,
           r"^sphkern: error: fcc: at step [0-9]+ \(t = .* d/c\) particles [0-9]+ and [0-9]+ met at one position, where no "
           r"SPH sum is defined: the pairing instability merged them \(the set as given had them apart\)")
    assert history.stat().st_size > 0
