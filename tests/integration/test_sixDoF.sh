# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: dcpRBF driven by a 6-DoF rigid body (the README recipe).
# OpenFOAM's incompressible/pimpleFoam/RAS/wingMotion/wingMotion2D_pimpleFoam
# (fields, schemes, solvers, kOmegaSST, the body's mass, inertia, constraints
# and springs) on the project's small NACA0012 mesh instead of the tutorial's
# snappyHexMesh + simpleFoam chain (minutes); flow 10 m/s instead of 100 m/s so
# that 20 fixed steps of 1 ms move the wing visibly. The wing's pointDisplacement
# is sixDoFRigidBodyDisplacement; the stock run uses the sixDoFRigidBodyMotion
# motion solver with the same body.

sixDoFSteps=20
sixDoFDeltaT=1e-3

# sixDoFBody: the stock tutorial's body (chord-1 wing at the origin, mid-span z = 0.05)
sixDoFBody() {
    cat <<'EOT'
mass            22.9;
centreOfMass    (0.4974612746 -0.01671895744 0.05);
momentOfInertia (1.958864357 3.920839234 2.057121362);
orientation     (1 0 0 0 1 0 0 0 1);
angularMomentum (0 0 -2);
g               (0 -9.81 0);
rho             rhoInf;
rhoInf          1;
report          on;
solver          { type symplectic; }
constraints
{
    yLine { sixDoFRigidBodyMotionConstraint line; centreOfRotation (0.25 0.007 0.05); direction (0 1 0); }
    zAxis { sixDoFRigidBodyMotionConstraint axis; axis (0 0 1); }
}
restraints
{
    verticalSpring
    {
        sixDoFRigidBodyMotionRestraint linearSpring;
        anchor (0.25 0.007 0.05); refAttachmentPt (0.25 0.007 0.05);
        stiffness 4000; damping 2; restLength 0;
    }
    axialSpring
    {
        sixDoFRigidBodyMotionRestraint linearAxialAngularSpring;
        axis (0 0 1); stiffness 700; damping 0.5;
        referenceOrientation (1 0 0 0 1 0 0 0 1);
    }
}
EOT
}

# wingMotionCase: the tutorial's setup on the airfoil mesh, in the current folder
wingMotionCase() {
    local tut="$FOAM_TUTORIALS/incompressible/pimpleFoam/RAS/wingMotion/wingMotion2D_pimpleFoam"
    [ -d "$tut" ] || fail "no OpenFOAM tutorial at $tut (FOAM_TUTORIALS: re-run ./Allwmake)" || return 1
    mkdir -p constant system
    cp -r "$tut/0.orig" 0
    rm -f 0/pointDisplacement
    cp "$tut/constant/transportProperties" "$tut/constant/turbulenceProperties" constant/
    cp "$tut/system/controlDict" "$tut/system/fvSchemes" "$tut/system/fvSolution" \
       "$tut/system/ensightWrite" system/
    # no function objects: the stock sixDoFRigidBodyState casts the motion
    # solver to sixDoFRigidBodyMotionSolver (fails with dcpRBF); no ensightWrite
    foamDictionary system/controlDict -entry functions -remove > /dev/null
    rm system/ensightWrite
    airfoilMesh 0.04 1.0 || return 1
    # the mesh's one empty patch is frontAndBack (the tutorial's: front, back)
    cat > 0/include/frontBackTopBottomPatches <<'EOT'
topAndBottom { type slip; }
frontAndBack { type empty; }
EOT
    sed -i 's/"(front|back|/"(frontAndBack|front|back|/' 0/nut
    grep -q frontAndBack 0/nut || fail "could not adapt 0/nut" || return 1
    sed -i 's/^flowVelocity .*/flowVelocity (10 0 0);/' 0/include/initialConditions
    foamDictionary system/controlDict -entry endTime -set "$(awk -v n=$sixDoFSteps -v d=$sixDoFDeltaT 'BEGIN { print n*d }')" > /dev/null
    foamDictionary system/controlDict -entry deltaT -set $sixDoFDeltaT > /dev/null
    foamDictionary system/controlDict -entry adjustTimeStep -set no > /dev/null
    foamDictionary system/controlDict -entry writeControl -set timeStep > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 5 > /dev/null
    foamDictionary system/controlDict -entry writePrecision -set 17 > /dev/null
}

# wingPointDisplacement WINGENTRY: 0/pointDisplacement, the far field fixed
wingPointDisplacement() {
    writeFile 0/pointDisplacement pointVectorField <<EOT
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    wing
    {
$1
    }
    frontAndBack { type empty; }
    "(inlet|outlet|topAndBottom)" { type fixedValue; value uniform (0 0 0); }
}
EOT
}

# sixDoFDcpRBF: the README recipe: the body in the wing's condition, dcpRBF moves the mesh
sixDoFDcpRBF() {
    wingPointDisplacement "type sixDoFRigidBodyDisplacement; value uniform (0 0 0);
$(sixDoFBody)"
    writeFile constant/dynamicMeshDict dictionary <<'EOT'
dynamicFvMesh    dynamicMotionSolverFvMesh;
motionSolverLibs ("libsixDoFRigidBodyMotion.so" "libdcpRBF.so");
motionSolver     dcpRBF;
dcpRBFCoeffs
{
    movingPatches (wing);
    staticPatches (inlet outlet topAndBottom);
    supportRadius 2.5;
}
EOT
}

# sixDoFStock: OpenFOAM's sixDoFRigidBodyMotion motion solver, same body
sixDoFStock() {
    wingPointDisplacement "type calculated; value uniform (0 0 0);"
    writeFile constant/dynamicMeshDict dictionary <<EOT
dynamicFvMesh    dynamicMotionSolverFvMesh;
motionSolverLibs ("libsixDoFRigidBodyMotion.so");
motionSolver     sixDoFRigidBodyMotion;
patches          (wing);
innerDistance    0.3;
outerDistance    1;
$(sixDoFBody)
EOT
}

test_sixDoF_dcpRBF_wingMovesMeshValid() {
    local diff
    wingMotionCase || return 1
    sixDoFDcpRBF
    run pimpleFoam || return 1
    tail -n 3 log.pimpleFoam | grep -q '^End' || fail "pimpleFoam did not end"
    grep -q "dcpRBF: control points" log.pimpleFoam || fail "no dcpRBF log line" || return 1
    grep -q "Centre of rotation" log.pimpleFoam || fail "no 6-DoF report in the log" || return 1
    awk -v patch=wing -f "$here/cases/patchPoints.awk" \
        constant/polyMesh/boundary constant/polyMesh/faces > wing.labels || fail "no wing points" || return 1
    local last
    last=$(foamListTimes -latestTime 2>/dev/null | tail -n 1)
    [ -f "$last/polyMesh/points" ] || fail "no moved points written (latest time '$last')" || return 1
    diff=$(awk -f "$here/cases/comparePatchPoints.awk" wing.labels constant/polyMesh/points \
        constant/polyMesh/points "$last/polyMesh/points") || fail "$diff" || return 1
    echo "wing points at t = $last vs initial: max displacement $(echo "$diff" | cut -d' ' -f4) m"
    awk -v d="$(echo "$diff" | cut -d' ' -f4)" 'BEGIN { exit !(d > 1e-4) }' \
        || fail "the wing did not move: max displacement $(echo "$diff" | cut -d' ' -f4) m at t = $last" || return 1
    meshOkAtEveryTime
}

# sixDoFState FILE: centreOfRotation and orientation (12 numbers, full
# precision) from a written state: the first entries of those names in FILE
# (uniform/sixDoFRigidBodyMotionState, or pointDisplacement where the wing's
# condition writes its state before its constraints)
sixDoFState() {
    awk '
    !c && /^ *centreOfRotation / { c = $0 }
    !o && /^ *orientation / { o = $0 }
    END {
        if (!c || !o) exit 1
        s = c " " o
        gsub(/centreOfRotation|orientation|[();]/, " ", s)
        n = split(s, v, " ")
        if (n != 12) exit 1
        for (i = 1; i <= n; i++) printf "%s ", v[i]
    }' "$1"
}

# The body's motion comes from the forces on the wing, the same for both motion
# solvers at the first step (same initial mesh and fields): the states after the
# first step must agree to round-off (1e-12). Afterwards the interior motion
# differs (sixDoFRigidBodyMotion: blending between inner- and outerDistance;
# dcpRBF: RBF), so the flow and the forces differ slightly: 1e-5.
# The condition must also be integrated once per step, like the stock solver:
# one "6-DoF rigid body motion" report (report on) per time step.
test_sixDoF_bodyMotionAsStockSolver() {
    local t a b diff bad="" nSteps nStock nDcp
    wingMotionCase || return 1
    foamDictionary system/controlDict -entry writeInterval -set 1 > /dev/null
    mkdir stock
    cp -r 0 constant system stock/
    (cd stock && sixDoFStock && run pimpleFoam) || fail "stock run (sixDoFRigidBodyMotion) failed: see stock/log.pimpleFoam" || return 1
    sixDoFDcpRBF
    run pimpleFoam || return 1
    echo "6-DoF state (centre of rotation, orientation), stock solver vs dcpRBF: time, max difference"
    for t in $(cd stock && foamListTimes 2>/dev/null)
    do
        a=$(sixDoFState "stock/$t/uniform/sixDoFRigidBodyMotionState") || fail "no stock state at t = $t" || return 1
        b=$(sixDoFState "$t/pointDisplacement") || fail "no dcpRBF state at t = $t" || return 1
        diff=$(echo "$a $b" | awk '{ m = 0; for (i = 1; i <= 12; i++) { d = $i - $(i + 12); if (d < 0) d = -d; if (d > m) m = d }; printf "%.3e", m }')
        echo "  t = $t: $diff"
        awk -v d="$diff" -v t="$t" -v dt=$sixDoFDeltaT 'BEGIN { exit !(d <= (t <= dt*1.0001 ? 1e-12 : 1e-5)) }' || bad="$bad $t"
    done
    [ -n "$t" ] || fail "no time written by the stock run" || return 1
    [ -z "$bad" ] || fail "the 6-DoF body moves differently under dcpRBF than under sixDoFRigidBodyMotion at t =$bad (tolerance 1e-12 at the first step, 1e-5 after)" || return 1
    nSteps=$(grep -c '^Time = ' log.pimpleFoam)
    nStock=$(grep -c '^6-DoF rigid body motion' stock/log.pimpleFoam)
    nDcp=$(grep -c '^6-DoF rigid body motion' log.pimpleFoam)
    echo "6-DoF updates: $nSteps time steps, sixDoFRigidBodyMotion $nStock, dcpRBF $nDcp"
    [ "$nDcp" -eq "$nSteps" ] || fail "the wing's sixDoFRigidBodyDisplacement condition is integrated $nDcp times in $nSteps time steps under dcpRBF (sixDoFRigidBodyMotion: $nStock): it must be updated once per step (the body state agrees today only because a repeated update from the same step start with the same forces is idempotent)"
}
