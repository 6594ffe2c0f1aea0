#!/usr/bin/python3
# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Rectangular wing (NACA 0012) in a spherical far field centred on its
pivot: prism layers on the wing, tetrahedra elsewhere, written for
gmshToFoam (msh 2.2).

Wing: chord 1 m, span 2 m from y = 0.2 m (root) to 2.2 m (tip), no sweep,
taper, twist or dihedral, flat root and tip caps. The section is NACA 0012
with its standard blunt trailing edge (0.25 % of the chord: a sharp one
gives prisms that fail checkMesh, see ../wing3D/README.md). Axes: x
streamwise, y along the span, z up; the leading edge of the root at
(0, 0.2, 0). The pivot (0.25, 0, 0): the wing flaps about the x axis
through it and pitches about the y axis through it (the quarter chord).

Patches: wing (the surface and both caps, a wall), farfield (the sphere of
radius 10 m about the pivot).

Usage: flappingWingMesh.py [output.msh] [--coarse] [--size-wing H] ...
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
ROOT = 0.2               # y of the root section: the wing's gap to the flapping axis
TIP = 2.2                # y of the tip section
PIVOT = (0.25, 0.0, 0.0)
# Meshed sheared by x += SHEAR*y, unsheared when written (wingLayers.unshear)
SHEAR = 1e-6


def section(geo, y, thickness, n):
    """The section at y: upper spline (TE -> LE), lower spline (LE -> TE),
    trailing-edge base line (lower -> upper); and its points LE, upper TE,
    lower TE."""
    xs = [0.5*(1 - math.cos(math.pi*i/n)) for i in range(n + 1)]

    def pt(x, side):
        return geo.addPoint(CHORD*x + SHEAR*y, y, side*CHORD*naca00(x, thickness))

    upper = [pt(x, 1) for x in reversed(xs)]
    lower = [upper[-1]] + [pt(x, -1) for x in xs[1:]]
    return ([geo.addSpline(upper), geo.addSpline(lower), geo.addLine(lower[-1], upper[0])],
            [upper[-1], upper[0], lower[-1]])


def outward(g):
    """Roughly outward at a wing triangle's centroid g: away from the chord
    line, the caps along -y and +y."""
    if g[1] < ROOT + 1e-9:
        return [0.0, -1.0, 0.0]
    if g[1] > TIP - 1e-9:
        return [0.0, 1.0, 0.0]
    xc = min(max(g[0], 0.1*CHORD), 0.9*CHORD)
    return [g[0] - xc, 0.0, g[2]]


def sphere(geo, centre, r, size):
    """The surfaces of a sphere (8 octants, built-in kernel)."""
    c = geo.addPoint(*centre, size)
    p = [geo.addPoint(centre[0] + r*d[0], centre[1] + r*d[1], centre[2] + r*d[2], size)
         for d in ((1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1))]
    eq = [geo.addCircleArc(p[i], c, p[(i + 1) % 4]) for i in range(4)]
    up = [geo.addCircleArc(p[i], c, p[4]) for i in range(4)]
    down = [geo.addCircleArc(p[i], c, p[5]) for i in range(4)]
    surfaces = []
    for i in range(4):
        j = (i + 1) % 4
        surfaces.append(geo.addSurfaceFilling([geo.addCurveLoop([eq[i], up[j], -up[i]])],
                                              sphereCenterTag=c))
        surfaces.append(geo.addSurfaceFilling([geo.addCurveLoop([eq[i], down[j], -down[i]])],
                                              sphereCenterTag=c))
    return surfaces


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output", nargs="?", default="flappingWing.msh")
    ap.add_argument("--coarse", action="store_true",
                    help="the integration test's mesh (< 30k cells)")
    addLayerArguments(ap, "size at the leading and trailing edges, root and tip [m]")
    ap.add_argument("--radius", type=float, default=10.0,
                    help="the far-field sphere's radius about the pivot [m] (default 10)")
    a = ap.parse_args()

    level = "coarse" if a.coarse else "default"
    defaults = {  # size-wing size-edge size-far layers first-height growth
        "coarse":  (0.2, 0.05, 3.0, 3, 5e-3, 1.3),
        "default": (0.1, 0.025, 2.0, 5, 5e-3, 1.3),
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
    gmsh.model.add("flapping_naca0012")

    # Wing (built-in kernel, which the boundary-layer extrusion needs): ruled
    # surfaces between the root and tip sections (upper, lower, the blunt
    # trailing edge's base), flat caps at both ends
    geo = gmsh.model.geo
    rc, rp = section(geo, ROOT, 0.12, 60)
    tc, tp = section(geo, TIP, 0.12, 60)
    span = [geo.addLine(r, t) for r, t in zip(rp, tp)]     # LE, upper TE, lower TE
    wing = [geo.addSurfaceFilling([geo.addCurveLoop([rc[0], span[0], -tc[0], -span[1]])]),
            geo.addSurfaceFilling([geo.addCurveLoop([rc[1], span[2], -tc[1], -span[0]])]),
            geo.addSurfaceFilling([geo.addCurveLoop([rc[2], span[1], -tc[2], -span[2]])]),
            geo.addPlaneSurface([geo.addCurveLoop(rc)]),
            geo.addPlaneSurface([geo.addCurveLoop(tc)])]
    geo.synchronize()

    # Sizes: fine along the leading and trailing edges and the caps' edges,
    # graded to the wing's size, then to the far field's over 6 m
    field = gmsh.model.mesh.field
    tEdge = threshold(field, distance(field, span + rc + tc, 400), he, hw, 0.005, 0.1, 1)
    tWing = field.add("MathEval")
    field.setString(tWing, "F", "min(%g, %g + %g*max(0, sqrt(max(0, max(-x, x - %g))^2"
                    " + max(0, max(%g - y, y - %g))^2 + max(0, abs(z) - 0.08)^2) - 0.02))"
                    % (hf, hw, (hf - hw)/6.0, CHORD, ROOT, TIP))
    fMin = field.add("Min")
    field.setNumbers(fMin, "FieldsList", [tEdge, tWing])
    field.setAsBackgroundMesh(fMin)
    meshBySizeField()

    # Surface mesh of the wing, then the prism layers along our own normals
    # (list data, which outlives the re-meshing of the wing by generate(3))
    ext, top, layers = extrudeLayers(wing, heights, outward)

    # The sphere about the pivot, the layers' outer surface its hole
    far = sphere(geo, (PIVOT[0] + SHEAR*PIVOT[1], PIVOT[1], PIVOT[2]), a.radius, hf)
    fluid = geo.addVolume([geo.addSurfaceLoop(far), geo.addSurfaceLoop([t for d, t in top])])
    geo.synchronize()

    gmsh.model.mesh.generate(3)
    checkLayers("flappingWingMesh", wing, layers, nl)
    unshear(SHEAR)

    for name, dim, tags in (("wing", 2, wing), ("farfield", 2, far),
                            ("fluid", 3, layers + [fluid])):
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.write(a.output)

    _, _, cellNodes = gmsh.model.mesh.getElements(3)
    nPoints = len(set().union(*(set(n) for n in cellNodes)))
    nPrism, nTet = (len(gmsh.model.mesh.getElementsByType(t)[0]) for t in (6, 4))
    print("flappingWingMesh: %s mesh, %d points, %d cells (%d prisms + %d tetrahedra),"
          " wing %g/%g m, far %g m, %d layers, first height %g m, total %g m,"
          " sphere of radius %g m about (%g %g %g)"
          % (level, nPoints, nPrism + nTet, nPrism, nTet, hw, he, hf, nl, heights[0],
             heights[-1], a.radius, *PIVOT))
    gmsh.finalize()


if __name__ == "__main__":
    sys.exit(main())
