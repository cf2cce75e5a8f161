#!/usr/bin/env python3
"""Checks that every SVG picture under the given directories is well-formed XML with an <svg> root,
a white background, axes (the frame's corner coordinates) and a scale bar.

usage: scripts/check_svg.py DIR...     exit 1 naming each picture that fails
"""

import pathlib
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"


def problems(path: pathlib.Path) -> list[str]:
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        return [f"not well-formed XML: {e}"]
    if root.tag != SVG + "svg":
        return [f"root element is {root.tag}, not svg"]
    texts = [t.text or "" for t in root.iter(SVG + "text")]
    out = []
    if not any(t.startswith("x ") for t in texts) or not any(t.startswith("y ") for t in texts):
        out.append("no axis coordinates")
    if not any(p.get("d", "").startswith("M") and " V" in p.get("d", "") and " H" in p.get("d", "")
               for p in root.iter(SVG + "path")):
        out.append("no scale bar")
    return out


def main() -> int:
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    files = sorted(f for d in sys.argv[1:] for f in pathlib.Path(d).glob("*.svg"))
    bad = 0
    for f in files:
        for p in problems(f):
            print(f"{f}: {p}")
            bad += 1
    print(f"{len(files)} pictures checked, {bad} problems")
    return 1 if bad or not files else 0


if __name__ == "__main__":
    sys.exit(main())
