# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The force coefficients of a case (forceCoeffs' coefficient.dat) and the
linear interpolation that puts a reference's on another case's times, for
the tutorials' comparisons with a rigidly moving mesh
(pitchingAirfoil2D/plotResults.py, flappingWing3D/plotResults.py,
flap3D/flow/plotFlow.py)."""
import os


def read_coefficients(case=".", start="0"):
    """Rows of forceCoeffs' coefficient.dat (of the run started at start)
    and a name -> column map."""
    rows, header = [], []
    with open(os.path.join(case, "postProcessing/forceCoeffs", start, "coefficient.dat")) as f:
        for line in f:
            if line.startswith("#"):
                header = line[1:].split()
                continue
            rows.append([float(v) for v in line.split()])
    return rows, {name: i for i, name in enumerate(header)}


def interpolate(ts, ys, t):
    """Linear interpolation of ys(ts) at t (ts increasing)."""
    lo, hi = 0, len(ts) - 1
    if t <= ts[lo]:
        return ys[lo]
    if t >= ts[hi]:
        return ys[hi]
    while hi - lo > 1:
        mid = (lo + hi)//2
        if ts[mid] <= t:
            lo = mid
        else:
            hi = mid
    w = (t - ts[lo])/(ts[hi] - ts[lo])
    return (1 - w)*ys[lo] + w*ys[hi]
