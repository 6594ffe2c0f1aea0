#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The wing surface (patch wing of the ASCII polyMesh) at rest and at written
times, with dcpRBF's control points of those times
(postProcessing/dcpRBF/controlPoints_<time>.vtk: moving ones on the wing,
static ones on the far field are not drawn): images/wing.png.

Usage: plotWing.py [--times 0.25 0.75] [--output images/wing.png]
"""
import argparse
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt                 # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402
import numpy as np                              # noqa: E402

from plotCut import readFaces, readPoints       # noqa: E402


def patchRange(boundary, name):
    """startFace, nFaces of a patch in a polyMesh/boundary file."""
    text = open(boundary).read()
    m = re.search(r"\b%s\s*\{([^}]*)\}" % name, text)
    body = m.group(1)
    return (int(re.search(r"startFace\s+(\d+)", body).group(1)),
            int(re.search(r"nFaces\s+(\d+)", body).group(1)))


def readVtkPoints(path):
    """Points and the 'moving' scalar of a legacy ASCII VTK polydata file."""
    lines = open(path).read().split("\n")
    i = next(k for k, l in enumerate(lines) if l.startswith("POINTS"))
    n = int(lines[i].split()[1])
    P = np.array([l.split() for l in lines[i + 1:i + 1 + n]], dtype=float)
    j = next(k for k, l in enumerate(lines) if l.startswith("SCALARS moving"))
    moving = np.array(lines[j + 2:j + 2 + n], dtype=int)
    return P, moving


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--times", nargs="*", default=["0.25", "0.75"])
    ap.add_argument("--output", default="images/wing.png")
    a = ap.parse_args()

    start, n = patchRange("constant/polyMesh/boundary", "wing")
    faces = readFaces("constant/polyMesh/faces")[start:start + n]
    cases = [("rest", readPoints("constant/polyMesh/points"), None)]
    for t in a.times:
        pts = os.path.join(t, "polyMesh", "points")
        vtk = os.path.join("postProcessing", "dcpRBF", "controlPoints_%s.vtk" % t)
        if os.path.exists(pts):
            cases.append(("t = %s s" % t, readPoints(pts), readVtkPoints(vtk) if os.path.exists(vtk) else None))

    fig = plt.figure(figsize=(4.2*len(cases), 4.4))
    for k, (title, P, cp) in enumerate(cases):
        ax = fig.add_subplot(1, len(cases), k + 1, projection="3d")
        ax.add_collection3d(Poly3DCollection([P[f] for f in faces], facecolors="0.85",
                                             edgecolors="0.35", linewidths=0.15))
        text = title
        if cp is not None:
            C, moving = cp
            C = C[moving == 1]
            ax.scatter(C[:, 0], C[:, 1], C[:, 2], s=4, c="r", depthshade=False)
            text += ", %d control points on the wing" % len(C)
        ax.set_xlim(0, 1.3)
        ax.set_ylim(0, 1.3)
        ax.set_zlim(-0.3, 0.3)
        ax.set_box_aspect((1.3, 1.3, 0.6))
        ax.view_init(elev=25, azim=-120)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        ax.set_zlabel("z [m]")
        ax.set_title(text, fontsize=9)
    fig.tight_layout()
    os.makedirs(os.path.dirname(a.output) or ".", exist_ok=True)
    fig.savefig(a.output, dpi=90)
    print("plotWing: " + a.output)


if __name__ == "__main__":
    main()
