#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The mesh at rest and at two written times (default: a quarter and three
quarters of the hub's period, the hub farthest from the centre of the rotor):
the rotor's cells blue, the stator's grey, the hub red, the interface black.
images/mesh.png (--output).

Usage: plotMesh.py [--case .] [--times 0.25 0.75] [--output images/mesh.png]
"""
import argparse
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt                 # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
import numpy as np                              # noqa: E402

import foamMesh                                 # noqa: E402


def sides(P, P0, faces):
    """The front edges (z = 0) of boundary faces."""
    segs = []
    for f in faces:
        q = [p for p in f if abs(P0[p, 2]) < 1e-9]
        if len(q) == 2:
            segs.append([P[q[0], :2], P[q[1], :2]])
    return segs


def edges(P, faces, select):
    """The edges of the front faces (z = 0) chosen by select(centroid0)."""
    segs = []
    for f in faces:
        if select(f):
            q = P[f]
            segs += [[q[i, :2], q[(i + 1) % len(f), :2]] for i in range(len(f))]
    return segs


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default=".")
    ap.add_argument("--times", nargs="*", default=["0.25", "0.75"])
    ap.add_argument("--output", default="images/mesh.png")
    a = ap.parse_args()

    p0 = foamMesh.points(a.case)
    faces = foamMesh.faces(a.case)
    front = [f for f in faces if np.all(np.abs(p0[f, 2]) < 1e-9) and len(f) > 2]
    inRotor = {tuple(f): np.hypot(*p0[f, :2].mean(axis=0)) < 0.5 for f in front}
    start, size = foamMesh.patches(a.case)["hub"]
    hub = [f for f in faces[start:start + size]]
    start, size = foamMesh.patches(a.case)["amiRotor"]
    ami = [f for f in faces[start:start + size]]
    times = [t for t in a.times if t in foamMesh.times(a.case)]
    fig, axes = plt.subplots(1, 1 + len(times), figsize=(5*(1 + len(times)), 5))
    for ax, t in zip(np.atleast_1d(axes), ["0"] + times):
        P = p0 if t == "0" else foamMesh.points(a.case, t)
        ax.add_collection(LineCollection(edges(P, front, lambda f: not inRotor[tuple(f)]), colors="0.6", linewidths=0.4))
        ax.add_collection(LineCollection(edges(P, front, lambda f: inRotor[tuple(f)]), colors="tab:blue", linewidths=0.4))
        ax.add_collection(LineCollection(sides(P, p0, hub), colors="tab:red", linewidths=2))
        ax.add_collection(LineCollection(sides(P, p0, ami), colors="k", linewidths=1.2))
        ax.set_xlim(-1.02, 1.02)
        ax.set_ylim(-1.02, 1.02)
        ax.set_aspect("equal")
        ax.set_title("t = %s s" % t)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.suptitle("relativeMotion2D: the rotor (blue) turns, its hub (red) oscillates in it;"
                 " the stator (grey) stays")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(a.output)), exist_ok=True)
    fig.savefig(a.output, dpi=110)
    print("wrote " + a.output)


if __name__ == "__main__":
    main()
