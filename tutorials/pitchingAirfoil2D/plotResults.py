#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Pictures of the pitchingAirfoil2D results (matplotlib, no ParaView needed).

images/mesh.png:   the mesh near the airfoil at t = 0 and at the largest
                   nose-up and nose-down pitch angles (front plane edges);
images/forces.png: pitch angle, lift and moment coefficients over time;
images/forcesVsRigid.png: Cl(t), Cm(t) of dcpRBF and of the rigidly rotating
                   reference (rigid/), and their difference.

Agreement (printed, and the exit status): over the window t >= --from,
max|Cl_dcp - Cl_rigid| / max|Cl_rigid|, the same for Cm (the rigid values
interpolated linearly at the dcpRBF times); exit 1 if either exceeds
--tolerance.

Reads the ascii polyMesh files written by the run (writeFormat ascii).
"""
import argparse
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from forceCoeffs import interpolate, read_coefficients  # noqa: E402

import matplotlib                                       # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt                         # noqa: E402
from matplotlib.collections import LineCollection      # noqa: E402

AMPLITUDE, OMEGA = math.radians(6), 0.2   # as in 0.orig/pointDisplacement


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
    angle = {t: AMPLITUDE*math.sin(OMEGA*t) for t, _ in time_dirs() if t > 0}
    extremes = []
    if angle:
        up, down = max(angle, key=angle.get), min(angle, key=angle.get)
        extremes = [t for t, ok in ((up, angle[up] > 1e-3), (down, angle[down] < -1e-3)) if ok]
    shots = [(0.0, "constant/polyMesh/points")]
    for t in sorted(set(extremes), key=lambda x: -angle[x]):
        name = [d for tt, d in time_dirs() if tt == t][0]
        shots.append((t, os.path.join(name, "polyMesh/points")))

    fig, axes = plt.subplots(1, len(shots), figsize=(5*len(shots), 5), sharey=True,
                             squeeze=False)
    axes = axes[0]
    for ax, (t, path) in zip(axes, shots):
        ax.add_collection(LineCollection(front_edges(read_points(path), faces),
                                         linewidths=0.4, colors="k"))
        vtk = "postProcessing/dcpRBF/controlPoints_%g.vtk" % t
        if os.path.exists(vtk):
            cp = read_vtk_points(vtk)
            ax.plot([p[0] for p in cp], [p[1] for p in cp], "o", color="tab:red",
                    markersize=3, label="%d control points" % len(cp))
            ax.legend(loc="upper right", fontsize=8)
        ax.set_xlim(-0.15, 0.45)
        ax.set_ylim(-0.2, 0.2)
        ax.set_aspect("equal")
        ax.set_title("t = %g s, pitch %+.2f deg" % (t, math.degrees(angle.get(t, 0))))
    fig.suptitle("dcpRBF (dynamic control points): NACA0012 pitching +-6 deg"
                 " about the quarter chord (leading edge, boundary layer)")
    fig.tight_layout()
    fig.savefig("images/mesh.png", dpi=110)


def compare_rigid(t_from, tolerance):
    """dcpRBF vs the rigidly rotating reference: picture and agreement."""
    dcp, col = read_coefficients()
    rig, rcol = read_coefficients("rigid")
    t_end = min(dcp[-1][0], rig[-1][0])
    window = [r for r in dcp if t_from <= r[0] <= t_end + 1e-9]
    if len(window) < 2:
        print("dcpRBF vs rigid: fewer than 2 samples in t = [%g, %g]" % (t_from, t_end))
        return False
    rt = [r[0] for r in rig]
    t = [r[0] for r in window]
    ok = True
    fig, ax = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    result = []
    for i, name in enumerate(("Cl", "CmPitch")):
        ry = [r[rcol[name]] for r in rig]
        y = [r[col[name]] for r in window]
        yr = [interpolate(rt, ry, x) for x in t]
        diff = max(abs(a - b) for a, b in zip(y, yr))
        scale = max(abs(b) for b in yr)
        rel = diff/scale if scale > 0 else float("inf")
        ok = ok and rel <= tolerance
        result.append("%s max|diff| %.3g = %.2f %% of max|%s_rigid| %.3g"
                      % (name, diff, 100*rel, name, scale))
        ax[i].plot(rt, ry, "k-", lw=2.5, alpha=0.4, label="rigid mesh rotation")
        ax[i].plot([r[0] for r in dcp], [r[col[name]] for r in dcp], "r-", lw=1,
                   label="dcpRBF")
        ax[i].set_ylabel(name if name == "Cl" else "Cm (quarter chord)")
        ax[i].legend(fontsize=8)
        ax[2].plot(t, [100*(a - b)/scale for a, b in zip(y, yr)],
                   label="%s (%% of max|%s_rigid|)" % (name, name))
    ax[2].axvline(t_from, color="grey", ls=":", lw=1)
    ax[2].set_ylabel("dcpRBF - rigid [%]")
    ax[2].set_xlabel("t [s]")
    ax[2].legend(fontsize=8)
    for a in ax:
        a.grid(True, alpha=0.3)
    fig.suptitle("dcpRBF vs whole-mesh rigid rotation (same motion, mesh, numerics)")
    fig.tight_layout()
    fig.savefig("images/forcesVsRigid.png", dpi=110)
    print("dcpRBF vs rigid over t = [%g, %g] (%d steps): %s, %s: %s (tolerance %g %%)"
          % (t_from, t_end, len(window), result[0], result[1],
             "agree" if ok else "DISAGREE", 100*tolerance))
    return ok


def plot_forces():
    rows, col = read_coefficients()
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
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tolerance", type=float, default=0.02,
                    help="largest relative difference dcpRBF vs rigid (0.02: 2 %%)")
    ap.add_argument("--from", dest="t_from", type=float, default=1.0,
                    help="compare from this time on (skips the impulsive start)")
    a = ap.parse_args()
    os.makedirs("images", exist_ok=True)
    faces = [list(map(int, m.split()))
             for m in read_list("constant/polyMesh/faces", r"\d+\(([0-9 ]+)\)")]
    plot_mesh(faces)
    plot_forces()
    print("wrote images/mesh.png and images/forces.png")
    if os.path.isdir("rigid"):
        ok = compare_rigid(a.t_from, a.tolerance)
        print("wrote images/forcesVsRigid.png")
        if not ok:
            sys.exit(1)


if __name__ == "__main__":
    main()
