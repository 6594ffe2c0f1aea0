#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Coarse 2D mesh of a NACA0012 airfoil (chord 1, leading edge at the origin)
in a rectangular channel, one cell thick (prisms), written for gmshToFoam.

Patches: wing, inlet (x = -xUp), outlet (x = xDown), topAndBottom (y = +-h),
frontAndBack (z = 0 and z = span).

Usage: naca0012Mesh.py [output.msh] [--size-wing 0.02] [--size-far 0.6]
"""
import argparse
import functools
import math
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from airfoilChannel import extrude_and_name, naca0012 as naca0012Law  # noqa: E402

naca0012 = functools.partial(naca0012Law, closed_trailing_edge=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output", nargs="?", default="airfoil.msh")
    ap.add_argument("--size-wing", type=float, default=0.02)
    ap.add_argument("--size-far", type=float, default=0.6)
    ap.add_argument("--x-up", type=float, default=5.0)
    ap.add_argument("--x-down", type=float, default=10.0)
    ap.add_argument("--half-height", type=float, default=5.0)
    ap.add_argument("--span", type=float, default=0.1)
    a = ap.parse_args()

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("naca0012")
    geo = gmsh.model.geo

    # Airfoil: cosine-spaced stations, upper and lower splines
    n = 60
    xs = [0.5*(1 - math.cos(math.pi*i/n)) for i in range(n + 1)]
    le = geo.addPoint(0, 0, 0, a.size_wing)
    te = geo.addPoint(1, 0, 0, a.size_wing)
    upper = [te] + [geo.addPoint(x, naca0012(x), 0, a.size_wing)
                    for x in reversed(xs[1:-1])] + [le]
    lower = [le] + [geo.addPoint(x, -naca0012(x), 0, a.size_wing)
                    for x in xs[1:-1]] + [te]
    wing = [geo.addSpline(upper), geo.addSpline(lower)]

    # Channel
    h, xu, xd = a.half_height, a.x_up, a.x_down
    c = [geo.addPoint(-xu, -h, 0, a.size_far), geo.addPoint(xd, -h, 0, a.size_far),
         geo.addPoint(xd, h, 0, a.size_far), geo.addPoint(-xu, h, 0, a.size_far)]
    bottom, outlet, top, inlet = (geo.addLine(c[i], c[(i + 1) % 4]) for i in range(4))
    outer = geo.addCurveLoop([bottom, outlet, top, inlet])
    inner = geo.addCurveLoop(wing)
    surface = geo.addPlaneSurface([outer, inner])
    geo.synchronize()

    # Grade the size away from the wing
    dist = gmsh.model.mesh.field.add("Distance")
    gmsh.model.mesh.field.setNumbers(dist, "EdgesList", wing)
    gmsh.model.mesh.field.setNumber(dist, "NumPointsPerCurve", 200)
    thr = gmsh.model.mesh.field.add("Threshold")
    gmsh.model.mesh.field.setNumber(thr, "InField", dist)
    gmsh.model.mesh.field.setNumber(thr, "SizeMin", a.size_wing)
    gmsh.model.mesh.field.setNumber(thr, "SizeMax", a.size_far)
    gmsh.model.mesh.field.setNumber(thr, "DistMin", 0.05)
    gmsh.model.mesh.field.setNumber(thr, "DistMax", 4.0)
    gmsh.model.mesh.field.setAsBackgroundMesh(thr)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.Algorithm", 6)

    # One cell thick, patches named (tutorials/common/airfoilChannel.py)
    extrude_and_name(geo, surface, a.span, 2)

    gmsh.model.mesh.generate(3)
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.write(a.output)
    gmsh.finalize()


if __name__ == "__main__":
    main()
