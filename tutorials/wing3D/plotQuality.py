#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Minimum cell quality against time for the runs of ./Allrun -selections
(selection/<mode>/postProcessing/dcpRBF/0/dcpRBF.dat, column minQuality):
images/minQuality.png, and a line per mode: lowest quality, control points.

Usage: plotQuality.py [--output images/minQuality.png]
"""
import argparse
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt                 # noqa: E402
import numpy as np                              # noqa: E402

COLUMNS = ("time nControl nAdded nRemoved nGuard nCells minQuality meanQuality "
           "boundaryError atMaxPoints swapTime selectTime interpolateTime guardTime").split()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--output", default="images/minQuality.png")
    a = ap.parse_args()

    fig, ax = plt.subplots(figsize=(6.5, 4))
    for mode, style in (("all", "k-"), ("greedy", "b--"), ("dynamic", "r-.")):
        path = os.path.join("selection", mode, "postProcessing", "dcpRBF", "0", "dcpRBF.dat")
        if not os.path.exists(path):
            continue
        d = np.loadtxt(path, comments="#", ndmin=2)
        col = {c: d[:, COLUMNS.index(c)] for c in COLUMNS}
        t, q = col["time"], col["minQuality"]
        ax.plot(t, q, style, label="%s (%d-%d control points)"
                % (mode, col["nControl"].min(), col["nControl"].max()))
        print("%-8s lowest minQuality %.4f at t = %g, control points %d-%d, "
              "boundary error max %.2e"
              % (mode, q.min(), t[q.argmin()], col["nControl"].min(), col["nControl"].max(),
                 col["boundaryError"].max()))
    ax.set_xlabel("t [s]")
    ax.set_ylabel("minimum cell quality (sizeShape, 1 = initial)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(a.output) or ".", exist_ok=True)
    fig.savefig(a.output, dpi=100)
    print("plotQuality: " + a.output)


if __name__ == "__main__":
    main()
