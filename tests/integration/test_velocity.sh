# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: cases driven by another field than pointDisplacement,
# switched by one word: a point velocity (a pointMotionU and no
# pointDisplacement, or a mesh class that sets the point velocity itself,
# interfaceTrackingFvMesh: dcpRBFVelocityMotionSolver) and one component of
# a velocity or displacement (pointMotionUx, pointDisplacementx:
# dcpRBFComponentMotionSolver). motionSolver dcpRBF moves the boundary as
# the stock solver does (x += deltaT U) and interpolates the rest.

# oneWordDynamicMeshDict SOLVER [LIBS]: constant/dynamicMeshDict with the
# motion solver SOLVER and nothing else (dcpRBF: no dcpRBFCoeffs; a stock
# solver: its uniform diffusivity)
oneWordDynamicMeshDict() {
    local libs='"libdcpRBF.so"'
    [ $# -gt 1 ] && libs="$2"
    writeFile constant/dynamicMeshDict dictionary <<EOT
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs ($libs);
motionSolver $1;
diffusivity uniform;
EOT
}

# movingConeVelocityCase [CONE]: the planar movingCone (test_movingCone.sh)
# driven by a point velocity: the cone's condition CONE (default 1 m/s in
# x), the far field slip, the end walls fixedValue zero; no
# pointDisplacement; one word
movingConeVelocityCase() {
    local cone="${1:-type fixedValue; value uniform (1 0 0);}"
    movingConePlanarCase || return 1
    rm -f 0/pointDisplacement
    writeFile 0/pointMotionU pointVectorField <<EOT
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    movingWall { $cone }
    "(farField|farFieldMoving)" { type slip; }
    "(fixedWall|left)" { type fixedValue; value uniform (0 0 0); }
    axis { type symmetryPlane; }
    "(front|back)" { type empty; }
}
EOT
    oneWordDynamicMeshDict dcpRBF
}

# patchPointsAgree PATCH A B MAXREL: the points of PATCH (the reference
# mesh's labels) in point files A and B differ by at most MAXREL of the
# reference mesh's diagonal; prints it
patchPointsAgree() {
    awk -v patch="$1" -f "$here/cases/patchPoints.awk" constant/polyMesh/boundary constant/polyMesh/faces \
        > "$1.labels" || fail "no patch $1" || return 1
    awk -v maxRel="$4" '
        function read(line, v) { gsub(/[()]/, "", line); return split(line, v, " ") }
        FNR == 1 { file++; i = 0 }
        file == 1 { want[$1] = 1; next }
        /^\(-?[0-9]/ {
            read($0, v)
            if (file == 2) {
                for (c = 1; c <= 3; c++) { if (i == 0 || v[c] < lo[c]) lo[c] = v[c]; if (i == 0 || v[c] > hi[c]) hi[c] = v[c] }
            } else if (i in want) {
                if (file == 3) { for (c = 1; c <= 3; c++) a[i, c] = v[c] }
                else { n++; d = 0; for (c = 1; c <= 3; c++) d += (v[c] - a[i, c])^2; if (d > m) m = d }
            }
            i++
        }
        END {
            diag = sqrt((hi[1] - lo[1])^2 + (hi[2] - lo[2])^2 + (hi[3] - lo[3])^2)
            printf "%s: %d points, largest difference %g of the diagonal\n", patch, n, sqrt(m)/diag
            exit !(n > 0 && sqrt(m)/diag <= maxRel)
        }' patch="$1" "$1.labels" constant/polyMesh/points "$2" "$3" \
        || fail "patch $1's points differ by more than $4 of the diagonal between $2 and $3"
}

# The cone driven by its velocity (oscillatingVelocity: each step the
# velocity that takes the points from where they are to 0.5 sin(3000 t) mm
# along x), one word: the log says so once and names
# the patches inferred from the velocity's conditions (every fixed-value
# kind moves: a velocity may be set while running), the mesh is valid at
# every write, and the cone's points are velocityLaplacian's (both move
# them by deltaT U each step) to round-off
test_movingConeVelocity_oneWordMovesTheConeAsVelocityLaplacian() {
    movingConeVelocityCase "type oscillatingVelocity; amplitude (0.0005 0 0); omega 3000; value uniform (0 0 0);" || return 1
    mkdir -p stock
    cp -r 0 constant system stock/
    sed -i 's/cellMotionUx/cellMotionU/' stock/system/fvSolution
    (cd stock && oneWordDynamicMeshDict velocityLaplacian fvMotionSolvers && run moveDynamicMesh) \
        || fail "the stock run failed (see stock/log.*)" || return 1
    run moveDynamicMesh || return 1
    [ "$(grep -c "^dcpRBF: velocity-driven (pointMotionU, dynamicFvMesh dynamicMotionSolverFvMesh)" log.moveDynamicMesh)" -eq 1 ] \
        || fail "the velocity-driven case not said once: $(grep -m3 '^dcpRBF' log.moveDynamicMesh)" || return 1
    grep -q "^dcpRBF: movingPatches 3(movingWall fixedWall left) and staticPatches 0()" log.moveDynamicMesh \
        || fail "not every fixed-value patch inferred moving: $(grep -m1 '^dcpRBF: movingPatches' log.moveDynamicMesh)" || return 1
    meshOkAtEveryTime || return 1
    patchPointsAgree movingWall 0.0005/polyMesh/points stock/0.0005/polyMesh/points 1e-12 || return 1
    patchPointsAgree fixedWall 0.0005/polyMesh/points stock/0.0005/polyMesh/points 0
}

# On 2 processors (simple 2 1 1: split through the cone and the far field)
test_movingConeVelocity_parallelEqualsSerial() {
    movingConeVelocityCase || return 1
    foamDictionary system/controlDict -entry endTime -set 0.00025 > /dev/null
    parallelEqualsSerial 0.00025
}

# Restarted at half time: the points and dcpRBF's steps as the
# uninterrupted run's (the boundary's displacement taken from the written
# points: x^n - x^0 + deltaT U); the cone at 0.5 mm/s for 1 s in 20 steps.
# The points to 1e-13 of the diagonal, not the displacement cases' 1e-14:
# the first steps after a restart differ from the uninterrupted run's by
# round-off, 3e-14 of the diagonal (as a displacement case's do, measured
# writing every step: the restarted run's set evaluated and refactorized
# anew), and here each step's boundary displacement comes from the last
# step's points, so it lasts to t = 1 (5.3e-14); a displacement case's
# steps are independent and agree again by t = 1 (1e-17)
test_movingConeVelocity_restartEqualsUninterrupted() {
    movingConeVelocityCase || return 1
    foamDictionary system/controlDict -entry startFrom -set latestTime > /dev/null
    foamDictionary system/controlDict -entry deltaT -set 0.05 > /dev/null
    foamDictionary system/controlDict -entry endTime -set 1 > /dev/null
    sed -i 's/value uniform (1 0 0);/value uniform (0.0005 0 0);/' 0/pointMotionU
    restartEqualsUninterrupted 1 ascii 1e-13
}

# sloshing2DCase DIR SOLVER: OpenFOAM's sloshing2D (interfaceTrackingFvMesh:
# the free surface's point velocity set from the flux each step) in DIR,
# 20 steps, with motionSolver SOLVER
sloshing2DCase() {
    local tut="$FOAM_TUTORIALS/incompressible/pimpleFoam/laminar/sloshing2D"
    [ -d "$tut" ] || fail "no OpenFOAM tutorial at $tut (FOAM_TUTORIALS: re-run ./Allwmake)" || return 1
    mkdir -p "$1" && cp -r "$tut/." "$1/"
    (
        cd "$1" || exit 1
        foamDictionary system/controlDict -entry endTime -set 0.4 > /dev/null
        foamDictionary system/controlDict -entry writeInterval -set 5 > /dev/null
        foamDictionary system/controlDict -entry writePrecision -set 17 > /dev/null
        run blockMesh && run makeFaMesh || exit 1
        # (makeWave, the tutorial's initial wave, casts the motion solver to
        # velocityLaplacian's: run before the switch)
        (cd makeWave && wmake > ../log.wmake 2>&1) || fail "makeWave did not build (see $1/log.wmake)"
        run makeWave || exit 1
        sed -i "s/^motionSolver .*/motionSolver $2;/" constant/dynamicMeshDict
        if [ "$2" = dcpRBF ]
        then
            sed -i 's/^motionSolverLibs (\(.*\));/motionSolverLibs (\1 "libdcpRBF.so");/' constant/dynamicMeshDict
        fi
        grep -q "^motionSolver $2;" constant/dynamicMeshDict || fail "could not switch the tutorial's motionSolver"
        run pimpleFoam
    )
}

# The tutorial switched by one word (velocityLaplacian -> dcpRBF): the mesh
# class casts its solver to velocityMotionSolver and sets the free
# surface's velocity; the run ends, the mesh valid at every write, the free
# surface where the stock run puts it (both move it by deltaT U; U comes
# from the flow, which sees the interior cells each solver makes: measured
# 5.5e-5 of the diagonal after 20 steps, the surface moved 5.0e-3), the
# bottom still
test_sloshing2D_oneWordFreeSurfaceAsVelocityLaplacian() {
    sloshing2DCase stock velocityLaplacian || fail "the stock run failed (see stock/log.*)" || return 1
    sloshing2DCase dcp dcpRBF || return 1
    grep -q "^dcpRBF: velocity-driven (pointMotionU, dynamicFvMesh interfaceTrackingFvMesh)" dcp/log.pimpleFoam \
        || fail "the velocity-driven case not said: $(grep -m3 '^dcpRBF' dcp/log.pimpleFoam)" || return 1
    cd dcp || return 1
    meshOkAtEveryTime || return 1
    patchPointsAgree top 0.4/polyMesh/points ../stock/0.4/polyMesh/points 2e-4 || return 1
    patchPointsAgree bottom 0.4/polyMesh/points constant/polyMesh/points 0
}

# The stock tutorial movingCone (the wedge, velocityComponentLaplacian x:
# pointMotionUx, its directional diffusivity left in the dictionary)
# switched by one word: the log names the diffusivity as not read (not the
# component), the cone's points as the stock run's to round-off after 100
# steps, the mesh valid, the points on their wedge planes and the axis
test_movingConeStock_oneWordMovesAsVelocityComponentLaplacian() {
    local tut="$FOAM_TUTORIALS/incompressible/pimpleFoam/laminar/movingCone"
    [ -d "$tut" ] || fail "no OpenFOAM tutorial at $tut (FOAM_TUTORIALS: re-run ./Allwmake)" || return 1
    cp -r "$tut/0" "$tut/constant" "$tut/system" .
    foamDictionary system/controlDict -entry functions -remove > /dev/null
    writeFile system/controlDict dictionary <<'EOT'
application moveDynamicMesh; startFrom startTime; startTime 0; stopAt endTime;
endTime 0.0005; deltaT 5e-06; writeControl timeStep; writeInterval 50;
writeFormat ascii; writePrecision 17; timeFormat general; timePrecision 8;
EOT
    run blockMesh || return 1
    mkdir -p stock && cp -r 0 constant system stock/
    (cd stock && run moveDynamicMesh) || fail "the stock run failed (see stock/log.*)" || return 1
    sed -i 's/^motionSolver .*/motionSolver dcpRBF;/; s/^motionSolverLibs .*/motionSolverLibs ("libdcpRBF.so");/' constant/dynamicMeshDict
    grep -q '^motionSolver dcpRBF;' constant/dynamicMeshDict || fail "could not switch the tutorial's motionSolver" || return 1
    run moveDynamicMesh || return 1
    grep -q "^dcpRBF: driven by pointMotionUx (component x of the point velocity)" log.moveDynamicMesh \
        || fail "the component case not said: $(grep -m3 '^dcpRBF' log.moveDynamicMesh)" || return 1
    # the component read, the diffusivity not
    grep -q "^dcpRBF: no dcpRBFCoeffs in dynamicMeshDict: every setting at its default (diffusivity: not dcpRBF's keywords, which it ignores; a mesh class may read them)" log.moveDynamicMesh \
        || fail "the keywords not read not named as they are: $(grep -m1 'no dcpRBFCoeffs' log.moveDynamicMesh)" || return 1
    meshOkAtEveryTime || return 1
    onWedgeAndAxis 0.0005 1e-6 || return 1
    patchPointsAgree movingWall 0.0005/polyMesh/points stock/0.0005/polyMesh/points 1e-12
}

# The planar cone driven by a displacement component as
# displacementComponentLaplacian reads it (pointDisplacementx, the component
# in displacementComponentLaplacianCoeffs), one word: the cone's points as
# the stock run's
test_movingConeDisplacementComponent_oneWordMovesAsDisplacementComponentLaplacian() {
    movingConePlanarCase || return 1
    rm -f 0/pointDisplacement
    writeFile 0/pointDisplacementx pointScalarField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform 0;
boundaryField
{
    movingWall { type uniformFixedValue; uniformValue table ((0 0) (1 1)); value uniform 0; }
    "(farField|farFieldMoving)" { type slip; }
    "(fixedWall|left)" { type fixedValue; value uniform 0; }
    axis { type symmetryPlane; }
    "(front|back)" { type empty; }
}
EOT
    writeFile constant/dynamicMeshDict dictionary <<'EOT'
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs ("libdcpRBF.so");
motionSolver dcpRBF;
displacementComponentLaplacianCoeffs { component x; diffusivity uniform; applyPointLocation false; }
EOT
    mkdir -p stock && cp -r 0 constant system stock/
    sed -i 's/cellMotionUx/cellDisplacementx/' stock/system/fvSolution
    sed -i 's/^motionSolver .*/motionSolver displacementComponentLaplacian;/; s/^motionSolverLibs .*/motionSolverLibs (fvMotionSolvers);/' stock/constant/dynamicMeshDict
    (cd stock && run moveDynamicMesh) || fail "the stock run failed (see stock/log.*)" || return 1
    run moveDynamicMesh || return 1
    grep -q "^dcpRBF: driven by pointDisplacementx (component x of the point displacement)" log.moveDynamicMesh \
        || fail "the component case not said: $(grep -m3 '^dcpRBF' log.moveDynamicMesh)" || return 1
    # the coefficients the component came from not named as ignored
    grep -q "^dcpRBF: no dcpRBFCoeffs in dynamicMeshDict: every setting at its default$" log.moveDynamicMesh \
        || fail "keywords named as ignored: $(grep -m1 'no dcpRBFCoeffs' log.moveDynamicMesh)" || return 1
    meshOkAtEveryTime || return 1
    patchPointsAgree movingWall 0.0005/polyMesh/points stock/0.0005/polyMesh/points 1e-12
}
