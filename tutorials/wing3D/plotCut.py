#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Cut of the mesh by the plane y = Y (default: mid semi-span) at rest and at
written times, near the wing section: images/cut.png. Reads the ASCII
polyMesh (constant/polyMesh/faces, points of each time).

Usage: plotCut.py [--y 0.6] [--times 0.25 0.75]
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
    a = ap.parse_args()

    faces = readFaces("constant/polyMesh/faces")
    P0 = readPoints("constant/polyMesh/points")
    # faces near the section only
    near = np.abs(P0[:, 1] - a.y) < 0.1
    near &= (P0[:, 0] > 0.1) & (P0[:, 0] < 1.4) & (np.abs(P0[:, 2]) < 0.4)
    faces = [f for f in faces if near[f].all()]

    cases = [("rest", P0)] + [("t = %s s" % t, readPoints(os.path.join(t, "polyMesh", "points")))
                              for t in a.times if os.path.exists(os.path.join(t, "polyMesh", "points"))]
    fig, axes = plt.subplots(1, len(cases), figsize=(5*len(cases), 4), squeeze=False)
    for ax, (title, P) in zip(axes[0], cases):
        ax.add_collection(LineCollection(cut(P, faces, a.y), linewidths=0.3, colors="k"))
        ax.set_xlim(0.3, 1.25)
        ax.set_ylim(-0.3, 0.35)
        ax.set_aspect("equal")
        ax.set_title("%s, cut y = %g m" % (title, a.y))
        ax.set_xlabel("x [m]")
        ax.set_ylabel("z [m]")
    fig.tight_layout()
    os.makedirs("images", exist_ok=True)
    fig.savefig("images/cut.png", dpi=150)
    print("plotCut: images/cut.png")


if __name__ == "__main__":
    main()
