#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Pictures of the pitchingAirfoil2D results (matplotlib, no ParaView needed).

images/mesh.png:   the mesh near the airfoil at t = 0 and at the largest
                   nose-up and nose-down pitch angles (front plane edges);
images/forces.png: pitch angle, lift and moment coefficients over time.

Reads the ascii polyMesh files written by the run (writeFormat ascii).
"""
import math
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt                         # noqa: E402
from matplotlib.collections import LineCollection      # noqa: E402

AMPLITUDE, OMEGA = 0.4363, math.pi   # as in 0.orig/pointDisplacement


def read_list(path, item):
    """Items of an ascii OpenFOAM list file matched by regex 'item'."""
    with open(path) as f:
        text = f.read()
    body = text[text.index("\n(", text.index("FoamFile")) + 2:]
    return re.findall(item, body)


def read_points(path):
    num = r"([-+0-9.eE]+)"
    return [tuple(map(float, m))
            for m in read_list(path, r"\(" + num + " " + num + " " + num + r"\)")]


def front_edges(points, faces):
    zmax = max(p[2] for p in points)
    edges = set()
    for f in faces:
        if all(abs(points[i][2] - zmax) < 1e-9 for i in f):
            for a, b in zip(f, f[1:] + f[:1]):
                edges.add((min(a, b), max(a, b)))
    return [[points[a][:2], points[b][:2]] for a, b in edges]


def time_dirs():
    times = []
    for d in os.listdir("."):
        try:
            times.append((float(d), d))
        except ValueError:
            pass
    return sorted(times)


def read_vtk_points(path):
    """Points of a legacy ASCII VTK file (dcpRBF control points)."""
    with open(path) as f:
        lines = f.read().split("\n")
    start = next(i for i, l in enumerate(lines) if l.startswith("POINTS"))
    n = int(lines[start].split()[1])
    return [tuple(map(float, l.split())) for l in lines[start + 1:start + 1 + n]]


def plot_mesh(faces):
    angle = {t: AMPLITUDE*math.sin(OMEGA*t) for t, _ in time_dirs()}
    up = max(angle, key=angle.get)
    down = min(angle, key=angle.get)
    shots = [(0.0, "constant/polyMesh/points")]
    for t in (up, down):
        name = [d for tt, d in time_dirs() if tt == t][0]
        shots.append((t, os.path.join(name, "polyMesh/points")))

    fig, axes = plt.subplots(1, 3, figsize=(15, 5), sharey=True)
    for ax, (t, path) in zip(axes, shots):
        ax.add_collection(LineCollection(front_edges(read_points(path), faces),
                                         linewidths=0.4, colors="k"))
        vtk = "postProcessing/dcpRBF/controlPoints_%g.vtk" % t
        if os.path.exists(vtk):
            cp = read_vtk_points(vtk)
            ax.plot([p[0] for p in cp], [p[1] for p in cp], "o", color="tab:red",
                    markersize=3, label="%d control points" % len(cp))
            ax.legend(loc="upper right", fontsize=8)
        ax.set_xlim(-0.6, 1.6)
        ax.set_ylim(-0.8, 0.8)
        ax.set_aspect("equal")
        ax.set_title("t = %g s, pitch %+.1f deg" % (t, math.degrees(angle.get(t, 0))))
    fig.suptitle("dcpRBF (dynamic control points): NACA0012 pitching +-25 deg"
                 " about the quarter chord")
    fig.tight_layout()
    fig.savefig("images/mesh.png", dpi=110)


def plot_forces():
    rows = []
    with open("postProcessing/forceCoeffs/0/coefficient.dat") as f:
        for line in f:
            if line.startswith("#"):
                header = line[1:].split()
                continue
            rows.append([float(v) for v in line.split()])
    col = {name: i for i, name in enumerate(header)}
    rows = [r for r in rows if r[0] > 0.05]          # skip the impulsive start
    t = [r[0] for r in rows]
    fig, ax = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    ax[0].plot(t, [math.degrees(AMPLITUDE*math.sin(OMEGA*x)) for x in t])
    ax[0].set_ylabel("pitch angle [deg]")
    ax[1].plot(t, [r[col["Cl"]] for r in rows])
    ax[1].set_ylabel("Cl")
    ax[2].plot(t, [r[col["CmPitch"]] for r in rows])
    ax[2].set_ylabel("Cm (quarter chord)")
    ax[2].set_xlabel("t [s]")
    for a in ax:
        a.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig("images/forces.png", dpi=110)


def main():
    os.makedirs("images", exist_ok=True)
    faces = [list(map(int, m.split()))
             for m in read_list("constant/polyMesh/faces", r"\d+\(([0-9 ]+)\)")]
    plot_mesh(faces)
    plot_forces()
    print("wrote images/mesh.png and images/forces.png")


if __name__ == "__main__":
    main()
