#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Cuts of a 3D polyMesh by a plane y = Y (or x = X), for the tutorials'
pictures (wing3D/plotCut.py, flap3D/plotCut.py, flappingWing3D/plotResults.py):
the ASCII polyMesh read, the faces cut into segments in (x, z) (or (y, z)),
the cuts of several times side by side."""
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


def cut(P, faces, y0, axis=1):
    """Segments where the faces cross the plane coordinate axis = y0 (1: y,
    0: x), in the other two coordinates ((x, z) or (y, z))."""
    u = 0 if axis == 1 else 1
    segs = []
    for f in faces:
        q = P[f]
        s = q[:, axis] - y0
        if s.min() > 0 or s.max() < 0:
            continue
        pts = []
        for i in range(len(f)):
            a, b = q[i], q[(i + 1) % len(f)]
            sa, sb = a[axis] - y0, b[axis] - y0
            if (sa < 0) != (sb < 0):
                t = sa/(sa - sb)
                pts.append(a + t*(b - a))
        if len(pts) == 2:
            segs.append([(pts[0][u], pts[0][2]), (pts[1][u], pts[1][2])])
    return segs


def plotCuts(times, y, window, output, title="t = %s s", axis=1):
    """The cut y = y (axis 1; axis 0: x = y) of the mesh at rest and at each
    of times (those written) side by side in window (x0, x1, z0, z1) of the
    plotted coordinates ((x, z); axis 0: (y, z)), into output."""
    u = 0 if axis == 1 else 1
    name = "xy"[axis]
    x0, x1, z0, z1 = window
    faces = readFaces("constant/polyMesh/faces")
    P0 = readPoints("constant/polyMesh/points")
    cases = [("rest", P0)] + [(title % t, readPoints(os.path.join(t, "polyMesh", "points")))
                              for t in times if os.path.exists(os.path.join(t, "polyMesh", "points"))]
    # faces near the section only (a vertex in the window's neighbourhood at
    # one of the times; cut() keeps those crossing the plane)
    near = np.zeros(len(P0), dtype=bool)
    for _, P in cases:
        near |= ((P[:, u] > x0 - 0.5) & (P[:, u] < x1 + 0.5)
                 & (np.abs(P[:, 2]) < max(abs(z0), abs(z1)) + 0.5) & (np.abs(P[:, axis] - y) < 1.0))
    faces = [f for f in faces if near[f].any()]

    fig, axes = plt.subplots(1, len(cases), figsize=(4.5*len(cases), 4.5*(z1 - z0)/(x1 - x0) + 0.8),
                             squeeze=False)
    for ax, (what, P) in zip(axes[0], cases):
        ax.add_collection(LineCollection(cut(P, faces, y, axis), linewidths=0.3, colors="k"))
        ax.set_xlim(x0, x1)
        ax.set_ylim(z0, z1)
        ax.set_aspect("equal")
        ax.set_title("%s, cut %s = %g m" % (what, name, y))
        ax.set_xlabel("%s [m]" % "xy"[u])
        ax.set_ylabel("z [m]")
    fig.tight_layout()
    os.makedirs(os.path.dirname(output) or ".", exist_ok=True)
    fig.savefig(output, dpi=72)
