"""The plugin probe cache: a file is probed once, again when it changes (in size, times or only
its ctime); a cached entry that disagrees with the file heals; a corrupt cache is ignored and
rewritten; a cache path that is not a regular file is left alone; a plugin replaced between its
probe and its load never runs unprobed."""
import json
import os
import re
import shutil

from conftest import BROKEN, expect, run


def probes(cache, *args):
    out = run(["--log-level", "debug", *args], env_extra={"XDG_CACHE_HOME": str(cache)})
    return out.stderr.count("debug: probing")


def test_a_file_is_probed_once_and_again_when_it_changes(tmp_path):
    cache, copy = tmp_path / "cache", tmp_path / "copy.so"
    shutil.copy(os.path.join(BROKEN, "sign_flip.so"), copy)
    # The cold cache probes every folder plugin, the warm one nothing.
    assert probes(cache, "eps", "cubic_bspline", "fcc", "--k", "1.2") >= 12
    assert probes(cache, "eps", "cubic_bspline", "fcc", "--k", "1.2") == 0
    # A new plugin file is probed, and then not again.
    assert probes(cache, "eps", "sign_flip", "fcc", "--k", "1.2", "--plugin", str(copy)) == 1
    assert probes(cache, "eps", "sign_flip", "fcc", "--k", "1.2", "--plugin", str(copy)) == 0
    # A changed plugin file is probed again.
    shutil.copy(os.path.join(BROKEN, "nan_band.so"), copy)
    assert probes(cache, "eps", "nan_band", "fcc", "--k", "1.2", "--plugin", str(copy)) == 1
    expect(["eps", "nan_band", "fcc", "--k", "1.4184397163120568", "--plugin", str(copy)], 4,
           r"kernel nan_band .*: W is not finite", env_extra={"XDG_CACHE_HOME": str(cache)})
    # Rewritten in place with its old size and modification time: only the ctime tells, and it does.
    mtime = copy.stat().st_mtime_ns
    copy.write_bytes(copy.read_bytes())
    os.utime(copy, ns=(mtime, mtime))
    assert probes(cache, "eps", "nan_band", "fcc", "--k", "1.2", "--plugin", str(copy)) == 1
    # New content in place, same size, same inode, mtime set back: probed again, and refused for
    # what it now says (its name patched to an invalid one).
    before = copy.stat()
    with open(copy, "r+b") as f:
        data = f.read()
        assert data.count(b"\0nan_band\0") == 1
        f.seek(data.index(b"\0nan_band\0") + 1)
        f.write(b"nan_bAnd")
    os.utime(copy, ns=(before.st_atime_ns, before.st_mtime_ns))
    after = copy.stat()
    # The patched plugin keeps size, mtime and inode.
    assert (after.st_size, int(after.st_mtime), after.st_ino) == (before.st_size, int(before.st_mtime), before.st_ino)
    out = run(["--log-level", "debug", "eps", "nan_band", "fcc", "--k", "1.2", "--plugin", str(copy)],
              env_extra={"XDG_CACHE_HOME": str(cache)})
    assert out.returncode == 4, out.stderr
    assert len(re.findall(r"debug: probing .*copy.so", out.stderr)) == 1, out.stderr
    assert "copy.so: invalid kernel descriptor: name must be 1 to 64 characters" in out.stderr, out.stderr


def test_a_wrong_cached_name_heals(tmp_path):
    # A cache entry with a wrong name for an unchanged file (a cache copied or edited): the load
    # validates the whole descriptor and the entry heals; before, every run failed until the file changed.
    cache, heal = tmp_path / "cache", tmp_path / "heal.so"
    env = {"XDG_CACHE_HOME": str(cache)}
    shutil.copy(os.path.join(BROKEN, "nan_band.so"), heal)
    expect(["eps", "nan_band", "fcc", "--k", "1.2", "--plugin", str(heal)], 0, r"^$", env_extra=env)
    path = cache / "sphkern" / "plugin-probes.json"
    c = json.loads(path.read_text())
    for k, e in c["plugins"].items():
        if k.endswith("/heal.so"):
            e["name"] = "cubic_bspline"
    path.write_text(json.dumps(c))
    expect(["eps", "nan_band", "fcc", "--k", "1.2", "--plugin", str(heal)], 0, r"^$", env_extra=env)
    # The wrong cached name is replaced by the descriptor's.
    c = json.loads(path.read_text())
    assert [e["name"] for k, e in c["plugins"].items() if k.endswith("/heal.so")] == ["nan_band"], c


def test_a_corrupt_cache_is_rewritten_and_a_link_is_not_written_through(tmp_path):
    cache = tmp_path / "cache"
    env = {"XDG_CACHE_HOME": str(cache)}
    expect(["eps", "cubic_bspline", "fcc", "--k", "1.2"], 0, r"^$", env_extra=env)
    path = cache / "sphkern" / "plugin-probes.json"
    path.write_text('{"format": "sphkern')
    expect(["eps", "cubic_bspline", "fcc", "--k", "1.2"], 0, r"^$", env_extra=env)
    json.loads(path.read_text())
    path.unlink()
    path.symlink_to("/dev/null")
    expect(["eps", "cubic_bspline", "fcc", "--k", "1.2"], 0, r"^$", env_extra=env)
    assert path.is_symlink() and os.path.exists("/dev/null")


def test_a_plugin_replaced_between_probe_and_load(tmp_path):
    # A plugin file replaced between its probe and its load: the replacement never runs unprobed
    # (its W would crash at the descriptor's probe points); the next run probes it.
    swap = tmp_path / "swap"
    swap.mkdir()
    shutil.copy(os.path.join(BROKEN, "replaces_itself.so"), swap / "plugin.so")
    shutil.copy(os.path.join(BROKEN, "crash_in_w.so"), swap / "other.so")
    out = run(["eps", "replaces_itself", "fcc", "--k", "1.2", "--plugin", str(swap / "plugin.so")],
              env_extra={"XDG_CACHE_HOME": str(swap), "SPHKERN_TEST_REPLACE_FROM": str(swap / "other.so"),
                         "SPHKERN_TEST_REPLACE_TO": str(swap / "plugin.so")})
    # Refused, the replacement not run.
    assert (out.returncode, out.stdout + out.stderr) == (
        4, f"sphkern: error: {swap}/plugin.so: the plugin changed while it was loaded; run again\n"), out
    # The file was replaced during the probe.
    assert (swap / "plugin.so").read_bytes() == open(os.path.join(BROKEN, "crash_in_w.so"), "rb").read()
    expect(["eps", "crash_in_w", "fcc", "--k", "1.2", "--plugin", str(swap / "plugin.so")], 4,
           r"swap/plugin.so: plugin crashed with signal 11", env_extra={"XDG_CACHE_HOME": str(swap)})


def test_a_stale_cached_name_heals(tmp_path):
    # A stale probe-cache entry (the file's own size and times, another kernel's name) heals: it
    # made wendland_c4 unknown and wendland_c2 "two plugins", run after run.
    stale = tmp_path / "stale-cache"
    env = {"XDG_CACHE_HOME": str(stale)}
    run(["kernels"], env_extra=env)
    path = stale / "sphkern" / "plugin-probes.json"

    def entry(d):
        return next(v for k, v in d["plugins"].items() if k.endswith("/wendland_c4.so"))

    d = json.loads(path.read_text())
    entry(d)["name"] = "wendland_c2"
    path.write_text(json.dumps(d))
    out = run(["eps", "wendland_c2", "fcc", "--k", "1.2"], env_extra=env)
    assert out.returncode == 0, out.stderr  # wendland_c2 still found once
    out = run(["eps", "wendland_c4", "fcc", "--k", "1.2"], env_extra=env)
    assert out.returncode == 0, out.stderr  # wendland_c4 found
    # The cache names the file by its descriptor again.
    assert entry(json.loads(path.read_text()))["name"] == "wendland_c4"
