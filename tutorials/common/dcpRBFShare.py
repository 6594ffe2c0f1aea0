# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""dcpRBF's share of a flow solver's run: its newPoints() (the times of
postProcessing/dcpRBF/0/dcpRBF.dat, summed over the steps) over the
solver's ExecutionTime (the log's last), for the tutorials under pimpleFoam
(flappingWing3D/plotResults.py, flap3D/flow/plotFlow.py)."""
import os
import re

COLUMNS = ("swapTime", "selectTime", "interpolateTime", "guardTime", "pointsTime", "measureTime")


def share(case=".", solver="pimpleFoam"):
    """(newPoints() seconds, steps, solver seconds) of the run in case, or
    None if its dcpRBF.dat or log.<solver> is missing."""
    dat = os.path.join(case, "postProcessing/dcpRBF/0/dcpRBF.dat")
    log = os.path.join(case, "log." + solver)
    if not os.path.exists(dat) or not os.path.exists(log):
        return None
    header, total, n = [], 0.0, 0
    for line in open(dat):
        if line.startswith("#"):
            header = line[1:].split()
            continue
        v = line.split()
        total += sum(float(v[header.index(c)]) for c in COLUMNS)
        n += 1
    run = re.findall(r"^ExecutionTime = (\S+) s", open(log).read(), re.M)
    if not run or not n:
        return None
    return total, n, float(run[-1])


def describe(measured, solver="pimpleFoam"):
    """share()'s result as a sentence."""
    total, n, run = measured
    return ("newPoints() %.3f s in %d steps, %.2f ms a step, %.2f %% of %s's %.1f s"
            % (total, n, 1000*total/n, 100*total/run, solver, run))
