#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""ONERA M6 planform half wing (NACA 0010 sections) in a far-field box with a
symmetry plane at the root: prism layers on the wing, tetrahedra elsewhere,
written for gmshToFoam (msh 2.2).

Planform (ONERA M6): root chord 0.806 m, semi-span 1.1963 m, leading-edge
sweep 30 deg, taper 0.562 (tip chord 0.453 m), no twist, no dihedral, flat
tip. The section is NACA 0010 with its standard blunt trailing edge
(0.21 % of the chord), a documented stand-in for the ONERA D section (9.8 %
thick, sharp trailing edge) whose coordinates are not reproduced here. Axes: x streamwise, y along
the span (root at y = 0), z up; the leading edge of the root at the origin.

Patches: wing (the wing and its tip), symmetry (y = 0), farfield (the other
five faces of the box).

Usage: wingMesh.py [output.msh] [--coarse | --fine] [--size-wing H] ...
"""
import argparse
import math
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from wingLayers import (addLayerArguments, distance, extrudeLayers,  # noqa: E402
                        layerHeights, meshBySizeField, naca00, threshold)

SEMI_SPAN = 1.1963
ROOT_CHORD = 0.806
TIP_CHORD = 0.453
SWEEP_LE = 30.0          # deg


def section(geo, y, thickness, n):
    """The section at y: upper spline (TE -> LE), lower spline (LE -> TE),
    trailing-edge base line (lower -> upper), its leading-edge point and its
    upper and lower trailing-edge points."""
    xle = y*math.tan(math.radians(SWEEP_LE))
    c = ROOT_CHORD + (TIP_CHORD - ROOT_CHORD)*y/SEMI_SPAN
    xs = [0.5*(1 - math.cos(math.pi*i/n)) for i in range(n + 1)]
    le = geo.addPoint(xle, y, 0)
    teU = geo.addPoint(xle + c, y, c*naca00(1.0, thickness))
    teL = geo.addPoint(xle + c, y, -c*naca00(1.0, thickness))
    upper = [teU] + [geo.addPoint(xle + c*x, y, c*naca00(x, thickness))
                     for x in reversed(xs[1:-1])] + [le]
    lower = [le] + [geo.addPoint(xle + c*x, y, -c*naca00(x, thickness))
                    for x in xs[1:-1]] + [teL]
    return (geo.addSpline(upper), geo.addSpline(lower), geo.addLine(teL, teU),
            le, teU, teL)


def outward(g):
    """Roughly outward at a wing triangle's centroid g: away from the chord
    point of the triangle's station (the tip cap: +y)."""
    xle = g[1]*math.tan(math.radians(SWEEP_LE))
    ch = ROOT_CHORD + (TIP_CHORD - ROOT_CHORD)*g[1]/SEMI_SPAN
    xc = min(max(g[0], xle + 0.1*ch), xle + 0.9*ch)
    if g[1] > SEMI_SPAN - 1e-9:
        return [0.0, 1.0, 0.0]
    return [g[0] - xc, 0.0, g[2]]


def atRoot(p):
    """A node of the root section (in the symmetry plane y = 0)."""
    return abs(p[1]) < 1e-9


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output", nargs="?", default="wing.msh")
    ap.add_argument("--coarse", action="store_true",
                    help="the integration test's mesh (~20k cells)")
    ap.add_argument("--fine", action="store_true",
                    help="a mesh of more than 1M points (not run in the tests)")
    addLayerArguments(ap, "size at the leading and trailing edges [m]")
    ap.add_argument("--thickness", type=float, default=0.10,
                    help="section thickness / chord")
    ap.add_argument("--box-scale", type=float, default=1.0,
                    help="the far-field box scaled by this about the root's leading edge"
                         " (default 1: x in [-5, 7], y in [0, 4], z in [-4, 4] m)")
    a = ap.parse_args()

    level = "fine" if a.fine else "coarse" if a.coarse else "default"
    defaults = {  # size-wing size-edge size-far layers first-height growth
        "coarse":  (0.06, 0.02, 1.2, 3, 2e-4, 1.3),
        "default": (0.03, 0.008, 0.6, 6, 2e-4, 1.3),
        "fine":    (0.006, 0.002, 0.3, 10, 5e-5, 1.2),     # 2.35M points
    }[level]
    hw = a.size_wing or defaults[0]
    he = a.size_edge or defaults[1]
    hf = a.size_far or defaults[2]
    nl = a.layers or defaults[3]
    h1 = a.first_height or defaults[4]
    growth = a.growth or defaults[5]
    heights = layerHeights(h1, growth, nl)

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 1)
    gmsh.model.add("onera_m6_naca0010")

    # Wing (built-in kernel, which the boundary-layer extrusion needs):
    # ruled surfaces between the root and tip sections (upper, lower, the
    # blunt trailing edge's base), flat tip cap. A sharp trailing edge gives
    # prism side faces of skewness > 4 there (checkMesh fails).
    geo = gmsh.model.geo
    ru, rl, rb, rle, rteU, rteL = section(geo, 0.0, a.thickness, 60)
    tu, tl, tb, tle, tteU, tteL = section(geo, SEMI_SPAN, a.thickness, 60)
    le = geo.addLine(rle, tle)
    teU = geo.addLine(rteU, tteU)
    teL = geo.addLine(rteL, tteL)
    wing = [geo.addSurfaceFilling([geo.addCurveLoop([ru, le, -tu, -teU])]),
            geo.addSurfaceFilling([geo.addCurveLoop([rl, teL, -tl, -le])]),
            geo.addSurfaceFilling([geo.addCurveLoop([rb, teU, -tb, -teL])]),
            geo.addPlaneSurface([geo.addCurveLoop([tu, tl, tb])])]
    geo.synchronize()
    eps = 1e-6
    lete = [le, teU, teL]
    tipCurves = [tu, tl, tb]

    # Sizes: fine along the leading and trailing edges and the tip
    field = gmsh.model.mesh.field
    tEdge = threshold(field, distance(field, lete + tipCurves, 400), he, hw, 0.005, 0.08, 1)
    dWing = field.add("Distance")
    field.setNumbers(dWing, "FacesList", wing)
    field.setNumber(dWing, "NumPointsPerCurve", 100)
    tWing = threshold(field, dWing, hw, hf, 0.02, 3.0, 0)
    fMin = field.add("Min")
    field.setNumbers(fMin, "FieldsList", [tEdge, tWing])
    field.setAsBackgroundMesh(fMin)
    meshBySizeField()

    # Surface mesh of the wing, then the prism layers along our own normals
    # (a vector view: the root nodes march in the symmetry plane; list data,
    # which outlives the re-meshing of the wing by generate(3), which gives
    # the same surface mesh)
    ext, top, layers = extrudeLayers(wing, heights, outward, atRoot)

    # Box: x in [-5, 7] m, y in [0, 4] m, z in [-4, 4] m, times --box-scale
    x0, x1, y1, z = (a.box_scale*v for v in (-5.0, 7.0, 4.0, 4.0))
    hole = geo.addCurveLoop([c[1] for c in gmsh.model.getBoundary(top)])
    p = [geo.addPoint(x, y, zz, hf) for y in (0.0, y1)
         for (x, zz) in ((x0, -z), (x1, -z), (x1, z), (x0, z))]
    l0 = [geo.addLine(p[i], p[(i + 1) % 4]) for i in range(4)]
    l1 = [geo.addLine(p[4 + i], p[4 + (i + 1) % 4]) for i in range(4)]
    lv = [geo.addLine(p[i], p[4 + i]) for i in range(4)]
    sym = geo.addPlaneSurface([geo.addCurveLoop(l0), hole])
    far = [geo.addPlaneSurface([geo.addCurveLoop(l1)])]
    for i in range(4):
        j = (i + 1) % 4
        far.append(geo.addPlaneSurface([geo.addCurveLoop([l0[i], lv[j], -l1[i], -lv[i]])]))
    shell = geo.addSurfaceLoop([t for d, t in top] + [sym] + far)
    fluid = geo.addVolume([shell])
    geo.synchronize()

    gmsh.model.mesh.generate(3)

    # The prisms' side faces on the root plane belong to the symmetry patch
    # (the extruded entities' extents are known once meshed)
    rootSides = [t for d, t in ext if d == 2 and (d, t) not in top
                 and gmsh.model.getBoundingBox(2, t)[4] < eps]
    for name, dim, tags in (("wing", 2, wing), ("symmetry", 2, [sym] + rootSides),
                            ("farfield", 2, far), ("fluid", 3, layers + [fluid])):
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.write(a.output)

    nodeTags = gmsh.model.mesh.getNodes()[0]
    print("wingMesh: %s mesh, %d points, wing %g/%g m, far %g m, %d layers, "
          "first height %g m, total %g m, box x %g"
          % (level, len(nodeTags), hw, he, hf, nl, heights[0], heights[-1], a.box_scale))
    gmsh.finalize()


if __name__ == "__main__":
    sys.exit(main())
