# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: the pitchingAirfoil2D, sixDoFAirfoil2D, relativeMotion2D and sloshing2D tutorials,
# shortened through their Allrun options, each run on a copy of the tutorials
# (tutorials/common and the mesh scripts they share) in the test folder.
#
# pitchingAirfoil2D: 0.6 s (60 steps) instead of a quarter period; both cases
# (dcpRBF and the whole mesh turning rigidly) complete, checkMesh passes at
# every written time (0.3 and 0.6 s), and the force agreement check runs and passes over
# t = [0.2, 0.6] at 2 %, as the default run over t = [1, 7.85] (measured on the
# short window: Cl 0.07 %, Cm 0.14 %; the window starts inside the impulsive
# start's transient, where Cl is small (0.1), so a looser tolerance would be
# defensible, but none is needed).
# sixDoFAirfoil2D: 0.05 s (50 steps); both motion solvers complete, checkMesh
# passes for both at every written time, the trajectory summary is printed.
# flappingWing3D: the coarse mesh, 0.3 s (30 steps); both cases (dcpRBF and
# the whole mesh turning rigidly) complete, checkMesh passes at every written
# time, Cl and Cd agree point by point over t = [0.1, 0.3] at 2 % (measured:
# Cl 0.17 %, Cd 1.1 %), dcpRBF's share of the run is reported.

# copyTutorials NAME...: tutorials/common and the named tutorials, cleaned
copyTutorials() {
    local t
    mkdir -p tutorials
    cp -r "$top/tutorials/common" tutorials/
    for t in "$@"
    do
        cp -r "$top/tutorials/$t" tutorials/ || return 1
        (cd "tutorials/$t" && ./Allclean > /dev/null 2>&1)
        rm -rf "tutorials/$t/images"
    done
}

# endsOk LOG: an OpenFOAM solver log that reached End
endsOk() {
    [ -f "$1" ] || fail "no $1" || return 1
    tail -n 3 "$1" | grep -q '^End' || fail "$1 did not end: $(grep -m2 -A3 'FOAM FATAL' "$1")"
}

# checkMeshAllOk DIR: DIR/log.checkMesh.moved says Mesh OK for every written time
checkMeshAllOk() {
    local nTimes nOk
    nTimes=$(writtenTimes "$1" | wc -l)
    nOk=$(countLines '^Mesh OK' "$1/log.checkMesh.moved")
    [ "$nTimes" -gt 0 ] || fail "$1: no time written" || return 1
    [ "$nOk" -eq "$nTimes" ] || fail "$1: checkMesh OK at $nOk of $nTimes times: $(grep -m3 'Failed\|\*\*\*' "$1/log.checkMesh.moved")"
}

test_tutorials_pitchingAirfoil2D_short_agreesWithRigid() {
    local c=tutorials/pitchingAirfoil2D
    copyTutorials pitchingAirfoil2D || return 1
    # write at 0.3 and 0.6 s (the tutorial writes every eighth of a period)
    # (sed, not foamDictionary -set: that would expand the #includeIfPresent of the end time)
    sed -i 's/^writeInterval .*/writeInterval   0.3;/' "$c/system/controlDict"
    "$c/Allrun" -endTime 0.6 -from 0.2 -tolerance 0.02 > log.Allrun 2>&1
    endsOk "$c/log.pimpleFoam" || return 1
    endsOk "$c/rigid/log.pimpleFoam" || return 1
    grep -q "^Time = 0.6$" "$c/log.pimpleFoam" && ! grep -q "^Time = 0.61$" "$c/log.pimpleFoam" \
        || fail "the run did not stop at t = 0.6 (Allrun -endTime)" || return 1
    grep -q "dcpRBF: control points" "$c/log.pimpleFoam" || fail "no dcpRBF log line" || return 1
    grep -q "^Mesh OK" "$c/log.checkMesh.initial" || fail "initial mesh fails checkMesh" || return 1
    checkMeshAllOk "$c" || return 1
    grep "^dcpRBF vs rigid" "$c/log.python3.plots" || fail "no agreement line: $(tail -5 "$c/log.python3.plots")" || return 1
    grep -q "^dcpRBF vs rigid.*: agree" "$c/log.python3.plots" || fail "dcpRBF and rigid rotation disagree" || return 1
    [ -f "$c/images/forcesVsRigid.png" ] || fail "no images/forcesVsRigid.png"
}

test_tutorials_sixDoFAirfoil2D_short_bothSolversMeshOk() {
    local c=tutorials/sixDoFAirfoil2D
    copyTutorials pitchingAirfoil2D sixDoFAirfoil2D || return 1
    "$c/Allrun" -endTime 0.05 > log.Allrun 2>&1
    endsOk "$c/log.pimpleFoam" || return 1
    endsOk "$c/stock/log.pimpleFoam" || return 1
    grep -q "dcpRBF: control points" "$c/log.pimpleFoam" || fail "no dcpRBF log line" || return 1
    grep -q "^6-DoF rigid body motion" "$c/log.pimpleFoam" || fail "no 6-DoF report" || return 1
    checkMeshAllOk "$c" || return 1
    checkMeshAllOk "$c/stock" || return 1
    grep -A8 "^sixDoFAirfoil2D:" "$c/log.python3.plots" || fail "no trajectory summary: $(tail -5 "$c/log.python3.plots")" || return 1
    [ -f "$c/images/trajectory.png" ] || fail "no images/trajectory.png"
}

test_tutorials_flappingWing3D_short_agreesWithRigid() {
    local c=tutorials/flappingWing3D
    copyTutorials flappingWing3D || return 1
    "$c/Allrun" -coarse -endTime 0.3 -tolerance 0.02 > log.Allrun 2>&1
    endsOk "$c/log.pimpleFoam" || return 1
    endsOk "$c/rigid/log.pimpleFoam" || return 1
    grep -q "^Time = 0.3$" "$c/log.pimpleFoam" && ! grep -q "^Time = 0.31$" "$c/log.pimpleFoam" \
        || fail "the run did not stop at t = 0.3 (Allrun -endTime)" || return 1
    grep -q "dcpRBF: rotationInterpolation, 1 body" "$c/log.pimpleFoam" || fail "no rotationInterpolation" || return 1
    grep -q "^Mesh OK" "$c/log.checkMesh.initial" || fail "initial mesh fails checkMesh" || return 1
    checkMeshAllOk "$c" || return 1
    grep "^dcpRBF" "$c/log.python3.plots" || fail "no agreement line: $(tail -5 "$c/log.python3.plots")" || return 1
    grep -q "^dcpRBF share: newPoints()" "$c/log.python3.plots" || fail "no share of the run" || return 1
    grep -q "^dcpRBF vs rigid: agree" "$c/log.python3.plots" || fail "dcpRBF and the rigid rotation disagree" || return 1
    [ -f "$c/images/forces.png" ] || fail "no images/forces.png" || return 1
    [ -f "$c/images/cut.png" ] || fail "no images/cut.png"
}

# relativeMotion2D (dcpRBF on a region, the cellZone rotor, as the zone's
# solver of dynamicMultiMotionSolverFvMesh, in a rotating frame, behind a
# cyclicAMI), shortened to 0.5 s (20 steps: a quarter turn). Its check
# (checkMotion.py) must say ok on every line: the stator does not move at
# all (a check of the set-up: dynamicMultiMotionSolverFvMesh gives dcpRBF
# the rotor zone's points alone), the rotor's side of the interface is the
# solid-body rotation (1e-12),
# the hub moves in the frame, the AMI's weights sum to 1 (1 %), checkMesh
# passes at every written time, no cell inverts. The same run on 3
# processors (the decomposition cutting the rotor and the interface; the
# middle processor has two processor patches, the others one) equals the
# serial one (1e-10) at 0.25 and 0.5 s, and a restart at 0.25 s the
# uninterrupted one at 0.75 s (1e-14; at 0.25 and 0.75 s the hub is at its
# largest displacement).

# relativeMotion2D ENDTIME: the tutorial's case in ./case, meshed, its end
# time ENDTIME, 0/ restored
relativeMotion2D() {
    mkdir -p case
    cp -r "$top/tutorials/relativeMotion2D/." case/ || return 1
    rm -rf case/images
    (
        cd case || exit 1
        ./Allclean > /dev/null 2>&1
        echo "endTime $1;" > system/endTime
        run blockMesh || exit 1
        cp -r 0.orig 0
    ) || return 1
}

test_region_relativeMotion2D_statorStillAMIIntact() {
    mkdir -p tutorials
    cp -r "$top/tutorials/relativeMotion2D" tutorials/ || return 1
    rm -rf tutorials/relativeMotion2D/images
    (cd tutorials/relativeMotion2D && ./Allclean > /dev/null 2>&1)
    tutorials/relativeMotion2D/Allrun -endTime 0.5 > log.Allrun 2>&1 \
        || fail "Allrun failed: $(tail -n 5 log.Allrun)"
    local check=tutorials/relativeMotion2D/log.python3.check
    [ -f "$check" ] || fail "no check: $(tail -n 5 log.Allrun)"
    cat "$check"
    [ "$(countLines ': ok$' "$check")" -eq 6 ] || fail "the check failed: $(grep -v ': ok$' "$check")"
    grep -q "dcpRBF: region cellZone rotor: 480 cells" tutorials/relativeMotion2D/log.moveDynamicMesh \
        || fail "no region in the log"
}

test_region_relativeMotion2D_parallelEqualsSerial() {
    relativeMotion2D 0.5 || return 1
    (cd case && run moveDynamicMesh) || fail "serial run failed"
    mkdir -p par
    cp -r case/constant case/system case/0 par/
    writeFile par/system/decomposeParDict dictionary <<'EOT'
numberOfSubdomains 3;
method simple;
coeffs { n (3 1 1); }
EOT
    (
        cd par || exit 1
        run decomposePar || exit 1
        OMP_NUM_THREADS=1 run mpirun --oversubscribe -np 3 moveDynamicMesh -parallel || exit 1
        run reconstructPar || exit 1
    ) || fail "parallel run failed (see par/log.*)"
    # (at 0.25 the hub is at its largest displacement, at 0.5 back at 0)
    local time
    for time in 0.25 0.5
    do
        pointsAgree "case/$time/polyMesh/points" "par/$time/polyMesh/points" 1e-10 \
            "serial vs parallel at t = $time" || return 1
    done
}

test_region_relativeMotion2D_restartEqualsUninterrupted() {
    relativeMotion2D 0.75 || return 1
    cp -r case restart
    (cd case && run moveDynamicMesh) || fail "uninterrupted run failed"
    (
        cd restart || exit 1
        echo "endTime 0.25;" > system/endTime
        run moveDynamicMesh || exit 1
        echo "endTime 0.75;" > system/endTime
        rm -f log.moveDynamicMesh
        run moveDynamicMesh || exit 1
        grep -q "restarting with" log.moveDynamicMesh || exit 2
    )
    case $? in
    (0) ;;
    (2) fail "the restart did not read the control set's state" ;;
    (*) fail "restarted run failed (see restart/log.*)" ;;
    esac
    # (at 0.75 the hub is at its largest displacement the other way)
    pointsAgree case/0.75/polyMesh/points restart/0.75/polyMesh/points 1e-14 "uninterrupted vs restarted at t = 0.75" || return 1
}

# sloshing2D: OpenFOAM's tutorial, stock and by one word, 0.4 s (20 steps):
# both end, checkMesh passes at every written time, the wave's height at
# the left wall agrees within 1 % of its rise (measured over 4 s: 0.04 %)
test_tutorials_sloshing2D_short_oneWordAgreesWithStock() {
    local c=tutorials/sloshing2D
    copyTutorials sloshing2D || return 1
    "$c/Allrun" -endTime 0.4 > log.Allrun 2>&1 || fail "Allrun failed: $(tail -5 log.Allrun)" || return 1
    endsOk "$c/stock/log.pimpleFoam" || return 1
    endsOk "$c/dcpRBF/log.pimpleFoam" || return 1
    grep -q "^dcpRBF: velocity-driven (pointMotionU, dynamicFvMesh interfaceTrackingFvMesh)" "$c/dcpRBF/log.pimpleFoam" \
        || fail "dcpRBF not the velocity-driven solver: $(grep -m2 '^dcpRBF' "$c/dcpRBF/log.pimpleFoam")" || return 1
    checkMeshAllOk "$c/stock" || return 1
    checkMeshAllOk "$c/dcpRBF" || return 1
    grep "^wave height" "$c/log.python3" || fail "no comparison: $(tail -5 "$c/log.python3")" || return 1
    grep -q "^wave height.*: agree" "$c/log.python3" || fail "the wave heights disagree" || return 1
    { [ -f "$c/images/waveHeight.png" ] && [ -f "$c/images/mesh.png" ]; } || fail "no images"
}
