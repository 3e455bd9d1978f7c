"""Plugins that fight the host when they are loaded (round 5, items 11 and 12)."""
import os

from conftest import expect


def test_plugin_closing_descriptors_loads_and_relative_output_stays(broken, tmp_path):
    # Its constructor closes descriptors 3..63 and moves the process to /.
    expect(["particles", "closes_descriptors", "fcc", "--size", "6,6,6", "--k", "1.2", "--plugin",
            os.path.join(broken, "closes_descriptors.so"), "--csv", "rel.csv"], 0, r"^$", cwd=tmp_path)
    assert (tmp_path / "rel.csv").stat().st_size > 0
