#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""sixDoFAirfoil2D: dcpRBF vs OpenFOAM's sixDoFRigidBodyMotion solver.

Reads the body's state reported at every step (report on) from
log.pimpleFoam (dcpRBF) and stock/log.pimpleFoam (stock solver), the
checkMesh logs of the written times and dcpRBF's time series
(postProcessing/dcpRBF/0/dcpRBF.dat); writes images/trajectory.png (heave
and pitch vs time, both solvers) and prints a summary: largest trajectory
difference, worst checkMesh values, dcpRBF minimum cell quality, time per step.
"""
import math
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt                         # noqa: E402

Y0 = 0.007          # centre of rotation at rest, y (0.orig/pointDisplacement)
VEC = r"\(([-+0-9.eE]+(?: [-+0-9.eE]+)*)\)"


def trajectory(log):
    """Time, heave (m), pitch (deg, nose up positive) and the CPU clock per step."""
    t, heave, pitch, clock = [], [], [], []
    time = None
    with open(log) as f:
        for line in f:
            if line.startswith("Time = "):
                time = float(line.split()[2])
            elif line.startswith("    Centre of rotation:") and time is not None:
                c = [float(v) for v in re.search(VEC, line).group(1).split()]
                cr = c[1] - Y0
            elif line.startswith("    Orientation:") and time is not None:
                q = [float(v) for v in re.search(VEC, line).group(1).split()]
                # Q maps body to global axes; nose up = clockwise about +z
                th = -math.degrees(math.atan2(q[3], q[0]))
                if t and t[-1] == time:      # several reports in a step: the last
                    heave[-1], pitch[-1] = cr, th
                else:
                    t.append(time)
                    heave.append(cr)
                    pitch.append(th)
            elif line.startswith("ExecutionTime = "):
                clock.append(float(line.split()[2]))
    return t, heave, pitch, clock


def check_mesh(log):
    """Written times checked, times OK, worst non-orthogonality and skewness."""
    n = ok = 0
    nonOrth = skew = 0.0
    with open(log) as f:
        for line in f:
            if line.startswith("Time = "):
                n += 1
            elif line.startswith("Mesh OK"):
                ok += 1
            m = re.search(r"non-orthogonality Max: ([0-9.eE+-]+)", line)
            if m:
                nonOrth = max(nonOrth, float(m.group(1)))
            m = re.search(r"Max skewness = ([0-9.eE+-]+)", line)
            if m:
                skew = max(skew, float(m.group(1)))
    return n, ok, nonOrth, skew


def dcp_series(path="postProcessing/dcpRBF/0/dcpRBF.dat"):
    rows, col = [], {}
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                col = {name: i for i, name in enumerate(line[1:].split())}
                continue
            if line.strip():
                rows.append([float(v) for v in line.split()])
    return rows, col


def per_step(clock):
    """Mean CPU seconds per step, the first step (set-up) left out."""
    if len(clock) < 3:
        return float("nan")
    return (clock[-1] - clock[0])/(len(clock) - 1)


def main():
    os.makedirs("images", exist_ok=True)
    td, hd, pd, cd = trajectory("log.pimpleFoam")
    ts, hs, ps, cs = trajectory("stock/log.pimpleFoam")
    n = min(len(td), len(ts))
    dh = max(abs(a - b) for a, b in zip(hd[:n], hs[:n]))
    dp = max(abs(a - b) for a, b in zip(pd[:n], ps[:n]))
    hmax = max(abs(v) for v in hs[:n])
    pmax = max(abs(v) for v in ps[:n])

    fig, ax = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True)
    ax[0].plot(ts, [1000*v for v in hs], "k-", lw=2.5, alpha=0.4, label="sixDoFRigidBodyMotion (stock)")
    ax[0].plot(td, [1000*v for v in hd], "r-", lw=1, label="dcpRBF + sixDoFRigidBodyDisplacement")
    ax[0].set_ylabel("heave [mm]")
    ax[1].plot(ts, ps, "k-", lw=2.5, alpha=0.4, label="sixDoFRigidBodyMotion (stock)")
    ax[1].plot(td, pd, "r-", lw=1, label="dcpRBF + sixDoFRigidBodyDisplacement")
    ax[1].set_ylabel("pitch, nose up [deg]")
    ax[1].set_xlabel("t [s]")
    for a in ax:
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8)
    fig.suptitle("Spring-mounted NACA0012, 10 m/s: body trajectory")
    fig.tight_layout()
    fig.savefig("images/trajectory.png", dpi=110)

    print("sixDoFAirfoil2D: %d steps (dcpRBF), %d steps (stock), t = %g s"
          % (len(td), len(ts), td[-1] if td else 0))
    print("  heave: range [%.2f, %.2f] mm; max |dcpRBF - stock| %.3g mm (%.2f %% of max|heave|)"
          % (1000*min(hs), 1000*max(hs), 1000*dh, 100*dh/hmax if hmax else 0))
    print("  pitch: range [%.2f, %.2f] deg; max |dcpRBF - stock| %.3g deg (%.2f %% of max|pitch|)"
          % (min(ps), max(ps), dp, 100*dp/pmax if pmax else 0))
    for name, log in (("dcpRBF", "log.checkMesh.moved"), ("stock ", "stock/log.checkMesh.moved")):
        nT, ok, no, sk = check_mesh(log)
        print("  checkMesh %s: %d of %d written times OK, worst max non-orthogonality %.2f,"
              " worst max skewness %.3f" % (name, ok, nT, no, sk))
    rows, col = dcp_series()
    qmin = min(r[col["minQuality"]] for r in rows)
    motion = sum(r[col[k]] for r in rows for k in
                 ("swapTime", "selectTime", "interpolateTime", "guardTime",
                  "measureTime") if k in col)/len(rows)
    print("  dcpRBF: min cell quality %.4f, control points %d -> %d, mesh motion %.2f ms per step"
          % (qmin, rows[0][col["nControl"]], rows[-1][col["nControl"]], 1000*motion))
    print("  CPU time per step (ExecutionTime; both cases side by side on a shared machine):"
          " dcpRBF %.1f ms, stock %.1f ms" % (1000*per_step(cd), 1000*per_step(cs)))
    print("wrote images/trajectory.png")


if __name__ == "__main__":
    main()
