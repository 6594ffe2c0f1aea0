# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests of rotationInterpolation (issue 11): large rotations stay
# valid where displacement interpolation folds cells; serial == parallel on
# a manual decomposition through the wing; a restart continues the angle
# past half a turn.

rotationCoeffs2D="movingPatches (wing); staticPatches (inlet outlet topAndBottom); supportRadius 2.5; rotationInterpolation true; rotation { centre (0.25 0 0); }"

# lastTimeMeshOk: checkMesh of the latest time passes
lastTimeMeshOk() {
    run checkMesh -latestTime -noTopology || return 1
    grep -q '^Mesh OK' log.checkMesh
}

# displacementFolds COEFFS: in displacement/, a copy of the case run with
# dcpRBFCoeffs COEFFS (no rotationInterpolation) has an invalid last mesh
displacementFolds() {
    mkdir -p displacement
    cp -r constant system 0 displacement/
    (
        cd displacement || exit 1
        dynamicMeshDict "$1"
        run moveDynamicMesh || exit 1
        ! lastTimeMeshOk
    ) || fail "displacement interpolation gave a valid mesh: the test case is too easy"
}

# 2D: the airfoil (channel +-5 chords) pitched 150 deg about its quarter
# chord: displacement interpolation folds cells, rotationInterpolation not
test_rotation2D_airfoil_pitch150deg_validWhereDisplacementFolds() {
    write_motionControls .
    airfoilMesh 0.04 1.0 || return 1
    airfoilPointDisplacement 2.618
    displacementFolds "movingPatches (wing); staticPatches (inlet outlet topAndBottom); supportRadius 2.5;" || return 1
    dynamicMeshDict "$rotationCoeffs2D"
    run moveDynamicMesh || return 1
    grep -q "body movingPatches: rotation -150.000" log.moveDynamicMesh \
        || fail "no rotation of -150 deg (about +z) in the log" || return 1
    meshOkAtEveryTime
}

# studies/largeRotation/foldScan predicts where a blend folds without a run.
# On the 150 deg case, whose every written mesh is valid, it finds no fold up
# to 150 deg in the run's direction; with the blend cut to a step (1 where it
# is 1, 0 elsewhere: the whole twist in one layer of cells) it finds one
# within 20 deg
test_rotation2D_foldScan_agreesWithTheRun() {
    local py
    write_motionControls .
    airfoilMesh 0.04 1.0 || return 1
    airfoilPointDisplacement 2.618
    dynamicMeshDict "$rotationCoeffs2D"
    run moveDynamicMesh || return 1
    meshOkAtEveryTime || return 1
    py=$(pythonWithGmsh) || fail "no python with gmsh" || return 1
    "$py" -c "import numpy" 2> /dev/null || fail "no numpy for $py (foldScan needs it)" || return 1
    # nose up: -150 deg about +z, i.e. +150 about -z (foldScan's first axis)
    "$py" "$top/studies/largeRotation/foldScan" . --centre 0.25 0 0 --axis 0 0 -1 \
        --max 150 > log.foldScan 2>&1 || fail "foldScan failed: $(tail -3 log.foldScan)" || return 1
    grep -m1 "^  axis" log.foldScan | grep -q "no fold up to 150 deg" \
        || fail "foldScan finds a fold the run does not have: $(grep -m1 '^  axis' log.foldScan)" || return 1
    mkdir -p step/0
    cp -r constant system step/
    awk '/^[-0-9.eE+]+$/ && list { print ($1 >= 1 ? 1 : 0); next }
         /^\($/ { list = 1 } /^\)/ { list = 0 } { print }' 0/rotationBlend > step/0/rotationBlend
    "$py" "$top/studies/largeRotation/foldScan" step --centre 0.25 0 0 --axis 0 0 -1 \
        --max 20 > log.foldScan.step 2>&1 \
        || fail "foldScan failed on the step blend: $(tail -3 log.foldScan.step)" || return 1
    grep -m1 "^  axis" log.foldScan.step | grep -q "first fold at [0-9]* deg" \
        || fail "foldScan finds no fold of the step blend within 20 deg: $(grep -m1 '^  axis' log.foldScan.step)"
}

# airfoilSlab3D AMPLITUDE: the airfoil mesh with symmetry sides instead of
# empty ones, so that the motion is solved in 3D (3D fit, star-shaped ring on
# the sphere), pitched by AMPLITUDE [rad] at t = 1
airfoilSlab3D() {
    write_motionControls .
    airfoilMesh 0.04 1.0 || return 1
    foamDictionary constant/polyMesh/boundary -entry entry0/frontAndBack/type -set symmetry > /dev/null
    pitchingPointDisplacement wing "(0 0 -1)" "(0.25 0 0)" "$1" \
        "(inlet|outlet|topAndBottom)" "frontAndBack { type symmetry; }"
}

rotationCoeffs3D="movingPatches (wing); staticPatches (inlet outlet topAndBottom); supportRadius 2.5; rotationInterpolation true; rotation { centre (0.25 0 0.05); }"

# 3D, pitched 120 deg: displacement interpolation folds cells,
# rotationInterpolation not
test_rotation3D_airfoilSlab_pitch120deg_validWhereDisplacementFolds() {
    airfoilSlab3D 2.0944 || return 1
    displacementFolds "movingPatches (wing); staticPatches (inlet outlet topAndBottom); supportRadius 2.5;" || return 1
    dynamicMeshDict "$rotationCoeffs3D"
    run moveDynamicMesh || return 1
    grep -q "3D, selection" log.moveDynamicMesh || fail "not solved in 3D" || return 1
    grep -q "rotation 120.000.* about (0 0 -1)" log.moveDynamicMesh \
        || fail "no rotation of 120 deg about -z in the log" || return 1
    meshOkAtEveryTime
}

# 3D, 2 processors (simple decomposition through the wing) equal serial,
# greedy selection (the rest is zero: rotation only)
test_rotation3D_airfoilSlab_parallelEqualsSerial() {
    airfoilSlab3D 2.0944 || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    dynamicMeshDict "$rotationCoeffs3D controlPoints { selection greedy; }"
    parallelEqualsSerial 0.5
}

# the bending, stretching wing (a non-rigid rest) under rotationInterpolation
# on the manual decomposition through the wing: every selection, with and
# without boundary correction, equals serial
test_rotation2D_parallelManual_bendingWing_equalsSerial() {
    bendingWingCase || return 1
    everySelectionParallelEqualsSerial 0.5 "$rotationCoeffs2D" correctionMoves
}

# restart at t = 0.5 (163 deg) to t = 1 (230 deg): the restarted run must
# continue the angle past 180 deg, not jump to -170 deg; every mode
rotationRun2D() {
    write_motionControls .
    airfoilMesh 0.04 1.0 || return 1
    airfoilPointDisplacement 4.0143
    dynamicMeshDict "$rotationCoeffs2D controlPoints { $1 }"
}

test_rotation2D_restartPastHalfATurn_everyMode() {
    restartEveryMode 1 rotationRun2D
}
