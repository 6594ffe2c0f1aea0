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
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt                 # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
import numpy as np                              # noqa: E402


def foamList(path):
    text = open(path).read()
    text = text[text.index("}", text.index("FoamFile")) + 1:]
    m = re.search(r"^(\d+)\s*\n\(", text, re.M)
    return int(m.group(1)), text[m.end():]


def readPoints(path):
    n, body = foamList(path)
    vals = re.findall(r"\(([-0-9.eE+]+) ([-0-9.eE+]+) ([-0-9.eE+]+)\)", body)[:n]
    return np.array(vals, dtype=float)


def readFaces(path):
    n, body = foamList(path)
    return [list(map(int, f.split())) for f in re.findall(r"\d+\(([^()]*)\)", body)[:n]]


def cut(P, faces, y0):
    """Segments where the faces cross y = y0, in (x, z)."""
    segs = []
    for f in faces:
        q = P[f]
        s = q[:, 1] - y0
        if s.min() > 0 or s.max() < 0:
            continue
        pts = []
        for i in range(len(f)):
            a, b = q[i], q[(i + 1) % len(f)]
            sa, sb = a[1] - y0, b[1] - y0
            if (sa < 0) != (sb < 0):
                t = sa/(sa - sb)
                pts.append(a + t*(b - a))
        if len(pts) == 2:
            segs.append([(pts[0][0], pts[0][2]), (pts[1][0], pts[1][2])])
    return segs


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
    x0, x1 = xle - 0.35*c, xle + 1.35*c
    z0, z1 = -w - 0.45*c, w + 0.45*c

    faces = readFaces("constant/polyMesh/faces")
    P0 = readPoints("constant/polyMesh/points")
    # faces near the section only (a vertex in the window's neighbourhood;
    # cut() keeps those crossing the plane)
    near = (P0[:, 0] > x0 - 0.5) & (P0[:, 0] < x1 + 0.5) & (np.abs(P0[:, 2]) < z1 + 0.5)
    near &= np.abs(P0[:, 1] - a.y) < 1.0
    faces = [f for f in faces if near[f].any()]

    cases = [("rest", P0)] + [("t = %s s" % t, readPoints(os.path.join(t, "polyMesh", "points")))
                              for t in a.times if os.path.exists(os.path.join(t, "polyMesh", "points"))]
    fig, axes = plt.subplots(1, len(cases), figsize=(4.5*len(cases), 4.5*(z1 - z0)/(x1 - x0) + 0.8),
                             squeeze=False)
    for ax, (title, P) in zip(axes[0], cases):
        ax.add_collection(LineCollection(cut(P, faces, a.y), linewidths=0.3, colors="k"))
        ax.set_xlim(x0, x1)
        ax.set_ylim(z0, z1)
        ax.set_aspect("equal")
        ax.set_title("%s, cut y = %g m" % (title, a.y))
        ax.set_xlabel("x [m]")
        ax.set_ylabel("z [m]")
    fig.tight_layout()
    os.makedirs(os.path.dirname(a.output) or ".", exist_ok=True)
    fig.savefig(a.output, dpi=72)
    print("plotCut: " + a.output)


if __name__ == "__main__":
    main()
