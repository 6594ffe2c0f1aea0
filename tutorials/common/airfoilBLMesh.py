#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Wall-resolved 2D mesh of a NACA0012 airfoil (chord 1, leading edge at the
origin) with a structured boundary layer, in a rectangular channel, one cell
thick (hexahedra in the layer, prisms outside), written for gmshToFoam.

Patches: wing, inlet (x = -xUp), outlet (x = xDown), topAndBottom (y = +-h),
frontAndBack (z = 0 and z = span).

Boundary layer: gmsh's BoundaryLayer field (quads) on the whole wing, first
cell height --first-layer, growth --growth, --layers layers; the trailing edge
is blunt (the standard NACA0012 thickness law, 0.25 % chord at x = 1) and the
layer turns round its two corners with fans (degenerate quads, prisms after
the extrusion).

First cell height: y+ = 1 at Re = 1e6 (chord 1) is about y = c / (Re sqrt(Cf/2))
= 2.3e-5 c with the flat-plate skin friction Cf = 0.0592 Re^-0.2 = 0.0037; the
default 1.5e-5 c leaves margin for the suction peak (local velocity up to 1.5 U).
With 30 layers at growth 1.2 the layer is 1.8e-2 c thick and its outer cells
(3e-3 c) meet triangles 2.5 times higher (7.5e-3 c at mid chord, --size-wing 0.01).
Defaults: 17738 cells (8154 hexahedra, 9584 prisms), Mesh OK in checkMesh.

Usage: airfoilBLMesh.py [output.msh] [--first-layer 1.5e-5] [--layers 30] ...
"""
import argparse
import functools
import math
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from airfoilChannel import extrude_and_name, naca0012 as naca0012Law  # noqa: E402

naca0012 = functools.partial(naca0012Law, closed_trailing_edge=False)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output", nargs="?", default="airfoilBL.msh")
    ap.add_argument("--first-layer", type=float, default=1.5e-5,
                    help="first cell height at the wall (chords)")
    ap.add_argument("--layers", type=int, default=30, help="number of layers")
    ap.add_argument("--growth", type=float, default=1.2, help="layer growth ratio")
    ap.add_argument("--size-wing", type=float, default=0.01,
                    help="largest cell length along the wing (mid chord)")
    ap.add_argument("--size-le", type=float, default=None,
                    help="cell length along the wing at the leading edge "
                         "(default size-wing/5)")
    ap.add_argument("--size-te", type=float, default=None,
                    help="cell length along the wing at the trailing edge "
                         "(default size-wing/4)")
    ap.add_argument("--size-far", type=float, default=0.25)
    ap.add_argument("--x-up", type=float, default=3.0,
                    help="inlet at x = -x-up (leading edge at 0)")
    ap.add_argument("--x-down", type=float, default=5.0, help="outlet at x = x-down")
    ap.add_argument("--half-height", type=float, default=2.0,
                    help="channel walls at y = +-half-height (pivot at y = 0)")
    ap.add_argument("--span", type=float, default=0.1)
    ap.add_argument("--only-2d", action="store_true", help=argparse.SUPPRESS)
    a = ap.parse_args()
    hLE = a.size_le or a.size_wing/5
    hTE = a.size_te or a.size_wing/4
    thickness = a.first_layer*(a.growth**a.layers - 1)/(a.growth - 1)

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("naca0012BL")
    geo = gmsh.model.geo

    # Airfoil: cosine-spaced stations, upper and lower splines, blunt base
    n = 120
    xs = [0.5*(1 - math.cos(math.pi*i/n)) for i in range(n + 1)]
    le = geo.addPoint(0, 0, 0, hLE)
    teU = geo.addPoint(1, naca0012(1), 0, hTE)
    teL = geo.addPoint(1, -naca0012(1), 0, hTE)
    upper = [teU] + [geo.addPoint(x, naca0012(x), 0, a.size_wing)
                     for x in reversed(xs[1:-1])] + [le]
    lower = [le] + [geo.addPoint(x, -naca0012(x), 0, a.size_wing)
                    for x in xs[1:-1]] + [teL]
    wing = [geo.addSpline(upper), geo.addSpline(lower), geo.addLine(teL, teU)]

    # Channel
    h, xu, xd = a.half_height, a.x_up, a.x_down
    c = [geo.addPoint(-xu, -h, 0, a.size_far), geo.addPoint(xd, -h, 0, a.size_far),
         geo.addPoint(xd, h, 0, a.size_far), geo.addPoint(-xu, h, 0, a.size_far)]
    bottom, outlet, top, inlet = (geo.addLine(c[i], c[(i + 1) % 4]) for i in range(4))
    outer = geo.addCurveLoop([bottom, outlet, top, inlet])
    inner = geo.addCurveLoop(wing)
    surface = geo.addPlaneSurface([outer, inner])
    # a few cells across the blunt base
    geo.mesh.setTransfiniteCurve(wing[2], max(3, 1 + round(2*naca0012(1)/hTE*4)))
    geo.synchronize()

    # Cell length along the wing: finest at the leading and trailing edges
    field = gmsh.model.mesh.field
    sizes = []
    for pts, hmin in (([le], hLE), ([teU, teL], hTE)):
        d = field.add("Distance")
        field.setNumbers(d, "PointsList", pts)
        t = field.add("Threshold")
        field.setNumber(t, "InField", d)
        field.setNumber(t, "SizeMin", hmin)
        field.setNumber(t, "SizeMax", a.size_wing)
        field.setNumber(t, "DistMin", 0.0)
        field.setNumber(t, "DistMax", 0.15)
        field.setNumber(t, "StopAtDistMax", 1)
        sizes.append(t)
    # ... and graded away from the wing to size-far
    d = field.add("Distance")
    field.setNumbers(d, "CurvesList", wing)
    field.setNumber(d, "NumPointsPerCurve", 400)
    t = field.add("Threshold")
    field.setNumber(t, "InField", d)
    field.setNumber(t, "SizeMin", a.size_wing)
    field.setNumber(t, "SizeMax", a.size_far)
    field.setNumber(t, "DistMin", thickness)
    field.setNumber(t, "DistMax", 0.6*h)
    sizes.append(t)
    m = field.add("Min")
    field.setNumbers(m, "FieldsList", sizes)
    field.setAsBackgroundMesh(m)

    # Structured layer: quads, fans round the two trailing-edge corners
    bl = field.add("BoundaryLayer")
    field.setNumbers(bl, "CurvesList", wing)
    field.setNumbers(bl, "FanPointsList", [teU, teL])
    field.setNumber(bl, "Size", a.first_layer)
    field.setNumber(bl, "Ratio", a.growth)
    # a hair above the sum of the layers so that exactly --layers are made
    field.setNumber(bl, "Thickness", thickness*(1 + 0.5*(a.growth - 1)/a.growth**a.layers))
    field.setNumber(bl, "SizeFar", a.size_far)
    field.setNumber(bl, "Quads", 1)
    field.setAsBoundaryLayer(bl)

    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.Algorithm", 6)

    # One cell thick, patches named (tutorials/common/airfoilChannel.py)
    extrude_and_name(geo, surface, a.span, 3)

    gmsh.model.mesh.generate(2 if a.only_2d else 3)
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.write(a.output)
    gmsh.finalize()


if __name__ == "__main__":
    main()
