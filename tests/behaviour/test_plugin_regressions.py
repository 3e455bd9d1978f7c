"""Plugins that fight the host when they are loaded (round 5, items 11 and 12)."""
import os

from conftest import expect


def test_plugin_closing_descriptors_loads_and_relative_output_stays(broken, tmp_path):
    # Its constructor closes descriptors 3..63 and moves the process to /.
    expect(["particles", "closes_descriptors", "fcc", "--size", "6,6,6", "--k", "1.2", "--plugin",
            os.path.join(broken, "closes_descriptors.so"), "--csv", "rel.csv"], 0, r"^$", cwd=tmp_path)
    assert (tmp_path / "rel.csv").stat().st_size > 0


def test_plugin_overflowing_on_a_band_is_named_with_its_band(broken):
    # 1e308 on 0.701 < q < 0.709: the fcc density sum at k = 1/0.705 overflows (round 5, item 13).
    expect(["eps", "huge_band", "fcc", "--k", "1.4184397163120568", "--plugin", os.path.join(broken, "huge_band.so")], 4,
           r"^sphkern: error: kernel huge_band .*: W reaches 1e\+308 for q in \[0\.70\d*, 0\.70\d*\] .*the lattice's density "
           r"and gradient sums of its finite values overflows a double")


def test_unwritable_probe_cache_is_only_a_missed_shortcut(broken, tmp_path):
    # The cache folder is a file: the probe result cannot be kept, the plugin still loads (round 5, item 12).
    (tmp_path / "cache").write_text("not a folder")
    import subprocess
    from conftest import CLI
    env = dict(os.environ, XDG_CACHE_HOME=str(tmp_path / "cache"))
    out = subprocess.run([CLI, "eps", "changes_folder", "fcc", "--k", "1.2", "--plugin",
                          os.path.join(broken, "changes_folder.so")], capture_output=True, text=True, env=env, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stderr == ""
