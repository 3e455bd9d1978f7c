"""assess's windows: every interval of k where the setting is both accurate and stable, with the
code's own h model (adaptive for SWIFT: h follows the density), each with its width in h, the
recommended one with its N_H range, the one holding (or nearest to) the setting given, and the
narrow ones flagged against the h a relaxed glass spans, measured here. Run by ctest with
SPHKERN_CLI set."""
import csv
import json
import os
import subprocess

import numpy as np

CLI = os.environ["SPHKERN_CLI"]


def run_json(*args):
    done = subprocess.run([CLI, *args, "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_the_windows_are_those_of_roots_with_the_codes_h_model():
    doc = run_json("assess", "cubic_bspline", "fcc", "--code", "swift", "--eta", "0.95")
    roots = run_json("roots", "cubic_bspline", "fcc", "--kmax", "2.0", "--stability", "--h-model", "adaptive", "--code",
                     "swift")[0]  # assess's window, [0.75, 2]
    both = roots["stability"]["accurate_and_stable"]
    assert [w["k"] for w in doc["windows"]] == both and len(both) > 1
    for w in doc["windows"]:
        a, b = w["k"]
        assert abs(w["relative_half_width"] - (b - a) / (b + a)) < 1e-15 and w["robust"] == (w["relative_half_width"] >= 0.02)
    rec = doc["recommended"]
    assert rec["nh"] == roots["stability"]["recommended"]["neighbours_range"]
    # eta 0.95 lies below every window, nearest to another than the widest: named beside the
    # recommendation, and flagged, being narrow.
    k = doc["eps"]["k"]
    distance = [max(0, w["k"][0] - k, k - w["k"][1]) for w in doc["windows"]]
    near = doc["windows"][doc["nearest_window"]]
    assert doc["nearest_window"] == distance.index(min(distance)) and near["k"] != rec["interval"] and k < near["k"][0]
    assert f"; nearest to the setting: eta {near['code'][0]:.3g} to {near['code'][1]:.3g}; narrow: +-" in doc["verdict"]


def test_a_window_narrower_than_a_glasss_h_is_flagged():
    doc = run_json("assess", "wendland_c2", "fcc", "--code", "swift", "--eta", "1.2348")
    rec = doc["recommended"]
    assert rec["relative_half_width"] < 0.02 and not rec["robust"]
    assert "narrow: +-" in doc["verdict"] and "less than the +-2% a relaxed glass's h spans" in doc["verdict"]


def test_a_relaxed_glass_spans_about_two_per_cent_in_h(tmp_path):
    # The bound's source: SWIFT's solve on a glass `relax` makes (p1 and p99 of h over its median).
    glass = tmp_path / "glass.h5"
    subprocess.run([CLI, "relax", "wendland_c2", "poisson", "--count", "3000", "--nh", "60", "--steps", "40", "--output",
                    str(glass)], capture_output=True, check=True)
    subprocess.run([CLI, "particles", "wendland_c2", str(glass), "--code", "swift", "--eta", "1.2348", "--csv",
                    str(tmp_path / "h.csv")], capture_output=True, check=True)
    with open(tmp_path / "h.csv") as f:
        h = np.array([float(r["h"]) for r in csv.DictReader(f)])
    spread = max(1 - np.percentile(h, 1) / np.median(h), np.percentile(h, 99) / np.median(h) - 1)
    assert 0.01 < spread < 0.04, spread
