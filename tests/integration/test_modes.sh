# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: greedy and dynamic control points with moveDynamicMesh.

airfoilCoeffs() {
    echo "movingPatches (wing); staticPatches (inlet outlet topAndBottom);"
    echo " supportRadius 4; qualityFloor 0.1; controlPoints { $1 }"
}

cubeCoeffs() {
    echo "movingPatches (body); staticPatches (outer); supportRadius 1.5 movingExtent;"
    echo " controlPoints { $1 }"
}

# modeRun2D SELECTION: the 2D airfoil pitched 60 deg in 10 steps
modeRun2D() {
    write_motionControls .
    airfoilMesh 0.03 1.0 || return 1
    airfoilPointDisplacement 1.047
    dynamicMeshDict "$(airfoilCoeffs "$1")"
}

# modeRun3D SELECTION: the hollow cube rotated 30 deg
modeRun3D() {
    write_hollowCube . 5
    run blockMesh || return 1
    hollowCubeRotation 0.5236
    dynamicMeshDict "$(cubeCoeffs "$1")"
}

# checkModeLog SELECTION: the log shows the selection at work
checkModeLog() {
    grep -q "selection $1)" log.moveDynamicMesh || fail "no selection $1 in the log"
    grep -q "greedy selection of" log.moveDynamicMesh || fail "no greedy selection"
    [ -f postProcessing/dcpRBF/0/dcpRBF.dat ] || fail "no time series"
    ls postProcessing/dcpRBF/controlPoints_*.vtk > /dev/null 2>&1 || fail "no control points VTK"
    [ -f 1/uniform/dcpRBFState ] || fail "no restart state written"
}

test_greedy2D_pitch60deg_meshValidEveryStep() {
    modeRun2D "selection greedy; tolerance 1e-2;" || return 1
    run moveDynamicMesh || return 1
    checkModeLog greedy && meshOkAtEveryTime
}

test_dynamic2D_pitch60deg_meshValidEveryStep() {
    modeRun2D "selection dynamic; tolerance 1e-2; nSwap 2;" || return 1
    run moveDynamicMesh || return 1
    checkModeLog dynamic || return 1
    # swaps are tried (errorGuided: kept, nAdded and nRemoved > 0, where
    # they help, else undone, nUndone > 0)
    awk '!/^#/ && (($3 > 0 && $4 > 0) || $15 > 0) { found = 1 } END { exit !found }' \
        postProcessing/dcpRBF/0/dcpRBF.dat || fail "no swap tried in postProcessing/dcpRBF/0/dcpRBF.dat"
    meshOkAtEveryTime
}

test_greedy3D_rotate30deg_meshValidEveryStep() {
    modeRun3D "selection greedy; tolerance 1e-2;" || return 1
    run moveDynamicMesh || return 1
    checkModeLog greedy && meshOkAtEveryTime
}

test_dynamic3D_rotate30deg_meshValidEveryStep() {
    modeRun3D "selection dynamic; tolerance 1e-2;" || return 1
    run moveDynamicMesh || return 1
    checkModeLog dynamic && meshOkAtEveryTime
}

test_dynamic2D_parallelEqualsSerial() {
    modeRun2D "selection dynamic; tolerance 1e-2; nSwap 2;" || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    parallelEqualsSerial 0.5
}

test_greedy3D_parallelEqualsSerial() {
    modeRun3D "selection greedy; tolerance 1e-2;" || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    parallelEqualsSerial 0.5
}

test_dynamic3D_parallelEqualsSerial() {
    modeRun3D "selection dynamic; tolerance 1e-2; nSwap 2;" || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    parallelEqualsSerial 0.5
}

test_dynamic2D_restartEqualsUninterrupted_parallel() {
    modeRun2D "selection dynamic; tolerance 1e-2; nSwap 2;" || return 1
    restartEqualsUninterrupted 2
}

test_qualityFloorStop_fatalErrorWhenUnmet() {
    modeRun3D "selection all;" || return 1
    dynamicMeshDict "$(cubeCoeffs "selection all;") qualityFloor 0.99; qualityFloorAction stop;"
    # selection all: no point can join, the error says what can help
    stoppedBelowFloor "below qualityFloor 0.99 .*every boundary point is a control point: more cannot help.*raise supportRadius"
}

test_qualityGuard_addsPointsInStep() {
    modeRun2D "selection greedy; tolerance 5e-2;" || return 1
    dynamicMeshDict "$(airfoilCoeffs "selection greedy; tolerance 5e-2;") qualityFloor 0.6; guardIterations 3;"
    run moveDynamicMesh || return 1
    # some step added points in-step (column nGuard: the guard's own count) and the floor shortfall is reported or met
    awk '!/^#/ && $5 > 0 { found = 1 } END { exit !found }' postProcessing/dcpRBF/0/dcpRBF.dat \
        || fail "the guard never added a point"
    meshOkAtEveryTime
}

# The guard stopped by guardIterations: the error names it and what else to
# raise when more points do not help
test_qualityFloorStop_atGuardIterationsNamesIt() {
    modeRun3D "selection greedy; tolerance 1e-2;" || return 1
    dynamicMeshDict "$(cubeCoeffs "selection greedy; tolerance 1e-2;") qualityFloor 0.999; qualityFloorAction stop; guardIterations 1;"
    stoppedBelowFloor "after 1 guard additions (guardIterations 1; where more points do not raise the minimum, raise supportRadius)"
}

test_dcpRBFFvMesh_writesCellQuality() {
    modeRun3D "selection dynamic;" || return 1
    sed -i 's/^dynamicFvMesh .*/dynamicFvMesh dcpRBFFvMesh;\ndynamicFvMeshLibs ("libdcpRBF.so");/' constant/dynamicMeshDict
    run moveDynamicMesh || return 1
    grep -q "dcpRBFFvMesh: cell quality min" log.moveDynamicMesh || fail "no quality log line"
    [ -f 1/cellQuality ] || fail "1/cellQuality not written"
    # quality is 1 at rest (to round-off) and lower after the rotation
    awk '/^dcpRBFFvMesh: cell quality min/ { q[n++] = $5 + 0 }
         END { exit !(n >= 2 && q[0] > 1 - 1e-12 && q[n - 1] < 0.99) }' log.moveDynamicMesh \
        || fail "quality not 1 at rest, or not lower after the rotation: $(grep 'dcpRBFFvMesh: cell quality' log.moveDynamicMesh | sed -n '1p;$p' | tr '\n' ' ')"
    tail -n 5 log.moveDynamicMesh | grep -q "End" || fail "did not end"
}

# The guard cannot add a point to a set at maxPoints: the error says so and
# names the keyword to raise (not only "after 0 guard additions")
test_qualityFloorStop_atMaxPointsNamesIt() {
    modeRun3D "selection greedy; tolerance 1e-2;" || return 1
    dynamicMeshDict "$(cubeCoeffs "selection greedy; tolerance 1e-12; minPoints 8; maxPoints 8; reselectTolerance 1e9;") qualityFloor 0.99; qualityFloorAction stop;"
    stoppedBelowFloor "after 0 guard additions (the set is at maxPoints 8: no point can join; raise maxPoints)"
}

# The fewest control points the polynomial takes (maxPoints dim+1, legal):
# every centre is needed by it, none can leave, so no trial swap is made
# (a leave-one-out error divided by zero crashed the run: SIGFPE); the run
# ends, inverted cells reported where checkMesh finds them
test_dynamic_fewestPointsThePolynomialTakes_noCrash() {
    local d
    for d in 2 3
    do
        mkdir -p "$d"D
        (
            cd "$d"D || exit 1
            if [ "$d" = 2 ]
            then
                modeRun2D "selection dynamic; maxPoints 3;"
            else
                modeRun3D "selection dynamic; maxPoints 4;"
            fi
            run moveDynamicMesh
            tail -n 3 log.moveDynamicMesh | grep -q '^End' || fail "${d}D: did not end"
            awk '!/^#/ && $2 != '"$((d + 1))"' { bad = 1 } END { exit bad }' postProcessing/dcpRBF/0/dcpRBF.dat \
                || fail "${d}D: not $((d + 1)) control points at every step"
            ! grep -q "trial swap" log.moveDynamicMesh || fail "${d}D: a trial swap with no removable point"
            invertedWhereCheckMeshFails any
        ) || fail "${d}D failed: $(tail -n 3 "$d"D/log.moveDynamicMesh)"
    done
}
