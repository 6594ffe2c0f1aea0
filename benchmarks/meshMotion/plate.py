# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Mesh p, a boundary-heavy mesh for the scaling benchmark (issue 37).

A plate 1 x 1 x 0.1 m of 250 x 250 x 4 hexahedra (blockMesh): 250,000 cells,
315,004 points, of which 129,002 lie on the boundary, all of them candidates.
Its top turns about the plate's vertical axis by 0.5 deg per step
(solidBodyMotionDisplacement, rotatingMotion); its bottom and sides stay put.
supportRadius 0.3 m. The same interface as hexDominant's mesh h: make_mesh(work)
and make_case(work, mesh, name, scan, selection, steps).
"""
import os, shutil, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cases import controlDict, sh, write, FV_SCHEMES, FV_SOLUTION  # noqa: E402

TITLE = "a plate of 250 x 250 x 4 hexahedra (blockMesh), its top turned"
POINTS = 315004

BLOCK_MESH = """convertToMeters 1;
vertices ((0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 0.1) (1 0 0.1) (1 1 0.1) (0 1 0.1));
blocks (hex (0 1 2 3 4 5 6 7) (250 250 4) simpleGrading (1 1 1));
boundary
(
    top { type wall; faces ((4 5 6 7)); }
    bottom { type wall; faces ((0 3 2 1)); }
    sides { type wall; faces ((0 1 5 4) (1 2 6 5) (2 3 7 6) (3 0 4 7)); }
);
"""

PD = """dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    top
    {
        type solidBodyMotionDisplacement;
        solidBodyMotionFunction rotatingMotion;
        origin (0.5 0.5 0.1); axis (0 0 1); omega 0.008726646259971648;
        value uniform (0 0 0);
    }
    "(bottom|sides)" { type fixedValue; value uniform (0 0 0); }
}
"""


def make_mesh(work):
    """Mesh p in work/mesh_p (made once)."""
    d = os.path.join(work, "mesh_p")
    if os.path.isfile(os.path.join(d, "constant", "polyMesh", "owner")):
        return d
    shutil.rmtree(d, ignore_errors=True)
    write(os.path.join(d, "system", "blockMeshDict"), "dictionary", BLOCK_MESH)
    write(os.path.join(d, "system", "controlDict"), "dictionary", controlDict(dict(dim=2), 1))
    if sh(["blockMesh"], d, os.path.join(d, "log.blockMesh")):
        sys.exit("mesh p: blockMesh failed, see %s" % os.path.join(d, "log.blockMesh"))
    return d


def make_case(work, mesh, name, scan, selection, steps):
    c = os.path.join(work, "p_" + name)
    shutil.rmtree(c, ignore_errors=True)
    os.makedirs(os.path.join(c, "constant"))
    os.symlink(os.path.join(mesh, "constant", "polyMesh"), os.path.join(c, "constant", "polyMesh"))
    write(os.path.join(c, "system", "controlDict"), "dictionary",
          controlDict(dict(dim=2, binary=True), steps))
    write(os.path.join(c, "system", "fvSchemes"), "dictionary", FV_SCHEMES)
    write(os.path.join(c, "system", "fvSolution"), "dictionary", FV_SOLUTION)
    write(os.path.join(c, "0", "pointDisplacement"), "pointVectorField", PD)
    write(os.path.join(c, "constant", "dynamicMeshDict"), "dictionary", """dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs ("libdcpRBF.so");
motionSolver dcpRBF;
dcpRBFCoeffs
{
    movingPatches (top);
    staticPatches (bottom sides);
    supportRadius 0.3;
    qualityScan %s;
    controlPoints { selection %s; }
}
""" % (scan, selection))
    return c
