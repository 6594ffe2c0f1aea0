#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Rectangular half wing (NACA 0012) with a full-span trailing-edge flap in a
far-field box with a symmetry plane at the root: prism layers on the wing,
tetrahedra elsewhere, written for gmshToFoam (msh 2.2).

Wing: chord 1 m, semi-span 2 m, no sweep, taper, twist or dihedral, flat tip
cap. The section is NACA 0012 with its standard blunt trailing edge (0.25 %
of the chord thick: a sharp one gives prisms that fail checkMesh, see
../wing3D/README.md). Axes: x streamwise, y along the span (root at y = 0),
z up; the leading edge of the root at the origin. The flap's hinge line is
x = 0.75, z = 0, along y.

Patches: the wing surface is cut at x = 0.70 and x = 0.80 (upper and lower
surfaces along the whole span, and the tip cap) into wing (x < 0.70: the
leading edge and the front of the tip cap), hinge (the strip 0.70 < x < 0.80,
which bends when the flap turns: finely meshed across) and flap (x > 0.80:
with the trailing-edge base and the aft part of the tip cap); the cut lines
are curves of the geometry, edges shared by the patches. symmetry (y = 0),
farfield (the other five faces of the box).

With --deflection DEG the wing is made with its flap deflected (trailing
edge down for DEG > 0): every point of a section turned about the hinge line
by s DEG, s the strip's blend of the rest x (quintic smoothstep from 0 at
x = 0.70 to 1 at x = 0.80), as hingeStripDisplacement and the flap's
solidBodyMotionDisplacement move it: the reference for the forces on the
morphed mesh (Allrun -flow).

Usage: flapMesh.py [output.msh] [--coarse] [--deflection DEG] [--size-wing H] ...
"""
import argparse
import math
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from wingLayers import (addLayerArguments, checkLayers, distance,  # noqa: E402
                        extrudeLayers, layerHeights, meshBySizeField, naca00,
                        threshold, unshear)

CHORD = 1.0
SEMI_SPAN = 2.0
HINGE_X = 0.75           # the hinge line: x = 0.75, z = 0, along y
CUTS = (0.70, 0.80)      # the chordwise cuts: wing | hinge | flap
# Meshed sheared by x += SHEAR*y (2e-6 m at the tip), unsheared when written
# (wingLayers.unshear says why)
SHEAR = 1e-6


def blend(x):
    """The strip's fraction s of the flap's rotation at rest x: 0 ahead of
    x = 0.70, 1 aft of x = 0.80, a quintic smoothstep between."""
    t = min(max((x - CUTS[0])/(CUTS[1] - CUTS[0]), 0.0), 1.0)
    return t*t*t*(10 - 15*t + 6*t*t)


def deflect(x, z, deg):
    """The rest point (x, z) of a section turned about the hinge line
    (x = 0.75, z = 0) by blend(x) deg, trailing edge down for deg > 0."""
    a = math.radians(blend(x)*deg)
    if a == 0:
        return x, z                             # bit for bit the undeflected mesh
    u = x - HINGE_X
    return HINGE_X + u*math.cos(a) + z*math.sin(a), -u*math.sin(a) + z*math.cos(a)


def rest(g, deg):
    """The rest position (x, z) of a deflected point g (deflect's inverse: a
    fixed-point iteration on the blend's rest x)."""
    if deg == 0:
        return g[0], g[2]
    x = g[0]
    for _ in range(20):
        a = -math.radians(blend(x)*deg)
        u = g[0] - HINGE_X
        x = HINGE_X + u*math.cos(a) + g[2]*math.sin(a)
    return x, -u*math.sin(a) + g[2]*math.cos(a)


def section(geo, y, thickness, n, deg):
    """The section at y as a closed chain of 7 curves, each from points[i] to
    points[(i + 1) % 7]: upper flap, hinge and front (TE -> LE), lower front,
    hinge and flap (LE -> TE), trailing-edge base (lower -> upper); points:
    upper TE, upper cuts at 0.80 and 0.70, LE, lower cuts at 0.70 and 0.80,
    lower TE. One spline per side through the cut points, split there (the
    pieces join with a continuous tangent)."""
    xs = [0.5*(1 - math.cos(math.pi*i/n)) for i in range(n + 1)]
    # the cosine points, those too close to a cut replaced by the cut
    xs = sorted([x for x in xs if min(abs(x - c) for c in CUTS) > 0.3/n] + list(CUTS))

    def pt(x, side):
        px, pz = deflect(CHORD*x, side*CHORD*naca00(x, thickness), deg)
        return geo.addPoint(px + SHEAR*y, y, pz)

    upper = [pt(x, 1) for x in reversed(xs)]        # TE -> LE
    lower = [upper[-1]] + [pt(x, -1) for x in xs[1:]]   # LE -> TE
    cutsU = [upper[len(xs) - 1 - xs.index(c)] for c in reversed(CUTS)]
    cutsL = [lower[xs.index(c)] for c in CUTS]
    curves = (list(geo.splitCurve(geo.addSpline(upper), cutsU))
              + list(geo.splitCurve(geo.addSpline(lower), cutsL))
              + [geo.addLine(lower[-1], upper[0])])
    points = [upper[0]] + cutsU + [upper[-1]] + cutsL + [lower[-1]]
    return curves, points


def outward(g, deg):
    """Roughly outward at a wing triangle's centroid g: away from the chord
    line at rest (the tip cap: +y), turned with the section."""
    if g[1] > SEMI_SPAN - 1e-9:
        return [0.0, 1.0, 0.0]
    x, z = rest(g, deg)                         # (the shear: < 2e-6 m)
    xc = min(max(x, 0.1*CHORD), 0.9*CHORD)
    a = math.radians(blend(x)*deg)
    u, w = x - xc, z
    return [u*math.cos(a) + w*math.sin(a), 0.0, -u*math.sin(a) + w*math.cos(a)]


def atRoot(p):
    """A node of the root section (in the symmetry plane y = 0)."""
    return abs(p[1]) < 1e-9


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output", nargs="?", default="flap.msh")
    ap.add_argument("--coarse", action="store_true",
                    help="the integration test's mesh (< 30k cells)")
    addLayerArguments(ap, "size at the leading and trailing edges and the tip [m]")
    ap.add_argument("--size-hinge", type=float,
                    help="size on the hinge strip and at the cuts [m]")
    ap.add_argument("--deflection", type=float, default=0.0, metavar="DEG",
                    help="the flap deflected by DEG (trailing edge down for DEG > 0)")
    ap.add_argument("--thickness", type=float, default=0.12,
                    help="section thickness / chord")
    ap.add_argument("--box", type=float, nargs=4, default=(-5.0, 8.0, 5.0, 5.0),
                    metavar=("X0", "X1", "Y1", "Z"),
                    help="the far-field box: x in [X0, X1], y in [0, Y1], z in [-Z, Z]"
                         " (default -5 8 5 5 m)")
    a = ap.parse_args()

    level = "coarse" if a.coarse else "default"
    defaults = {  # size-wing size-edge size-hinge size-far layers first-height growth
        "coarse":  (0.2, 0.03, 0.033, 2.0, 3, 2e-4, 1.3),
        "default": (0.08, 0.012, 0.016, 0.8, 6, 2e-4, 1.3),
    }[level]
    hw = a.size_wing or defaults[0]
    he = a.size_edge or defaults[1]
    hh = a.size_hinge or defaults[2]
    hf = a.size_far or defaults[3]
    nl = a.layers or defaults[4]
    h1 = a.first_height or defaults[5]
    growth = a.growth or defaults[6]
    heights = layerHeights(h1, growth, nl)

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 1)
    gmsh.model.add("flap_naca0012")

    # Wing (built-in kernel, which the boundary-layer extrusion needs): ruled
    # surfaces between the root and tip sections, one per section curve (the
    # front, hinge and flap parts of the upper and lower surfaces, the blunt
    # trailing edge's base); the flat tip cap in three plane pieces, cut by
    # straight lines at x = 0.70 and 0.80.
    geo = gmsh.model.geo
    rc, rp = section(geo, 0.0, a.thickness, 60, a.deflection)
    tc, tp = section(geo, SEMI_SPAN, a.thickness, 60, a.deflection)
    span = [geo.addLine(r, t) for r, t in zip(rp, tp)]
    sides = [geo.addSurfaceFilling([geo.addCurveLoop(
        [rc[i], span[(i + 1) % 7], -tc[i], -span[i]])]) for i in range(7)]
    cut7 = geo.addLine(tp[2], tp[4])         # the tip's cuts, upper -> lower
    cut8 = geo.addLine(tp[1], tp[5])
    capFront = geo.addPlaneSurface([geo.addCurveLoop([tc[2], tc[3], -cut7])])
    capHinge = geo.addPlaneSurface([geo.addCurveLoop([tc[1], cut7, tc[4], -cut8])])
    capFlap = geo.addPlaneSurface([geo.addCurveLoop([tc[0], cut8, tc[5], tc[6]])])
    patches = {"wing": [sides[2], sides[3], capFront],
               "hinge": [sides[1], sides[4], capHinge],
               "flap": [sides[0], sides[5], sides[6], capFlap]}
    wing = [s for p in ("wing", "hinge", "flap") for s in patches[p]]
    geo.synchronize()
    eps = 1e-6

    # Sizes: fine along the leading and trailing edges and the tip, and on
    # the hinge strip (every point of it within 0.05 m of a cut), graded to
    # the wing's size, then to the far field's
    field = gmsh.model.mesh.field
    edges = [span[3], span[0], span[6]] + tc          # LE, TE corners, tip
    cuts = [span[1], span[2], span[4], span[5], cut7, cut8]
    tEdge = threshold(field, distance(field, edges, 400), he, hw, 0.005, 0.08, 1)
    tCut = threshold(field, distance(field, cuts, 400), hh, hw, 0.05,
                     0.05 + 1.5*(hw - hh), 1)
    # hw to hf over 3 m from the wing's bounding box (a MathEval: gmsh 4.8's
    # Distance field to surfaces takes seconds to build)
    tWing = field.add("MathEval")
    field.setString(tWing, "F", "min(%g, %g + %g*max(0, sqrt(max(0, max(-x, x - %g))^2"
                    " + max(0, y - %g)^2 + max(0, abs(z) - %g)^2) - 0.02))"
                    % (hf, hw, (hf - hw)/2.98, CHORD, SEMI_SPAN, 0.6*a.thickness*CHORD))
    fMin = field.add("Min")
    field.setNumbers(fMin, "FieldsList", [tEdge, tCut, tWing])
    field.setAsBackgroundMesh(fMin)
    meshBySizeField()

    # Surface mesh of the wing, then the prism layers along our own normals
    # (a vector view: the root nodes march in the symmetry plane; list data,
    # which outlives the re-meshing of the wing by generate(3), which gives
    # the same surface mesh)
    # (a deflected flap: the normals at the nodes, see outwardNormals; the
    # undeflected mesh as it was made before, with the triangles' data)
    ext, top, layers = extrudeLayers(wing, heights, lambda g: outward(g, a.deflection), atRoot,
                                     atNodes=a.deflection != 0)

    # Box: x in [x0, x1], y in [0, y1], z in [-z, z]; the root plane has the
    # hole of the prism layers' outer section
    x0, x1, y1, z = a.box
    hole = geo.addCurveLoop([c[1] for c in gmsh.model.getBoundary(top)])
    p = [geo.addPoint(x + SHEAR*y, y, zz, hf) for y in (0.0, y1)
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
    checkLayers("flapMesh", wing, layers, nl)
    unshear(SHEAR)

    # The prisms' side faces on the root plane belong to the symmetry patch
    # (the extruded entities' extents are known once meshed)
    rootSides = [t for d, t in ext if d == 2 and (d, t) not in top
                 and gmsh.model.getBoundingBox(2, t)[4] < eps]
    groups = [(name, 2, patches[name]) for name in ("wing", "hinge", "flap")]
    groups += [("symmetry", 2, [sym] + rootSides), ("farfield", 2, far),
               ("fluid", 3, layers + [fluid])]
    for name, dim, tags in groups:
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.write(a.output)

    # (the points of the cells: gmsh's model also holds some unused nodes)
    _, _, cellNodes = gmsh.model.mesh.getElements(3)
    nPoints = len(set().union(*(set(n) for n in cellNodes)))
    nPrism, nTet = (len(gmsh.model.mesh.getElementsByType(t)[0]) for t in (6, 4))
    print("flapMesh: %s mesh, %d points, %d cells (%d prisms + %d tetrahedra), wing %g/%g m,"
          " hinge %g m, far %g m, %d layers, first height %g m, total %g m, box %s;"
          " hinge line x = %g, z = 0, flap deflected %g deg"
          % (level, nPoints, nPrism + nTet, nPrism, nTet, hw, he, hh, hf, nl, heights[0],
             heights[-1], " ".join("%g" % v for v in a.box), HINGE_X, a.deflection))
    gmsh.finalize()


if __name__ == "__main__":
    sys.exit(main())
