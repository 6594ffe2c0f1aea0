# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The deformation-capacity study's set-up: paths, meshes, configurations
and the meaning of a step (see run)."""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
WORK = os.path.join(HERE, "work")
RESULTS = os.path.join(HERE, "results")
IMAGES = os.path.join(HERE, "images")
PITCH = os.path.join(TOP, "tutorials", "pitchingAirfoil2D")
WING = os.path.join(TOP, "tutorials", "wing3D")
PYTHON = "/usr/bin/python3"

# The wing (mesh c): ONERA M6 planform of tutorials/wing3D, semi-span b [m];
# per step the tip rises by WING_DEFL_STEP b and twists by WING_TWIST_STEP deg.
WING_SEMISPAN = 1.1963
WING_DEFL_STEP = 0.025
WING_TWIST_STEP = 1.0

# The meshes: generator, arguments, supportRadius (chords)
MESHES = {
    "a": dict(title="pitching tutorial mesh (naca0012Mesh.py defaults, 5056 prisms)",
              script=os.path.join(PITCH, "naca0012Mesh.py"), args=[], supportRadius=3.0),
    "b": dict(title="boundary-layer mesh (airfoilBLMesh.py defaults, 1.5e-5 c first layer, 30 layers)",
              script=os.path.join(TOP, "tutorials", "common", "airfoilBLMesh.py"), args=[],
              supportRadius=3.0),
    "c": dict(title="3D wing (tutorials/wing3D/wingMesh.py --coarse, ~31k prisms + tets), "
                    "bending + twist ramp",
              script=os.path.join(WING, "wingMesh.py"), args=["--coarse"],
              supportRadius=round(2*WING_SEMISPAN, 4),  # 2 semi-spans (2.39 m)
              system=os.path.join(WING, "system"),
              types={"symmetry": "symmetryPlane", "wing": "wall"},
              staticPatches="farfield", dim=3),
}
# 2D defaults of the entries above
for _m in MESHES.values():
    _m.setdefault("system", os.path.join(PITCH, "system"))
    _m.setdefault("types", {"frontAndBack": "empty", "wing": "wall"})
    _m.setdefault("staticPatches", "inlet outlet topAndBottom")
    _m.setdefault("dim", 2)


def is3D(m):
    return MESHES[m]["dim"] == 3


def scaleTag(S):
    """Suffix of a run's key and name at ramp scale S ("" at the default 1)."""
    return "" if S == 1 else "_s%g" % S


def stepLabel(m, t, S=1):
    """What step t means on mesh m; at ramp scale S != 1, t is already the
    amplitude in units of the 1x step (2D: degrees; 3D: 2.5 % b tip
    deflection and 1 deg twist) and is given in physical units only."""
    if S != 1:
        if is3D(m):
            return "tip %.3g m = %.3g %% b, %.3g deg" % (
                WING_DEFL_STEP*WING_SEMISPAN*t, 100*WING_DEFL_STEP*t, WING_TWIST_STEP*t)
        return "%g deg" % t
    if is3D(m):
        return "%g (tip %.3f m = %.1f %% b, %g deg)" % (
            t, WING_DEFL_STEP*WING_SEMISPAN*t, 100*WING_DEFL_STEP*t, WING_TWIST_STEP*t)
    return "%g" % t

FIXED_N = "tolerance 1e-12; minPoints {N}; maxPoints {N}; reselectTolerance 1e9;"
# DCP at fixed N: both rules swap at constant size (also at maxPoints), the
# paper's rule leaving first when the set is full.
FIXED_N_DCP = "tolerance 1e-12; minPoints {N}; maxPoints {N}; reselectTolerance 1e9;"

# The configurations. 'controlPoints' is formatted with N and the swapRule
# entry; 'needs' names a library feature that must be detected first;
# 'perN' False: run once (the set size is not fixed); 'correction' False:
# boundaryCorrection is meaningless (selection all).
CONFIGS = [
    dict(key="all", label="all (full RBF)", controlPoints="selection all;",
         perN=False, correction=False),
    dict(key="greedy", label="greedy, static N",
         controlPoints="selection greedy; " + FIXED_N),
    dict(key="greedyReselect", label="greedy + re-selection (tol 1e-3)",
         controlPoints="selection greedy; tolerance 1e-3;", perN=False),
    dict(key="dcpPaper", label="DCP (paper rule: nearest)",
         controlPoints="selection dynamic; " + FIXED_N_DCP + " nSwap 1; {swapRuleNearest}"),
    dict(key="dcpNew", label="DCP (new rule: errorGuided)",
         controlPoints="selection dynamic; " + FIXED_N_DCP + " swapRule errorGuided;",
         needs="swapRule"),
]
QUICK = dict(meshes=["b"], N=[20, 50], correction=["off", "on"],
             configs=["all", "greedy", "greedyReselect", "dcpPaper", "dcpNew"])
FULL = dict(meshes=["a", "b", "c"], N=[20, 50, 100], correction=["off", "on"],
            configs=[c["key"] for c in CONFIGS])
