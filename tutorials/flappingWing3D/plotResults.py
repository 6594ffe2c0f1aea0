#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Pictures of the flappingWing3D results (matplotlib, no ParaView needed)
and the agreement with the rigidly turning reference (rigid/).

images/cut.png:    the mesh cut by the plane x = 0.25 m (through the pivot,
                   across the span) at rest and at the largest flapping and
                   pitch angles written (t = T/4, 3T/4, ...);
images/forces.png: the angles, Cl(t) and Cd(t) of dcpRBF and of the
                   reference, and their difference.

Agreement (printed, and the exit status): over each whole period that both
runs cover after the first (the impulsive start), the peaks (largest and
smallest value) and the period mean of Cl and Cd, and the largest pointwise
difference; each difference over the reference's largest |value| in that
period; exit 1 if a peak or a mean differs by more than --tolerance. A run
shorter than two periods (the tests) is compared point by point from t =
--from on instead, against the same tolerance. Also
dcpRBF's share of the run (newPoints(): the times of postProcessing/dcpRBF's
dcpRBF.dat over the solver's ExecutionTime).
"""
import argparse
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from dcpRBFShare import describe, share  # noqa: E402
from forceCoeffs import interpolate, read_coefficients  # noqa: E402
from meshCut import plotCuts  # noqa: E402

import matplotlib                                       # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt                         # noqa: E402


def kinematics():
    """(flap amplitude, pitch amplitude) [deg] and omega [rad/s], read from
    constant/wingKinematics (the one place they are written)."""
    text = open("constant/wingKinematics").read()
    amp = [tuple(float(v) for v in m.split())
           for m in re.findall(r"amplitude\s+\(([^)]*)\)", text)]
    omega = float(re.search(r"omega\s+([-0-9.eE+]+)", text).group(1))
    return amp[0][0], amp[1][1], omega


def written_times():
    times = []
    for d in os.listdir("."):
        try:
            times.append((float(d), d))
        except ValueError:
            pass
    return sorted(t for t in times if t[0] > 0)


def plot_cut(omega):
    """The cut x = 0.25 at rest and at the written times nearest the first
    up and down extremes (t = T/4, 3T/4)."""
    period = 2*math.pi/omega
    times = written_times()
    shots = []
    for target in (period/4, 3*period/4):
        if times:
            t, name = min(times, key=lambda x: abs(x[0] - target))
            if abs(t - target) < period/16 and name not in shots:
                shots.append(name)
    plotCuts(shots, 0.25, (-0.5, 2.7, -2.2, 2.2), "images/cut.png", title="t = %s s",
             axis=0)


def period_stats(t, y, t0, t1):
    inside = [v for x, v in zip(t, y) if t0 - 1e-9 <= x <= t1 + 1e-9]
    return max(inside), min(inside), sum(inside)/len(inside)


def compare(omega, tolerance, t_from):
    dcp, col = read_coefficients()
    rig, rcol = read_coefficients("rigid")
    period = 2*math.pi/omega
    t_end = min(dcp[-1][0], rig[-1][0])
    t = [r[0] for r in dcp]
    rt = [r[0] for r in rig]
    ok = True
    fig, ax = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    flap, pitch, _ = kinematics()
    ax[0].plot(rt, [flap*math.sin(omega*x) for x in rt], label="flap (about x)")
    ax[0].plot(rt, [pitch*math.sin(omega*x) for x in rt], label="pitch (about y, nose up)")
    ax[0].set_ylabel("angle [deg]")
    ax[0].legend(fontsize=8)
    lines = []
    nPeriods = int((t_end + 1e-6)/period)
    for i, name in enumerate(("Cl", "Cd")):
        y = [r[col[name]] for r in dcp]
        ry = [r[rcol[name]] for r in rig]
        yr = [interpolate(rt, ry, x) for x in t]
        ax[1 + i].plot(rt, ry, "k-", lw=2.5, alpha=0.4, label="rigid mesh rotation")
        ax[1 + i].plot(t, y, "r-", lw=1, label="dcpRBF")
        # the impulsive start's spike (the first steps) off the scale
        late = [v for x, v in zip(t, y) if x >= min(t_from, 0.5*t_end)]
        pad = 0.05*(max(late) - min(late)) + 1e-9
        ax[1 + i].set_ylim(min(late) - pad, max(late) + pad)
        ax[1 + i].set_ylabel(name)
        ax[1 + i].legend(fontsize=8)
        for k in range(1, nPeriods):
            t0, t1 = k*period, (k + 1)*period
            mine, ref = period_stats(t, y, t0, t1), period_stats(t, yr, t0, t1)
            scale = max(abs(ref[0]), abs(ref[1]))
            rel = [abs(a - b)/scale for a, b in zip(mine, ref)]
            inside = [(a, b) for x, a, b in zip(t, y, yr) if t0 - 1e-9 <= x <= t1 + 1e-9]
            pointwise = max(abs(a - b) for a, b in inside)/scale
            ok = ok and max(rel) <= tolerance
            lines.append("%s period %d (t = %.3f .. %.3f): max %.4f / %.4f, min %.4f / %.4f, "
                         "mean %.4f / %.4f (dcpRBF / rigid); differences %.2f %%, %.2f %%, "
                         "%.2f %% of max|%s_rigid| %.4f; pointwise at most %.2f %%"
                         % (name, k + 1, t0, t1, mine[0], ref[0], mine[1], ref[1], mine[2],
                            ref[2], 100*rel[0], 100*rel[1], 100*rel[2], name, scale,
                            100*pointwise))
        scale = max(abs(v) for v in yr)
        if nPeriods < 2:
            inside = [(a, b) for x, a, b in zip(t, y, yr) if t_from <= x]
            wscale = max(abs(b) for _, b in inside)
            pointwise = max(abs(a - b) for a, b in inside)/wscale
            ok = ok and pointwise <= tolerance
            lines.append("%s over t = %g .. %g (%d steps): max|diff| %.2f %% of max|%s_rigid| "
                         "%.4f" % (name, t_from, t_end, len(inside), 100*pointwise, name, wscale))
        ax[3].plot(t, [100*(a - b)/scale for a, b in zip(y, yr)],
                   label="%s (%% of max|%s_rigid|)" % (name, name))
    ax[3].set_ylabel("dcpRBF - rigid [%]")
    ax[3].set_xlabel("t [s]")
    ax[3].legend(fontsize=8)
    for a in ax:
        a.grid(True, alpha=0.3)
        for k in range(1, nPeriods + 1):
            a.axvline(k*period, color="grey", ls=":", lw=1)
    fig.suptitle("flappingWing3D: dcpRBF vs the whole mesh turning rigidly")
    fig.tight_layout()
    fig.savefig("images/forces.png", dpi=100)
    for line in lines:
        print("dcpRBF vs rigid: " + line)
    print("dcpRBF vs rigid: %s (tolerance %g %% on the %s)"
          % ("agree" if ok else "DISAGREE", 100*tolerance,
             "peaks and means" if nPeriods >= 2 else "values, point by point"))
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tolerance", type=float, default=0.02,
                    help="largest difference of a peak or a mean, dcpRBF vs rigid (0.02: 2 %%)")
    ap.add_argument("--from", dest="t_from", type=float, default=0.1,
                    help="a run shorter than two periods: compare from this time on")
    a = ap.parse_args()
    os.makedirs("images", exist_ok=True)
    _, _, omega = kinematics()
    plot_cut(omega)
    print("wrote images/cut.png")
    measured = share()
    if measured:
        print("dcpRBF share: " + describe(measured))
    if os.path.isdir("rigid"):
        ok = compare(omega, a.tolerance, a.t_from)
        print("wrote images/forces.png")
        if not ok:
            sys.exit(1)


if __name__ == "__main__":
    main()
