"""The rules the documentation tests apply, on small documents: a figure in the prose must be
one a command printed (rounded as written) or typed on a command line; code spans, tables made
by scripts and one-digit values are not figures to check; fences indented in a list are fences."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parents[1] / "cli"))
from markdown_docs import blocks, prose, unchecked_figures  # noqa: E402

PRINTED = "e0   1.1605e-01   0.9404896593\nrecommended eta = 1.69736 ([1.68359, 1.71112])"


@pytest.mark.parametrize("line, unchecked", [
    ("the RMS is 0.116 on the Poisson set", []),            # 1.1605e-01 rounded to 3 digits
    ("the RMS is 0.12 there", []),                          # and to 2
    ("the RMS is 0.1162 there", ["0.1162"]),                # not what was printed, rounded
    ("eta 1.697 (1.684 to 1.711)", []),
    ("eta 1.698", ["1.698"]),
    ("a root at -0.94049", []),                             # the sign aside
    ("a stale 0.130 in the guide", ["0.130"]),              # the trailing zero is a digit
    ("to 1e-12 and 0.01 and 0.5", []),                      # one significant digit: a tolerance
    ("a setting `--hdx 1.2348` in code", []),
    ("a span `over\nlines 3.25` in code", []),
    ("VTK 9.1 reads it", ["9.1"]),
    ("a typed 1.2348 on a command line", []),
])
def test_figures(line, unchecked):
    found = [figure for _, figure in unchecked_figures(line + "\n", PRINTED, {"1.2348"})]
    assert found == unchecked


def test_a_table_made_by_a_script_is_the_scripts():
    text = "<!-- table: python3 share/scripts/x.py build/sphkern -->\n| a | 3.25 |\n\nthen 4.75 again\n"
    assert [figure for _, figure in unchecked_figures(text, "", set())] == ["4.75"]


def test_a_fence_indented_in_a_list_item_is_a_fence():
    text = "- item:\n\n  ```console\n  $ sphkern shells sc --radius 1\n  ```\n- next 2.5\n"
    assert blocks(text) == [(["console"], 4, ["$ sphkern shells sc --radius 1"])]
    assert [line for _, line in prose(text) if "sphkern" in line] == []
