#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""What moved and what did not, at every written time: the stator (beyond the
interface, and its side of it) must not move at all (dynamicMultiMotionSolverFvMesh
moves the rotor zone's points alone: a check of the set-up); the rotor's side of the
interface must be the reference turned about the axis by omega t (the AMI
stays intact); the AMI's weights and checkMesh over the whole run. One line
each, ending "ok" or "FAILED"; the exit code is 1 if any failed.

Usage: checkMotion.py [--case .] [--omega pi] [--tolerance 1e-12]
"""
import argparse
import math
import re
import sys

import numpy as np

import foamMesh


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default=".")
    ap.add_argument("--omega", type=float, default=math.pi)
    ap.add_argument("--tolerance", type=float, default=1e-12)
    a = ap.parse_args()

    p0 = foamMesh.points(a.case)
    r0 = np.hypot(p0[:, 0], p0[:, 1])
    statorSide = foamMesh.patchPoints(a.case, "amiStator")
    rotorSide = foamMesh.patchPoints(a.case, "amiRotor")
    stator = np.zeros(len(p0), bool)
    stator[r0 > 0.5 + 1e-9] = True
    stator[statorSide] = True
    ok = True

    times = foamMesh.times(a.case)
    if not times:
        print("no time written: FAILED")
        return 1
    statorMoved = 0.0
    sideOff = 0.0
    hubMoved = 0.0
    hub = foamMesh.patchPoints(a.case, "hub")
    for t in times:
        p = foamMesh.points(a.case, t)
        statorMoved = max(statorMoved, np.linalg.norm(p[stator] - p0[stator], axis=1).max())
        angle = a.omega*float(t)
        c, s = math.cos(angle), math.sin(angle)
        q = p0[rotorSide]
        turned = np.column_stack((c*q[:, 0] - s*q[:, 1], s*q[:, 0] + c*q[:, 1], q[:, 2]))
        sideOff = max(sideOff, np.linalg.norm(p[rotorSide] - turned, axis=1).max())
        h = p0[hub]
        turnedHub = np.column_stack((c*h[:, 0] - s*h[:, 1], s*h[:, 0] + c*h[:, 1], h[:, 2]))
        hubMoved = max(hubMoved, np.linalg.norm(p[hub] - turnedHub, axis=1).max())

    def say(text, good):
        nonlocal ok
        ok = ok and good
        print(text + (": ok" if good else ": FAILED"))

    say("stator: largest motion %.3g m over %d times" % (statorMoved, len(times)),
        statorMoved == 0)
    say("rotor's side of the interface: largest distance from the solid-body"
        " rotation %.3g m" % sideOff, sideOff <= a.tolerance)
    say("hub: largest motion in the rotor's frame %.3g m" % hubMoved, hubMoved > 1e-3)

    log = open(a.case + "/log.moveDynamicMesh").read()
    sums = [float(x) for x in re.findall(r"sum\(weights\) min:([0-9.eE+-]+)", log)]
    sums += [float(x) for x in re.findall(r"sum\(weights\) min:[0-9.eE+-]+ max:([0-9.eE+-]+)", log)]
    steps = len(re.findall(r"^Time = ", log, re.M))
    say("AMI: sum(weights) from %.6f to %.6f over %d steps" % (min(sums), max(sums), steps)
        if sums else "AMI: no weights in the log", bool(sums) and 0.99 < min(sums) and max(sums) < 1.01)
    checks = open(a.case + "/log.checkMesh.moved").read()
    nOk = len(re.findall(r"^Mesh OK", checks, re.M))
    say("checkMesh: Mesh OK at %d of %d written times" % (nOk, len(times)), nOk == len(times))
    quality = [float(x) for x in re.findall(r"quality min ([0-9.eE+-]+)", log)]
    say("dcpRBF: smallest cell quality %.4g over the run" % min(quality) if quality
        else "dcpRBF: no log line", bool(quality) and min(quality) > 0)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
