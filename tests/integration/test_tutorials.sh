# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: the pitchingAirfoil2D and sixDoFAirfoil2D tutorials,
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
