# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""What the 3D wing meshes share (gmsh Python API, built-in kernel): the NACA
00tt thickness, the outward normals along which gmsh extrudes the prism
layers, the check that every layer is there, and the size fields.

Used by ../wing3D/wingMesh.py, ../flap3D/flapMesh.py and
../flappingWing3D/flappingWingMesh.py.
"""
import math
import sys

import gmsh


def naca00(x, t):
    """Half thickness of a NACA 00tt section (chord 1), standard (blunt)
    trailing edge: 0.252 % of the chord thick at x = 1 for t = 0.12, 0.21 %
    for t = 0.10."""
    return 5*t*(0.2969*math.sqrt(x) - 0.1260*x - 0.3516*x**2
                + 0.2843*x**3 - 0.1015*x**4)


def outwardNormals(surfaces, guide, inPlane=lambda p: False, atNodes=False):
    """Unit outward normals at the mesh nodes of the surfaces (angle-weighted
    mean of the triangles' normals: the bisector at a trailing edge's
    corners), as a list of vector triangles (gmsh "VT" list data). Each
    surface is oriented by a vote of its triangles against guide(g), a
    roughly outward direction at a triangle's centroid g. Nodes where
    inPlane(p) is true get normals with no y component (a root in a
    symmetry plane y = 0: the prisms' side faces stay in it). atNodes: as
    vector points at the nodes (gmsh "VP"), which gmsh finds at each node
    exactly; the triangles' data are found by a search that can take a
    node's normal from another surface's triangle whose box holds the node
    (a thin part, tilted: a deflected flap's trailing edge)."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xyz = {int(t): coords[3*i:3*i + 3] for i, t in enumerate(tags)}
    normal = {}
    tris = []
    for s in surfaces:
        _, _, nodes = gmsh.model.mesh.getElements(2, s)
        ts = [[int(t) for t in nodes[0][3*i:3*i + 3]] for i in range(len(nodes[0])//3)]
        ns = []
        vote = 0.0
        for a, b, c in ts:
            pa, pb, pc = xyz[a], xyz[b], xyz[c]
            u = [pb[k] - pa[k] for k in range(3)]
            v = [pc[k] - pa[k] for k in range(3)]
            n = [u[1]*v[2] - u[2]*v[1], u[2]*v[0] - u[0]*v[2], u[0]*v[1] - u[1]*v[0]]
            out = guide([(pa[k] + pb[k] + pc[k])/3 for k in range(3)])
            vote += sum(n[k]*out[k] for k in range(3))
            ns.append(((a, b, c), n))
        sign = 1.0 if vote > 0 else -1.0
        for tri, n in ns:
            tris.append(tri)
            mn = math.sqrt(sum(c*c for c in n))
            for i, t in enumerate(tri):
                p0, p1, p2 = (xyz[tri[(i + j) % 3]] for j in range(3))
                u = [p1[k] - p0[k] for k in range(3)]
                v = [p2[k] - p0[k] for k in range(3)]
                cosA = sum(u[k]*v[k] for k in range(3))/math.sqrt(
                    sum(c*c for c in u)*sum(c*c for c in v))
                w = math.acos(max(-1.0, min(1.0, cosA)))/mn
                m = normal.setdefault(t, [0.0, 0.0, 0.0])
                for k in range(3):
                    m[k] += sign*w*n[k]
    for t, n in normal.items():
        if inPlane(xyz[t]):
            n[1] = 0.0
        m = math.sqrt(sum(c*c for c in n))
        normal[t] = [c/m for c in n]
    data = []
    if atNodes:
        for t, n in normal.items():
            data += list(xyz[t]) + n
        return len(normal), data
    for tri in tris:
        data += [xyz[t][0] for t in tri] + [xyz[t][1] for t in tri] + [xyz[t][2] for t in tri]
        for t in tri:
            data += normal[t]
    return len(tris), data


def checkLayers(script, surfaces, layers, nl):
    """Exit (naming the script) unless every triangle of the surfaces has
    its nl prisms (gmsh writes a collapsed prism as a pyramid) and no node
    is doubled."""
    nTri = sum(len(gmsh.model.mesh.getElementsByType(2, s)[0]) for s in surfaces)
    nPrism = sum(len(gmsh.model.mesh.getElementsByType(6, v)[0]) for v in layers)
    _, coords, _ = gmsh.model.mesh.getNodes()
    nDup = len(coords)//3 - len({tuple(coords[i:i + 3]) for i in range(0, len(coords), 3)})
    if nPrism != nl*nTri or nDup:
        sys.exit("%s: %d prisms for %d triangles x %d layers, %d doubled nodes"
                 % (script, nPrism, nTri, nl, nDup))


def unshear(shear):
    """x -= shear*y at every node (y unchanged). The unswept wings are meshed
    sheared by x += shear*y: gmsh 4.8's boundary-layer extrusion keeps its
    normals in a set ordered by x, y, z with a tolerance of 1e-12, and on a
    cylindrical wing the surface mesher gives rows of nodes whose x differ by
    1e-15..1e-11 only: the set's order is then inconsistent and some nodes'
    normals are not found (no layers there: collapsed prisms, or a node
    doubled between prisms and tetrahedra, depending on the memory layout of
    the run). Sheared by 1e-6, the x of the nodes of a row differ by >= 1e-9 m."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    for i, t in enumerate(tags):
        x, y, z = coords[3*i:3*i + 3]
        gmsh.model.mesh.setNode(t, [x - shear*y, y, z], [])


def threshold(field, distance, sizeMin, sizeMax, distMin, distMax, stop):
    """A Threshold field on the Distance field distance."""
    f = field.add("Threshold")
    field.setNumber(f, "InField", distance)
    field.setNumber(f, "SizeMin", sizeMin)
    field.setNumber(f, "SizeMax", sizeMax)
    field.setNumber(f, "DistMin", distMin)
    field.setNumber(f, "DistMax", distMax)
    field.setNumber(f, "StopAtDistMax", stop)
    return f


def distance(field, curves, n):
    """A Distance field to the curves (n points per curve)."""
    f = field.add("Distance")
    field.setNumbers(f, "EdgesList", curves)
    field.setNumber(f, "NumPointsPerCurve", n)
    return f


def layerHeights(h1, growth, nl):
    """The cumulative heights of nl layers, the first h1 thick, each growth
    times the one below."""
    heights = []
    h = 0.0
    for i in range(nl):
        h += h1*growth**i
        heights.append(h)
    return heights


def addLayerArguments(ap, edge="size at the leading and trailing edges [m]"):
    """The mesh options the wing scripts share (None: the script's level's
    default)."""
    ap.add_argument("--size-wing", type=float, help="surface size on the wing [m]")
    ap.add_argument("--size-edge", type=float, help=edge)
    ap.add_argument("--size-far", type=float, help="size at the far field [m]")
    ap.add_argument("--layers", type=int, help="prism layers")
    ap.add_argument("--first-height", type=float, help="first layer height [m]")
    ap.add_argument("--growth", type=float, help="layer growth ratio")


def meshBySizeField():
    """Sizes from the background field alone (not from the points, the
    boundary or the curvature); Frontal-Delaunay triangles, Delaunay
    tetrahedra."""
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.option.setNumber("Mesh.Algorithm", 6)
    gmsh.option.setNumber("Mesh.Algorithm3D", 1)


def extrudeLayers(surfaces, heights, guide, inPlane=lambda p: False, atNodes=False):
    """Mesh the surfaces, then extrude the prism layers (cumulative heights)
    along outwardNormals(surfaces, guide, inPlane) (a vector view of list
    data, which outlives the re-meshing of the surfaces by generate(3), which
    gives the same surface mesh; atNodes: see outwardNormals). Returns the
    extrusion's entities, the layers' outer surfaces and their volumes."""
    gmsh.model.mesh.generate(2)
    view = gmsh.view.add("normals")
    gmsh.view.addListData(view, "VP" if atNodes else "VT",
                          *outwardNormals(surfaces, guide, inPlane, atNodes))
    ext = gmsh.model.geo.extrudeBoundaryLayer(
        [(2, t) for t in surfaces], [1]*len(heights), heights, True,
        viewIndex=gmsh.view.getIndex(view))
    top = [ext[i - 1] for i in range(1, len(ext)) if ext[i][0] == 3]
    layers = [t for d, t in ext if d == 3]
    gmsh.model.geo.synchronize()
    return ext, top, layers
