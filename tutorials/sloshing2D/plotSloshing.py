# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""sloshing2D, stock against dcpRBF: the wave's height at the left wall over
time (interfaceTrackingFvMesh's history/0/leftPoint.txt) and the meshes at
the last written time. Prints the largest difference of the heights and of
the free surface's points; writes images/waveHeight.png and images/mesh.png.
The heights agree when their largest difference is within TOL (1 %) of the
largest rise; exit status 1 where they do not.

    python3 plotSloshing.py [TOL]      (after ./Allrun)
"""
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt                         # noqa: E402
from matplotlib.collections import LineCollection      # noqa: E402

RUNS = ("stock", "dcpRBF")


def history(run):
    """(time, height) at the left wall."""
    t, y = [], []
    with open(os.path.join(run, "history", "0", "leftPoint.txt")) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = line.split()
            t.append(float(v[0]))
            y.append(float(v[2]))
    return t, y


def body(path):
    text = open(path).read()
    return text[text.index("}", text.index("FoamFile")) + 1:]


def points(path):
    return [tuple(map(float, m.groups())) for m in
            re.finditer(r"\(([-0-9.eE+]+) ([-0-9.eE+]+) ([-0-9.eE+]+)\)", body(path))]


def faces(run):
    return [list(map(int, m.group(1).split())) for m in
            re.finditer(r"\d+\(([\d ]+)\)", body(os.path.join(run, "constant", "polyMesh", "faces")))]


def patch(run, name):
    b = body(os.path.join(run, "constant", "polyMesh", "boundary"))
    m = re.search(r"\b%s\s*\{([^}]*)\}" % name, b)
    d = dict(re.findall(r"(\w+)\s+([^;]+);", m.group(1)))
    return int(d["startFace"]), int(d["nFaces"])


def last_time(run):
    times = [d for d in os.listdir(run)
             if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0
             and os.path.isfile(os.path.join(run, d, "polyMesh", "points"))]
    return max(times, key=float)


def main():
    os.makedirs("images", exist_ok=True)
    curves = {run: history(run) for run in RUNS}
    (t0, y0), (t1, y1) = curves["stock"], curves["dcpRBF"]
    n = min(len(y0), len(y1))
    amplitude = max(abs(v - y0[0]) for v in y0[:n])
    diff = max(abs(a - b) for a, b in zip(y0[:n], y1[:n]))
    tol = float(sys.argv[1]) if len(sys.argv) > 1 else 0.01
    agree = n > 1 and diff <= tol*amplitude
    print("wave height at the left wall, %d steps to t = %g: largest |dcpRBF - stock| %.3g m"
          " (%.2f %% of the largest rise, %.3g m): %s (tolerance %g %%)"
          % (n - 1, t0[n - 1], diff, 100*diff/amplitude, amplitude,
             "agree" if agree else "disagree", 100*tol))

    fig, ax = plt.subplots(figsize=(7, 3.5))
    for run, style in zip(RUNS, ("-", "--")):
        t, y = curves[run]
        ax.plot(t, y, style, label="%s (%s)" % (run, "velocityLaplacian" if run == "stock" else "one word"))
    ax.set_xlabel("t [s]")
    ax.set_ylabel("free surface at the left wall [m]")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join("images", "waveHeight.png"), dpi=120)

    # the meshes at the last written time: the front plane's faces
    t = last_time("stock")
    f = faces("stock")
    start, count = patch("stock", "frontAndBack")
    top = patch("stock", "top")
    fig, axes = plt.subplots(1, 2, figsize=(10, 5), sharey=True)
    moved = {}
    for ax, run in zip(axes, RUNS):
        p = points(os.path.join(run, t, "polyMesh", "points"))
        moved[run] = p
        zmax = max(q[2] for q in p)
        polys = [[(p[i][0], p[i][1]) for i in face + face[:1]]
                 for face in f[start:start + count] if all(p[i][2] > zmax - 1e-9 for i in face)]
        ax.add_collection(LineCollection(polys, linewidths=0.3, colors="k"))
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_title("%s at t = %s" % (run, t))
    fig.tight_layout()
    fig.savefig(os.path.join("images", "mesh.png"), dpi=120)

    surface = {i for face in f[top[0]:top[0] + top[1]] for i in face}
    a, b = moved["stock"], moved["dcpRBF"]
    dist = max(sum((x - y)**2 for x, y in zip(a[i], b[i]))**0.5 for i in surface)
    print("free surface's points at t = %s: largest |dcpRBF - stock| %.3g m" % (t, dist))
    return 0 if agree else 1


if __name__ == "__main__":
    sys.exit(main())
