"""What a plugin does besides its kernel: its printf goes to stderr, never into --json; its text
(and a data file's) reaches the terminal printable and JSON valid; a constructor that changes
the working folder does not move a relative output; a daemon it forks does not outlive sphkern."""
import json
import os
import signal
import subprocess
from pathlib import Path

from conftest import BROKEN, CLI, run


def test_plugin_output_goes_to_stderr():
    # stdout is sphkern's alone: a plugin's printf goes to stderr.
    out = run(["eps", "noisy", "fcc", "--k", "1.2", "--json", "--plugin",
               os.path.join(BROKEN, "prints_and_ignores_signals.so")])
    json.loads(out.stdout)
    assert "hello from a plugin" in out.stderr


def test_plugin_text_reaches_the_terminal_printable(tmp_path):
    # Text from plugins and data files reaches the terminal and JSON printable and valid.
    plugin = os.path.join(BROKEN, "hostile_text.so")
    text = subprocess.run([CLI, "kernels", "--plugin", plugin], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          timeout=60).stdout
    assert b"\x1b" not in text and b"\\x1b[2J" in text, text[-200:]
    listed = subprocess.run([CLI, "kernels", "--json", "--plugin", plugin], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, timeout=60).stdout
    d = [k for k in json.loads(listed) if k["name"] == "hostile_text"][0]
    assert d["title"] == "bad \ufffd\ufffd title", d["title"]
    assert d["reference"].startswith("\\x1b[2J"), d["reference"]


def test_lattice_title_printed_without_its_escape_byte(tmp_path):
    (tmp_path / "escaped.json").write_text(
        '{"name": "esc", "title": "\\u001b[31mred", "dimension": 2, "basis": [[1, 0], [0, 1]], "motif": [[0, 0]]}')
    text = subprocess.run([CLI, "lattices", str(tmp_path / "escaped.json")], stdout=subprocess.PIPE, timeout=60).stdout
    assert b"\x1b" not in text and b"\\x1b[31mred" in text, text


def test_relative_output_stays_where_it_was_given(tmp_path):
    # A plugin whose constructor moves the process to / does not move a relative output with it.
    (tmp_path / "here").mkdir()
    run(["particles", "changes_folder", "fcc", "--size", "6,6,6", "--k", "1.2", "--plugin",
         os.path.join(BROKEN, "changes_folder.so"), "--csv", "rel.csv"], cwd=tmp_path / "here")
    assert (tmp_path / "here" / "rel.csv").stat().st_size > 0
    assert not Path("/rel.csv").exists()


def test_a_daemon_a_plugin_forks_does_not_outlive_sphkern(tmp_path):
    # A plugin that forks a daemon when it is loaded (a session of its own, every descriptor closed),
    # in the probe's child and in sphkern: nothing of it outlives sphkern.
    pids = tmp_path / "daemons.txt"
    run(["particles", "forks_daemon", "fcc", "--size", "6,6,6", "--k", "1.2", "--plugin",
         os.path.join(BROKEN, "forks_daemon.so")], env_extra={"SPHKERN_TEST_DAEMON_PIDS": str(pids)})
    assert pids.exists() and pids.stat().st_size > 0
    left = []
    for pid in pids.read_text().split():
        stat = Path(f"/proc/{pid}/stat")
        try:
            state = stat.read_text().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if state != "Z":
            os.kill(int(pid), signal.SIGKILL)  # a survivor is killed
            left.append(pid)
    assert not left, f"daemons still running: {left}"
