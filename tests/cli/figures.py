#!/usr/bin/env python3
"""Every figure of the default study in every format is a valid image of the size its
panels call for: 520 x 380 pixels per panel, at most three panels across (PDF at 96
pixels per inch, 72 points per inch). Checked from the files' own headers: the PNG IHDR
chunk, the SVG root element, the PDF MediaBox.
Usage: figures.py SPHKERN"""
import os
import re
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

sphkern = sys.argv[1]
with tempfile.TemporaryDirectory() as work:
    out = os.path.join(work, "out")
    subprocess.run([sphkern, "run", "--format", "svg,png,pdf", "-o", out], check=True, stdout=subprocess.DEVNULL)
    plots = os.path.join(out, "plots")
    # The default study: 8 kernels on one lattice in two modes, 8 surface panels, 8 stability and dispersion panels.
    expected = {name: (3 * 520, 3 * 380) for name in
                ("triangular-paper", "triangular-default", "triangular-surface", "triangular-stability",
                 "triangular-dispersion")}
    found = sorted({f.rsplit(".", 1)[0] for f in os.listdir(plots) if not f.endswith(".gp")})
    assert found == sorted(expected), found
    for name, (width, height) in expected.items():
        with open(os.path.join(plots, name + ".png"), "rb") as f:
            head = f.read(24)
        assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR", name
        assert struct.unpack(">II", head[16:24]) == (width, height), (name, struct.unpack(">II", head[16:24]))
        root = ET.parse(os.path.join(plots, name + ".svg")).getroot()
        assert root.tag.endswith("svg") and (root.get("width"), root.get("height")) == (str(width), str(height)), \
            (name, root.get("width"), root.get("height"))
        pdf = open(os.path.join(plots, name + ".pdf"), "rb").read()
        assert pdf.startswith(b"%PDF-") and b"%%EOF" in pdf[-1024:], name
        box = re.search(rb"/MediaBox \[ *0 0 ([0-9.]+) ([0-9.]+) *\]", pdf)
        assert box and abs(float(box.group(1)) - width * 0.75) < 1 and abs(float(box.group(2)) - height * 0.75) < 1, \
            (name, box and box.groups())
    report = open(os.path.join(out, "report.md")).read()
    assert all(f"plots/{name}.svg" in report for name in expected), "the report embeds the SVG figures"
print("figures: every figure valid in svg, png and pdf at its size")
