# Integration tests: moveDynamicMesh with dcpRBF on a 2D and a 3D case.
# Each test runs in its own empty folder (see lib.sh: runTest).

# pointDisplacement for the airfoil: pitching amplitude $1 [rad], reached at t = 1
airfoilPointDisplacement() {
    writeFile 0/pointDisplacement pointVectorField <<EOT
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    wing
    {
        type angularOscillatingDisplacement;
        axis (0 0 -1); origin (0.25 0 0); angle0 0;
        amplitude $1; omega 1.5707963267948966;
        value uniform (0 0 0);
    }
    "(inlet|outlet|topAndBottom)" { type fixedValue; value uniform (0 0 0); }
    frontAndBack { type empty; }
}
EOT
}

# pointDisplacement for the hollow cube: rotation about (1 1 1) by up to $1 [rad] at t = 1
hollowCubeRotation() {
    writeFile 0/pointDisplacement pointVectorField <<EOT
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    body
    {
        type angularOscillatingDisplacement;
        axis (1 1 1); origin (0 0 0); angle0 0;
        amplitude $1; omega 1.5707963267948966;
        value uniform (0 0 0);
    }
    outer { type fixedValue; value uniform (0 0 0); }
}
EOT
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
    grep -q "dcpRBF: .* control points (WendlandC2.*2D)" log.moveDynamicMesh || fail "no dcpRBF log line"
    meshOkAtEveryTime
}

test_hollowCube3D_rotate30deg_meshValidEveryStep() {
    write_hollowCube . 6
    run blockMesh || return 1
    hollowCubeRotation 0.5236
    dynamicMeshDict "movingPatches (body); staticPatches (outer); function WendlandC2; supportRadius 1.5;"
    run moveDynamicMesh || return 1
    grep -q "dcpRBF: .* control points (WendlandC2.*3D)" log.moveDynamicMesh || fail "no dcpRBF log line"
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

test_badFunction_fatalIOErrorFromTheUtility() {
    write_hollowCube . 2
    run blockMesh || return 1
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { ".*" { type fixedValue; value uniform (0 0 0); } }
EOT
    dynamicMeshDict "movingPatches (body); staticPatches (outer); function cubicSpline; supportRadius 1;"
    if moveDynamicMesh > log.moveDynamicMesh 2>&1
    then
        fail "moveDynamicMesh accepted function cubicSpline"
    fi
    grep -q "FOAM FATAL IO ERROR" log.moveDynamicMesh || fail "no FatalIOError"
    grep -q "Unknown function cubicSpline" log.moveDynamicMesh || fail "error does not name the function"
    grep -q "WendlandC2" log.moveDynamicMesh || fail "error does not list the allowed functions"
}

test_unlistedPatch_warns() {
    write_hollowCube . 2
    run blockMesh || return 1
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { ".*" { type fixedValue; value uniform (0 0 0); } }
EOT
    dynamicMeshDict "movingPatches (body); staticPatches (); supportRadius 1;"
    foamDictionary system/controlDict -entry endTime -set 0.1 > /dev/null
    run moveDynamicMesh || return 1
    grep -q "neither movingPatches nor staticPatches" log.moveDynamicMesh || fail "no warning for patch outer"
}
