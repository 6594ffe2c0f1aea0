#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The flap3D flow results (Allrun): the comparisons, printed as lines that
start with "flow", and the pictures (matplotlib).

- serial vs parallel (par/) and the restart (restart/) vs the uninterrupted
  run: the largest differences of Cl, Cd and CmPitch over the steps both
  have (parallel: also over the last period, past the impulsive start),
  each relative to the serial run's largest |value|;
- the period means and peaks of the last whole period;
- dcpRBF's share of a step (serial and parallel);
- the flap held at 20 deg, steady (steady/): Cl, Cd and CmPitch on the
  mesh dcpRBF morphed and on three made at 20 deg (surface sizes varied),
  the morphed one's difference to their mean relative to the mean and to
  the flap's effect (20 deg vs at rest), beside the made ones' spread.

../images/flowForces.png: the deflection, Cl, Cd and CmPitch over the run
(serial, parallel, restart); ../images/flowMeshes.png: the mid-span cut
of the morphed and of the made mesh at 20 deg.

The comparisons are reported, not judged (the tests judge); the cases
missing (par/, restart/, steady/) are left out.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "common"))
from dcpRBFShare import describe, share  # noqa: E402
from forceCoeffs import read_coefficients  # noqa: E402
from meshCut import cut, readFaces, readPoints  # noqa: E402

import matplotlib                                       # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt                         # noqa: E402
from matplotlib.collections import LineCollection       # noqa: E402

NAMES = ("Cl", "Cd", "CmPitch")


def flapMotion():
    """The flap's amplitude [deg] and omega [rad/s] (constant/flapMotion)."""
    text = open(os.path.join("constant", "flapMotion")).read()
    amplitude = re.search(r"^amplitude\s+\(\s*\S+\s+(\S+)\s+\S+\s*\)", text, re.M)
    omega = re.search(r"^omega\s+([-0-9.eE+]+)", text, re.M)
    return float(amplitude.group(1)), float(omega.group(1))


AMPLITUDE, OMEGA = flapMotion()


def series(case=".", start="0"):
    """{time: (Cl, Cd, CmPitch)} of a run."""
    rows, col = read_coefficients(case, start)
    return {round(r[0], 6): tuple(r[col[n]] for n in NAMES) for r in rows}


def compare(what, ref, other, after=0.0):
    """The largest differences of other from ref over their common steps
    after t = after."""
    common = sorted(t for t in set(ref) & set(other) if t > after)
    if not common:
        print("flow %s: no common steps" % what)
        return
    parts = []
    for i, n in enumerate(NAMES):
        d = max(abs(other[t][i] - ref[t][i]) for t in common)
        scale = max(abs(ref[t][i]) for t in ref)
        parts.append("%s %.3g (%.2g of max |%s|)" % (n, d, d/scale, n))
    print("flow %s, %d steps from t = %g: largest differences %s"
          % (what, len(common), common[0], ", ".join(parts)))


def lastPeriod(ref):
    """The means and peaks of the last whole period."""
    period = 2*math.pi/OMEGA
    ts = sorted(ref)
    if ts[-1] < period:
        return
    window = [t for t in ts if t > ts[-1] - period + 1e-9]
    for i, n in enumerate(NAMES):
        v = [ref[t][i] for t in window]
        print("flow period t = %.2f .. %.2f s: %s mean %.4f, max %.4f, min %.4f"
              % (window[0], window[-1], n, sum(v)/len(v), max(v), min(v)))


def plotForces(runs):
    fig, ax = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    ref = runs[0][1]
    ts = sorted(ref)
    ax[0].plot(ts, [AMPLITUDE*math.sin(OMEGA*t) for t in ts], "k")
    ax[0].set_ylabel("flap [deg]\n(trailing edge down)")
    for label, run, style in runs:
        t = sorted(run)
        for i, n in enumerate(NAMES):
            ax[i + 1].plot(t, [run[s][i] for s in t], style, label=label, lw=1)
    for i, n in enumerate(NAMES):
        v = sorted(ref[t][i] for t in ts[len(ts)//20:])    # the impulsive start off the scale
        pad = 0.1*(v[-1] - v[0]) + 1e-9
        ax[i + 1].set_ylim(v[0] - pad, v[-1] + pad)
        ax[i + 1].set_ylabel(n)
    ax[1].legend(loc="upper right")
    ax[-1].set_xlabel("t [s]")
    fig.tight_layout()
    fig.savefig("../images/flowForces.png", dpi=72)


def steady():
    """The steady cases' last coefficients; the morphed mesh's against the
    meshes made at 20 deg (their mean and spread) and the flap's effect."""
    made = ("made", "madeSizeWing", "madeSizeHinge")
    cases = ("rest", "morphed") + made
    if not all(os.path.isdir(os.path.join("steady", c, "postProcessing")) for c in cases):
        return
    last = {}
    for c in cases:
        run = series(os.path.join("steady", c))
        it = max(run)
        last[c] = run[it]
        print("flow steady %-13s (%d iterations): %s" % (c, it, ", ".join(
            "%s %.5f" % (n, v) for n, v in zip(NAMES, last[c]))))
    for i, n in enumerate(NAMES):
        values = [last[c][i] for c in made]
        mean = sum(values)/len(values)
        d = last["morphed"][i] - mean
        effect = mean - last["rest"][i]
        print("flow steady %s: made at 20 deg %.5f .. %.5f (mean %.5f, spread %.2f %% of it); "
              "morphed - mean %.5f: %.2f %% of the mean, %.2f %% of the flap's effect %.5f"
              % (n, min(values), max(values), mean, 100*(max(values) - min(values))/abs(mean),
                 d, 100*d/abs(mean), 100*d/abs(effect), effect))
    plotMeshes()
    print("flow: wrote ../images/flowMeshes.png")


def plotMeshes():
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, c in zip(axes, ("morphed", "made")):
        mesh = os.path.join("steady", c, "constant", "polyMesh")
        P = readPoints(os.path.join(mesh, "points"))
        faces = [f for f in readFaces(os.path.join(mesh, "faces"))
                 if (abs(P[f, 1] - 1.0) < 0.3).any() and (abs(P[f, 0] - 0.85) < 0.6).any()]
        ax.add_collection(LineCollection(cut(P, faces, 1.0), linewidths=0.3, colors="k"))
        ax.set_xlim(0.35, 1.35)
        ax.set_ylim(-0.4, 0.4)
        ax.set_aspect("equal")
        ax.set_title("flap 20 deg, %s, cut y = 1 m" % ("morphed by dcpRBF" if c == "morphed"
                                                        else "mesh made there"))
        ax.set_xlabel("x [m]")
        ax.set_ylabel("z [m]")
    fig.tight_layout()
    fig.savefig("../images/flowMeshes.png", dpi=72)


def main():
    os.makedirs("../images", exist_ok=True)
    ref = series()
    runs = [("serial", ref, "k-")]
    if os.path.isdir("par/postProcessing"):
        par = series("par")
        compare("parallel vs serial", ref, par)
        period = 2*math.pi/OMEGA
        if max(ref) > period:
            compare("parallel vs serial, the last period", ref, par, max(ref) - period)
        runs.append(("2 processors", par, "r--"))
    starts = os.listdir("restart/postProcessing/forceCoeffs") if os.path.isdir(
        "restart/postProcessing/forceCoeffs") else []
    if starts:
        restart = series("restart", starts[0])
        compare("restart vs uninterrupted", ref, restart)
        runs.append(("restarted at t = %s" % starts[0], restart, "b:"))
    lastPeriod(ref)
    for what, case in (("serial", "."), ("2 processors", "par")):
        measured = share(case)
        if measured:
            print("flow dcpRBF share, %s: %s" % (what, describe(measured)))
    plotForces(runs)
    print("flow: wrote ../images/flowForces.png")
    steady()


if __name__ == "__main__":
    main()
