#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Cut of the flap3D mesh by the plane y = Y (default: mid semi-span) at rest
and at the flap's extremes, around the hinge and the flap:
images/cut.png (--output); --zoom: the hinge strip's first layers.

Usage: plotCut.py [--y 1] [--times 20 60] [--zoom] [--output images/cut.png]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from meshCut import plotCuts  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--y", type=float, default=1.0)
    ap.add_argument("--times", nargs="*", default=["20", "60"])
    ap.add_argument("--zoom", action="store_true")
    ap.add_argument("--output", default="images/cut.png")
    a = ap.parse_args()
    # the flap (hinge x = 0.75, chord 0.25) turning +-40 deg; zoom: the strip
    window = (0.66, 0.84, -0.07, 0.07) if a.zoom else (0.35, 1.35, -0.4, 0.4)
    plotCuts(a.times, a.y, window, a.output, title="t = %s")
    print("plotCut: " + a.output)


if __name__ == "__main__":
    main()
