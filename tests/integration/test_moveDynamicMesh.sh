# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: moveDynamicMesh with dcpRBF on a 2D and a 3D case.
# Each test runs in its own empty folder (see lib.sh: runTest).

# pitchingPointDisplacement PATCH AXIS ORIGIN AMPLITUDE STATIC EXTRA:
# PATCH rotates about AXIS through ORIGIN by AMPLITUDE sin(pi t/2) [rad]
# (the full amplitude at t = 1); STATIC patches (regex) are fixed; EXTRA is
# added to boundaryField (e.g. the empty patches)
pitchingPointDisplacement() {
    writeFile 0/pointDisplacement pointVectorField <<EOT
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    $1
    {
        type angularOscillatingDisplacement;
        axis $2; origin $3; angle0 0;
        amplitude $4; omega 1.5707963267948966;
        value uniform (0 0 0);
    }
    "$5" { type fixedValue; value uniform (0 0 0); }
    $6
}
EOT
}

# pointDisplacement for the airfoil: pitching amplitude $1 [rad], reached at t = 1
airfoilPointDisplacement() {
    pitchingPointDisplacement wing "(0 0 -1)" "(0.25 0 0)" "$1" \
        "(inlet|outlet|topAndBottom)" "frontAndBack { type empty; }"
}

# pointDisplacement for the hollow cube: rotation about (1 1 1) by up to $1 [rad] at t = 1
hollowCubeRotation() {
    pitchingPointDisplacement body "(1 1 1)" "(0 0 0)" "$1" outer ""
}

# dynamicMeshDict with dcpRBFCoeffs body $1
dynamicMeshDict() {
    writeFile constant/dynamicMeshDict dictionary <<EOT
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs ("libdcpRBF.so");
motionSolver dcpRBF;
dcpRBFCoeffs
{
    $1
}
EOT
}

test_airfoil2D_pitch40deg_meshValidEveryStep() {
    write_motionControls .
    airfoilMesh 0.04 1.0 || return 1
    airfoilPointDisplacement 0.698
    dynamicMeshDict "movingPatches (wing); staticPatches (inlet outlet topAndBottom); supportRadius 2.5;"
    run moveDynamicMesh || return 1
    reportsSetUp WendlandC2 2D
    meshOkAtEveryTime
}

# Without movingPatches and staticPatches, the lists come from the
# pointDisplacement conditions (the wing's angularOscillatingDisplacement
# moves, the fixedValue walls stay, frontAndBack is empty), said once, and
# the points are the listed case's bit for bit; one list alone is refused
test_airfoil2D_patchListsInferred_samePointsAsListed() {
    write_motionControls .
    airfoilMesh 0.04 1.0 || return 1
    airfoilPointDisplacement 0.698
    mkdir -p inferred
    cp -r constant system 0 inferred/
    dynamicMeshDict "movingPatches (wing); staticPatches (inlet outlet topAndBottom); supportRadius 2.5;"
    run moveDynamicMesh || return 1
    (
        cd inferred || exit 1
        dynamicMeshDict "supportRadius 2.5;"
        run moveDynamicMesh || exit 1
    ) || fail "the inferred case failed (see inferred/log.moveDynamicMesh)" || return 1
    grep -q "^dcpRBF: movingPatches 1(wing) and staticPatches 3(topAndBottom outlet inlet) from the pointDisplacement conditions" \
        inferred/log.moveDynamicMesh || fail "no inference line: $(grep -m1 'movingPatches' inferred/log.moveDynamicMesh)" || return 1
    [ "$(grep -c 'from the pointDisplacement conditions' inferred/log.moveDynamicMesh)" -eq 1 ] \
        || fail "the inference said more than once" || return 1
    local t
    t=$(writtenTimes . | sort -g | tail -n 1)
    pointsAgree "$t/polyMesh/points" "inferred/$t/polyMesh/points" 0 "listed vs inferred at t = $t" || return 1
    (
        cd inferred || exit 1
        dynamicMeshDict "movingPatches (wing); supportRadius 2.5;"
        ! moveDynamicMesh > log.oneList 2>&1 || exit 2
        grep -A3 "FOAM FATAL IO ERROR" log.oneList | grep -q "staticPatches" || exit 3
    )
    case $? in
    (0) ;;
    (2) fail "movingPatches without staticPatches was accepted" ;;
    (*) fail "the refusal of one list does not name staticPatches: $(grep -A3 'FOAM FATAL' inferred/log.oneList)" ;;
    esac
}

# One word: a dynamicMeshDict with motionSolver dcpRBF and no dcpRBFCoeffs
# (and the former solver's diffusivity and coefficients left in it) moves the mesh as
# dcpRBFCoeffs { supportRadius D; } does, D the reference mesh's diagonal in
# its plane (the default radius), the patch lists inferred, selection all
# (102 boundary points, at most maxPoints): the points bit for bit; the log
# says once what it did not read and that the radius was not given
test_airfoil2D_noCoeffs_samePointsAsTheDefaultsGiven() {
    local r t
    write_motionControls .
    airfoilMesh 0.04 1.0 || return 1
    airfoilPointDisplacement 0.698
    mkdir -p given
    cp -r constant system 0 given/
    r=$(awk '/^\(-?[0-9]/ { gsub(/[()]/, ""); if (n++ == 0) { x0 = x1 = $1; y0 = y1 = $2 }
             if ($1 < x0) x0 = $1; if ($1 > x1) x1 = $1; if ($2 < y0) y0 = $2; if ($2 > y1) y1 = $2 }
             END { printf "%.17g", sqrt((x1 - x0)^2 + (y1 - y0)^2) }' constant/polyMesh/points)
    writeFile constant/dynamicMeshDict dictionary <<'EOT'
dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs ("libdcpRBF.so");
motionSolver dcpRBF;
diffusivity quadratic inverseDistance (wing);
displacementLaplacianCoeffs { diffusivity uniform; }
EOT
    run moveDynamicMesh || return 1
    [ "$(grep -c "^dcpRBF: no dcpRBFCoeffs in dynamicMeshDict: every setting at its default (diffusivity displacementLaplacianCoeffs: not dcpRBF's keywords, which it ignores; a mesh class may read them)" log.moveDynamicMesh)" -eq 1 ] \
        || fail "no single line on the missing dcpRBFCoeffs: $(grep -m1 'dcpRBFCoeffs' log.moveDynamicMesh)" || return 1
    grep -q "supportRadius [0-9.e+]* (not given: the mesh's extent), .*selection all)" log.moveDynamicMesh \
        || fail "the default radius not said: $(grep -m1 'boundary points (' log.moveDynamicMesh)" || return 1
    (
        cd given || exit 1
        dynamicMeshDict "supportRadius $r;"
        run moveDynamicMesh || exit 1
    ) || fail "the case with the radius given failed (see given/log.moveDynamicMesh)" || return 1
    t=$(writtenTimes . | sort -g | tail -n 1)
    pointsAgree "$t/polyMesh/points" "given/$t/polyMesh/points" 0 "no dcpRBFCoeffs vs supportRadius $r at t = $t"
}

test_hollowCube3D_rotate30deg_meshValidEveryStep() {
    write_hollowCube . 6
    run blockMesh || return 1
    hollowCubeRotation 0.5236
    dynamicMeshDict "movingPatches (body); staticPatches (outer); function WendlandC2; supportRadius 1.5;"
    run moveDynamicMesh || return 1
    reportsSetUp WendlandC2 3D
    meshOkAtEveryTime
}

test_airfoil2D_pimpleFoam_runs() {
    cp -r "$top/tutorials/pitchingAirfoil2D/system" "$top/tutorials/pitchingAirfoil2D/constant" .
    rm -rf constant/polyMesh
    cp -r "$top/tutorials/pitchingAirfoil2D/0.orig" 0
    airfoilMesh 0.04 1.0 || return 1
    foamDictionary system/controlDict -entry endTime -set 0.1 > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 0.05 > /dev/null
    foamDictionary system/controlDict -entry functions -remove > /dev/null
    run pimpleFoam || return 1
    tail -n 3 log.pimpleFoam | grep -q '^End' || fail "pimpleFoam did not end"
    meshOkAtEveryTime
}

# staticHollowCube: a coarse hollow cube with every patch fixed
staticHollowCube() {
    write_hollowCube . 2
    run blockMesh || return 1
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { ".*" { type fixedValue; value uniform (0 0 0); } }
EOT
}

test_badFunction_fatalIOErrorFromTheUtility() {
    staticHollowCube || return 1
    dynamicMeshDict "movingPatches (body); staticPatches (outer); function cubicSpline; supportRadius 1;"
    if moveDynamicMesh > log.moveDynamicMesh 2>&1
    then
        fail "moveDynamicMesh accepted function cubicSpline"
    fi
    grep -q "FOAM FATAL IO ERROR" log.moveDynamicMesh || fail "no FatalIOError"
    grep -q "Unknown function cubicSpline" log.moveDynamicMesh || fail "error does not name the function"
    grep -q "WendlandC2" log.moveDynamicMesh || fail "error does not list the allowed functions"
}

# A patch in neither list: one whose condition follows the interpolation
# (slip) is said to do so; one whose condition fixes its values is said to
# move by them, with what to do (the two warnings apart)
# outerCondition TYPE_AND_VALUE: the hollow cube's body fixed, outer with this condition
outerCondition() {
    writeFile 0/pointDisplacement pointVectorField <<EOT
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { body { type fixedValue; value uniform (0 0 0); } outer { $1 } }
EOT
}

test_unlistedPatch_warns() {
    staticHollowCube
    dynamicMeshDict "movingPatches (body); staticPatches (); supportRadius 1;"
    foamDictionary system/controlDict -entry endTime -set 0.1 > /dev/null
    mkdir fixed
    cp -r constant system fixed/
    outerCondition "type slip;"
    run moveDynamicMesh
    warningText "Patches in neither movingPatches nor staticPatches: " 2 "no warning for the slip patch outer"
    grep -q "1(outer) *Their points move with the interpolated displacement" warning \
        || fail "the slip patch's warning does not name outer or say what happens: $(head -c 300 warning)"
    ! grep -q "whose pointDisplacement condition fixes" log.moveDynamicMesh \
        || fail "the slip patch is said to be moved by its own condition"

    cd fixed || fail "no folder fixed"
    outerCondition "type fixedValue; value uniform (0 0 0);"
    run moveDynamicMesh
    warningText "whose pointDisplacement condition fixes their points' values" 3 \
        "no warning for the fixed-value patch outer"
    grep -q "values: outer .*List a patch that moves under movingPatches, one that stays put under staticPatches" warning \
        || fail "the fixed-value patch's warning does not name outer or say what to do: $(head -c 400 warning)"
}
