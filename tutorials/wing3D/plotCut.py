#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Cut of the mesh by the plane y = Y (default: mid semi-span) at rest and at
written times, near the wing section: images/cut.png (--output). Reads the
ASCII polyMesh (constant/polyMesh/faces, points of each time). The window
follows the section (leading edge, chord and deflection at y = Y).

Usage: plotCut.py [--y 0.6] [--times 0.25 0.75] [--output images/cut.png]
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from meshCut import plotCuts  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--y", type=float, default=0.6)
    ap.add_argument("--times", nargs="*", default=["0.25", "0.75"])
    ap.add_argument("--output", default="images/cut.png")
    a = ap.parse_args()

    # the section at y (ONERA M6 planform, wingMesh.py), the tip deflection
    # 0.15 (y/b)^2 at the extremes
    b = 1.1963
    xle = a.y*np.tan(np.radians(30.0))
    c = 0.806 + (0.453 - 0.806)*min(a.y, b)/b
    w = 0.15*min(a.y/b, 1.0)**2
    window = (xle - 0.35*c, xle + 1.35*c, -w - 0.45*c, w + 0.45*c)
    plotCuts(a.times, a.y, window, a.output)
    print("plotCut: " + a.output)


if __name__ == "__main__":
    main()
