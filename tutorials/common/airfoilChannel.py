# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Shared by the 2D airfoil mesh scripts: the NACA0012 thickness law, and the
extrusion of a channel surface one cell thick with the patches named for
gmshToFoam."""
import math

import gmsh


def naca0012(x, closed_trailing_edge):
    """Half thickness of NACA0012 at x (chord 1): the standard law (blunt
    trailing edge, 0.25 % of the chord) or the closed-trailing-edge variant."""
    a4 = 0.1036 if closed_trailing_edge else 0.1015
    return 0.6*(0.2969*math.sqrt(x) - 0.1260*x - 0.3516*x**2 + 0.2843*x**3 - a4*x**4)


def extrude_and_name(geo, surface, span, n_wing_curves):
    """Extrude `surface` by `span` (one cell, recombined) and name the
    patches: topAndBottom, outlet, inlet (the outer loop's curves, in order
    bottom, outlet, top, inlet), wing (the next n_wing_curves curves),
    frontAndBack; the volume is "fluid". Lateral surfaces follow the order of
    the boundary curves: outer loop, then the wing."""
    out = geo.extrude([(2, surface)], 0, 0, span, numElements=[1], recombine=True)
    geo.synchronize()
    front, volume, lateral = out[0][1], out[1][1], [t for d, t in out[2:]]
    names = {"topAndBottom": [lateral[0], lateral[2]], "outlet": [lateral[1]],
             "inlet": [lateral[3]], "wing": lateral[4:4 + n_wing_curves],
             "frontAndBack": [surface, front]}
    for name, tags in names.items():
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, tags), name)
    gmsh.model.setPhysicalName(3, gmsh.model.addPhysicalGroup(3, [volume]), "fluid")
