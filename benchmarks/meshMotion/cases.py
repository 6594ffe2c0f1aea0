# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The mesh-motion benchmark's settings and OpenFOAM cases (see run): the
meshes and their motions, a run's Options, the mesh cases (gmsh,
gmshToFoam) and the moveDynamicMesh cases with their dictionaries. Puts
tutorials/common (foamCase.py) on sys.path."""
import copy, os, shutil, sys
from dataclasses import dataclass

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(TOP, "tutorials", "common"))
from foamCase import PYTHON, sh, write  # noqa: E402

BUILD = os.path.join(TOP, "build", "meshMotion")
PITCH = os.path.join(TOP, "tutorials", "pitchingAirfoil2D")
WING = os.path.join(TOP, "tutorials", "wing3D")
STEPS_2D, STEPS_3D, STEPS_FINE = 20, 10, 3

# the meshes as the scripts give them; a run's own copy, with the command
# line's changes, is Options.specs (mesh_specs)
MESHES = {
    "a": dict(title="pitching tutorial mesh (naca0012Mesh.py)",
              script=os.path.join(PITCH, "naca0012Mesh.py"), args=[], dim=2, R=3.0,
              types={"frontAndBack": "empty", "wing": "wall"},
              static="inlet outlet topAndBottom"),
    "b": dict(title="boundary-layer airfoil mesh (airfoilBLMesh.py)",
              script=os.path.join(TOP, "tutorials", "common", "airfoilBLMesh.py"), args=[],
              dim=2, R=3.0, types={"frontAndBack": "empty", "wing": "wall"},
              static="inlet outlet topAndBottom"),
    "c": dict(title="wing3D (wingMesh.py default)", script=os.path.join(WING, "wingMesh.py"),
              args=[], dim=3, R=3.0, types={"symmetry": "symmetryPlane", "wing": "wall"},
              static="farfield"),
    "f": dict(title="wing3D (wingMesh.py --fine)", script=os.path.join(WING, "wingMesh.py"),
              args=["--fine"], dim=3, R=3.0, types={"symmetry": "symmetryPlane", "wing": "wall"},
              static="farfield", binary=True, steps=STEPS_FINE),
}
DCP_CONFIGS = [("all", "selection all;"), ("greedy", "selection greedy;"),
               ("dynamic", "selection dynamic;")]


def mesh_specs(coarse_wing=False, msh=None):
    """A copy of MESHES: mesh c with wingMesh.py --coarse (--coarse-wing),
    mesh f from an existing gmsh file (--msh)."""
    specs = copy.deepcopy(MESHES)
    if coarse_wing:
        specs["c"]["args"] = ["--coarse"]
        specs["c"]["title"] = "wing3D (wingMesh.py --coarse)"
    if msh:
        specs["f"]["msh"] = os.path.abspath(msh)
    return specs


@dataclass
class Options:
    """What one invocation does, made from the command line by run's main()."""
    specs: dict                 # the meshes (mesh_specs)
    work: str                   # the cases' folder
    threads: str = "1"          # OMP_NUM_THREADS of every run (--threads)
    meshes: tuple = ("a", "b", "c")
    command: str = "benchmarks/meshMotion/run"   # as the reports give it
    no_readme: bool = False
    no_1M: bool = False         # --no-1M: no resampled baseline
    msh: str = None             # --fine-wing --msh
    stored_mb: int = 0          # --fine-wing --stored-mb
    laplacian: bool = False     # --fine-wing --laplacian


FV_SCHEMES = """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
"""
FV_SOLUTION = """solvers
{
    "cellDisplacement.*"
    {
        solver GAMG; smoother GaussSeidel;
        tolerance 1e-8; relTol 0; maxIter 2000;
    }
}
"""


def make_mesh(o, m):
    d = os.path.join(o.work, "mesh_" + m)
    if os.path.isfile(os.path.join(d, "constant", "polyMesh", "owner")):
        return d
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    spec = o.specs[m]
    write(os.path.join(d, "system", "controlDict"), "dictionary", controlDict(spec, 1))
    write(os.path.join(d, "system", "fvSchemes"), "dictionary", FV_SCHEMES)
    write(os.path.join(d, "system", "fvSolution"), "dictionary", FV_SOLUTION)
    steps = [([PYTHON, spec["script"], "mesh.msh"] + spec["args"], "log.mesh"),
             (["gmshToFoam", "mesh.msh"], "log.gmshToFoam")]
    if spec.get("msh"):                     # an existing gmsh file (--msh)
        os.symlink(spec["msh"], os.path.join(d, "mesh.msh"))
        steps = steps[1:]
    for i, (patch, typ) in enumerate(sorted(spec["types"].items())):
        steps.append((["foamDictionary", "constant/polyMesh/boundary", "-entry",
                       "entry0/%s/type" % patch, "-set", typ], "log.fd%d" % i))
    for args, log in steps:
        if sh(args, d, os.path.join(d, log)):
            sys.exit("mesh %s: %s failed, see %s" % (m, args[0], os.path.join(d, log)))
    os.remove(os.path.join(d, "mesh.msh"))
    return d


def controlDict(spec, endTime):
    dt = 0.025 if spec["dim"] == 3 else 1
    return """application moveDynamicMesh;
libs ("libdcpRBF.so");
startFrom startTime; startTime 0; stopAt endTime; endTime %g; deltaT %g;
writeControl timeStep; writeInterval %d;
writeFormat %s; writePrecision 17; timeFormat general; timePrecision 6;
runTimeModifiable false;
profiling { active true; cpuInfo false; memInfo false; sysInfo false; }
""" % (endTime*dt, dt, endTime, "binary" if spec.get("binary") else "ascii")


PD_2D = """dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    wing
    {
        type solidBodyMotionDisplacement;
        solidBodyMotionFunction rotatingMotion;
        origin (0.25 0 0); axis (0 0 -1); omega 0.017453292519943295;
        value uniform (0 0 0);
    }
    "(inlet|outlet|topAndBottom)" { type fixedValue; value uniform (0 0 0); }
    frontAndBack { type empty; }
}
"""


def make_case(o, m, name, motion):
    c = os.path.join(o.work, "%s_%s" % (m, name))
    shutil.rmtree(c, ignore_errors=True)
    mesh = os.path.join(o.work, "mesh_" + m)
    spec = o.specs[m]
    shutil.copytree(os.path.join(mesh, "system"), os.path.join(c, "system"))
    if spec.get("binary"):                  # large: the moved points go to the time directories
        os.makedirs(os.path.join(c, "constant"))
        os.symlink(os.path.join(mesh, "constant", "polyMesh"),
                   os.path.join(c, "constant", "polyMesh"))
    else:
        shutil.copytree(os.path.join(mesh, "constant", "polyMesh"),
                        os.path.join(c, "constant", "polyMesh"))
    n = spec.get("steps") or (STEPS_3D if spec["dim"] == 3 else STEPS_2D)
    write(os.path.join(c, "system", "controlDict"), "dictionary", controlDict(spec, n))
    write(os.path.join(c, "constant", "dynamicMeshDict"), "dictionary", motion)
    os.makedirs(os.path.join(c, "0"))
    if spec["dim"] == 3:
        shutil.copy(os.path.join(WING, "0.orig", "pointDisplacement"), os.path.join(c, "0"))
    else:
        write(os.path.join(c, "0", "pointDisplacement"), "pointVectorField", PD_2D)
    return c


def dcp_dict(spec, cp, mem):
    return """dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs ("libdcpRBF.so");
motionSolver dcpRBF;
dcpRBFCoeffs
{
    movingPatches (wing);
    staticPatches (%s);
    function WendlandC2;
    supportRadius %g;
    controlPoints { %s }
%s}
""" % (spec["static"], spec["R"], cp,
       "" if mem is None else "    evaluationMemoryMB %d;\n" % mem)


LAPLACIAN = """dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs ("libfvMotionSolvers.so");
motionSolver displacementLaplacian;
displacementLaplacianCoeffs { diffusivity quadratic inverseDistance (wing); }
"""
