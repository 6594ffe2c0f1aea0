# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: a run restarted from a written time reproduces the
# uninterrupted run.

# motionRun NP: moveDynamicMesh on NP (1 or 2) processors from the latest time
motionRun() {
    if [ "$1" -eq 1 ]
    then
        run moveDynamicMesh
    else
        [ -d processor0 ] || run decomposePar || return 1
        OMP_NUM_THREADS=1 run mpirun -np "$1" moveDynamicMesh -parallel
    fi
}

# writeSimpleDecomposition: system/decomposeParDict, 2 processors split in x
writeSimpleDecomposition() {
    writeFile system/decomposeParDict dictionary <<'EOT'
numberOfSubdomains 2;
method simple;
coeffs { n (2 1 1); }
EOT
}

# restartEqualsUninterrupted [NP [FORMAT [MAXREL]]]: written at t = 0.5 and 1 only
# (points at full precision), so the uninterrupted run carries updated
# factorizations between writes; run to t = 1 here; in restart/, run to 0.5,
# restart from 0.5 to 1; the points at 1 agree to round-off (1e-14 of the
# domain size). NP = 2: both runs on 2 processors (simple decomposition),
# reconstructed. binary: writeFormat binary at OpenFOAM's default
# writePrecision 6 (the points exact in binary; dcpRBF's state at full
# precision whatever writePrecision). MAXREL: the points' bound instead of
# 1e-14
restartEqualsUninterrupted() {
    local np="${1:-1}" format="${2:-ascii}" maxRel="${3:-1e-14}"
    if [ "$format" = binary ]
    then
        foamDictionary system/controlDict -entry writeFormat -set binary > /dev/null
        foamDictionary system/controlDict -entry writePrecision -set 6 > /dev/null
    else
        foamDictionary system/controlDict -entry writePrecision -set 17 > /dev/null
    fi
    foamDictionary system/controlDict -entry writeInterval -set 5 > /dev/null
    writeSimpleDecomposition
    mkdir -p restart
    cp -r constant system 0 restart/
    motionRun "$np" || return 1
    (
        cd restart || exit 1
        foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
        motionRun "$np" || exit 1
        foamDictionary system/controlDict -entry endTime -set 1 > /dev/null
        motionRun "$np" || exit 1
        [ "$np" -eq 1 ] || run reconstructPar -time 1 || exit 1
    ) || fail "restarted run failed (see restart/log.*)" || return 1
    [ "$np" -eq 1 ] || run reconstructPar -time 1 || return 1
    if [ "$format" = binary ]
    then
        grep -q "format *binary;" restart/0.5/uniform/dcpRBFState \
            || fail "restart/0.5/uniform/dcpRBFState not written as a binary case's" || return 1
        # the state at full precision: its reference quality not rounded
        # to writePrecision's 6 digits
        awk '$1 == "trialQuality" { v = $2 + 0; found = 1 }
            END { exit !(found && v != sprintf("%.6g", v) + 0) }' restart/0.5/uniform/dcpRBFState \
            || fail "restart/0.5/uniform/dcpRBFState: trialQuality missing or at writePrecision" || return 1
        asciiPoints 1/polyMesh/points points.uninterrupted || return 1
        asciiPoints restart/1/polyMesh/points points.restarted || return 1
        set -- points.uninterrupted points.restarted
    else
        set -- 1/polyMesh/points restart/1/polyMesh/points
    fi
    pointsAgree "$1" "$2" "$maxRel" \
        "uninterrupted vs restarted at t = 1 ($np processors, $format)" || return 1
    # the control set's state (set, ages, the trials' wait, back-off and
    # reference quality, a blend) the same as the uninterrupted run's
    local state=1/uniform/dcpRBFState
    [ "$np" -eq 1 ] || state=processor0/$state
    [ -f "$state" ] || fail "no $state written by the uninterrupted run"
    [ -f "restart/$state" ] || fail "no restart/$state written by the restarted run"
    stateAgrees "$state" "restart/$state" \
        || fail "dcpRBFState at t = 1 differs after the restart ($state)"
    # every step after the restart as in the uninterrupted run: the set's
    # size, additions and removals, the guard's, the trials undone (a
    # trials' wait forgotten makes trials the uninterrupted run did not),
    # inverted cells exactly; the qualities to 1e-9
    stepsAgree postProcessing/dcpRBF/0/dcpRBF.dat restart/postProcessing/dcpRBF/0.5/dcpRBF.dat 0.5 \
        || fail "dcpRBF.dat after t = 0.5 differs after the restart"
}

# stepsAgree UNINTERRUPTED RESTARTED T0: the rows of the uninterrupted run's
# dcpRBF.dat after T0 and the restarted run's, alike (columns 2-6, 10, 15 and
# 17 exactly, 7 and 8 to 1e-9); prints the first difference
stepsAgree() {
    [ -f "$1" ] || fail "no $1"
    [ -f "$2" ] || fail "no $2"
    awk -v t0="$3" '
        FNR == 1 { file++ }
        /^#/ { next }
        file == 1 && $1 + 0 > t0 + 1e-9 { a[++na] = $0 }
        file == 2 { b[++nb] = $0 }
        END {
            if (na != nb || na == 0) { print "rows after t0: " na " and " nb; exit 1 }
            for (i = 1; i <= na; ++i)
            {
                split(a[i], x); split(b[i], y)
                for (c = 1; c <= 17; ++c)
                {
                    exact = (c >= 2 && c <= 6) || c == 10 || c == 15 || c == 17
                    if (exact && x[c] != y[c]) { print "row " i " column " c ": " x[c] " vs " y[c]; exit 1 }
                    if ((c == 7 || c == 8) && (x[c] - y[c] > 1e-9 || y[c] - x[c] > 1e-9)) { print "row " i " column " c ": " x[c] " vs " y[c]; exit 1 }
                }
            }
            print na " steps after the restart as uninterrupted"
        }' "$1" "$2"
}

# stateAgrees A B: the two dictionaries have the same words, and numbers
# that agree to 1e-12 (relative; the points agree to round-off in parallel)
stateAgrees() {
    awk 'NR == FNR { a[FNR] = $0; n = FNR; next }
        {
            m = FNR
            na = split(a[FNR], x); nb = split($0, y)
            if (na != nb) exit 1
            for (i = 1; i <= na; ++i)
            {
                u = x[i]; v = y[i]; sub(/;$/, "", u); sub(/;$/, "", v)
                if (u == v) continue
                if (u !~ /^[-+0-9.eE]+$/ || v !~ /^[-+0-9.eE]+$/) exit 1
                d = u - v; if (d < 0) d = -d
                s = (u < 0 ? -u : u); if (s < 1) s = 1
                if (d > 1e-12*s) exit 1
            }
        }
        END { exit (m != n) }' "$1" "$2"
}

# restartEveryMode NP SETUP: restartEqualsUninterrupted for all, greedy and
# dynamic; SETUP SELECTION writes the case
restartEveryMode() {
    local np="$1" setup="$2" selection failed=()
    for selection in "selection all;" "selection greedy; tolerance 1e-2;" \
        "selection dynamic; tolerance 1e-2; nSwap 2;"
    do
        local dir="${selection%%;*}"; dir="${dir#selection }"
        mkdir -p "$dir"
        (cd "$dir" && "$setup" "$selection" && restartEqualsUninterrupted "$np") \
            > "$dir/log.test" 2>&1 || failed+=("$dir: $(tail -n 1 "$dir/log.test")")
        grep "uninterrupted vs restarted" "$dir/log.test"
    done
    [ ${#failed[@]} -eq 0 ] || fail "$(printf '%s\n' "${failed[@]}")"
}

test_hollowCube3D_restartEqualsUninterrupted() {
    write_hollowCube . 4
    run blockMesh || return 1
    hollowCubeRotation 0.5236
    dynamicMeshDict "movingPatches (body); staticPatches (outer); supportRadius 1.5;"
    restartEqualsUninterrupted
}

test_airfoil2D_restartEveryMode_serial() {
    restartEveryMode 1 modeRun2D || return 1
    # here the restart falls in a wait after undone trials: the wait, its
    # back-off and reference quality cross it (the states at t = 1 agree)
    awk '$1 == "trialWait" { w = $2 + 0 } END { exit !(w > 0) }' \
        dynamic/0.5/uniform/dcpRBFState \
        || fail "dynamic: no trials' wait pending at t = 0.5: the restart does not cross one"
}

test_cube3D_restartEveryMode_parallel() {
    restartEveryMode 2 modeRun3D
}

# writeFormat binary: dcpRBF's state is text in a file whose header says
# binary, read back as text (a list read as binary failed: "Not implemented",
# ITstream::readRaw), and at full precision whatever writePrecision
test_airfoil2D_restartFromBinaryFiles() {
    modeRun2D "selection dynamic; tolerance 1e-2; nSwap 2;" || return 1
    # (OpenFOAM writes the condition's own omega at writePrecision: one
    # that 6 digits hold, so that only dcpRBF's state can differ)
    foamDictionary 0/pointDisplacement -entry boundaryField/wing/omega -set 1.5 > /dev/null
    restartEqualsUninterrupted 1 binary
}

# restartWith COEFFS: the run to t = 0.5, restarted to 1 with dcpRBFCoeffs
# COEFFS; its log is log.moveDynamicMesh.1
restartWith() {
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    run moveDynamicMesh
    [ -f 0.5/uniform/dcpRBFState ] || fail "no restart state at t = 0.5"
    foamDictionary system/controlDict -entry endTime -set 1 > /dev/null
    dynamicMeshDict "$1"
    run moveDynamicMesh
}

# A restart whose settings differ from the state's selects anew, saying so
# (a new user's run restarted with selection all kept the old 65 points)
test_restart_otherSelection_selectsAnewSaysSo() {
    modeRun2D "selection greedy; tolerance 1e-2;"
    restartWith "$(airfoilCoeffs "selection all;")"
    warningText "was selected with other settings" 2 "no warning of the changed settings" log.moveDynamicMesh.1
    grep -q "selection greedy -> all" warning || fail "the warning does not say what changed: $(head -c 400 warning)"
    # every boundary point a control point after the restart
    local n
    n=$(sed -n 's/^dcpRBF: \([0-9]*\) boundary points.*/\1/p' log.moveDynamicMesh.1)
    grep -q "^dcpRBF: control points $n " log.moveDynamicMesh.1 \
        || fail "not all $n boundary points control points after the restart: $(grep -m1 '^dcpRBF: control points' log.moveDynamicMesh.1)"
    ! grep -q "restarting with" log.moveDynamicMesh.1 || fail "the old control set was read"
}

# A restart from a time without its dcpRBFState (a time copied without its
# uniform folder): selected anew, saying so (a new user's restart differed
# from the uninterrupted run by 4e-4 of the domain without a word)
test_restart_withoutState_saysSo() {
    modeRun2D "selection greedy; tolerance 1e-2;"
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    run moveDynamicMesh || return 1
    rm 0.5/uniform/dcpRBFState || fail "no restart state at t = 0.5" || return 1
    foamDictionary system/controlDict -entry endTime -set 1 > /dev/null
    run moveDynamicMesh || return 1
    warningText "No control-point state" 2 "no warning of the missing state" log.moveDynamicMesh.1
    grep -q "selected anew" warning || fail "the warning does not say what happens: $(head -c 400 warning)"
    ! grep -q "No control-point state" log.moveDynamicMesh \
        || fail "a warning at the start of a run from time 0"
    # selection all: the set is every candidate, nothing lost, no warning
    rm 1/uniform/dcpRBFState || fail "no restart state at t = 1" || return 1
    dynamicMeshDict "$(airfoilCoeffs "selection all;")"
    foamDictionary system/controlDict -entry endTime -set 1.2 > /dev/null
    run moveDynamicMesh || return 1
    ! grep -q "No control-point state" log.moveDynamicMesh.2 \
        || fail "a warning with selection all, where nothing is lost"
}

test_restart_otherMaxPoints_selectsAnewSaysSo() {
    modeRun2D "selection greedy; tolerance 1e-6;"
    restartWith "$(airfoilCoeffs "selection greedy; tolerance 1e-6; maxPoints 12;")"
    warningText "was selected with other settings" 2 "no warning of the changed settings" log.moveDynamicMesh.1
    grep -q "maxPoints 2000 -> 12" warning || fail "the warning does not say what changed: $(head -c 400 warning)"
    awk '!/^#/ && $1 > 0.5 && $2 > 12 { bad = 1 } END { exit bad }' postProcessing/dcpRBF/0.5/dcpRBF.dat \
        || fail "more than maxPoints 12 control points after the restart"
}

# Another region (a cellZone now): selected anew, saying so
test_restart_otherRegion_selectsAnewSaysSo() {
    modeRun2D "selection greedy; tolerance 1e-2;" || return 1
    writeFile system/topoSetDict dictionary <<'EOT'
actions
(
    { name near; type cellSet; action new; source boxToCell; sourceInfo { box (-2.5 -2.5 -10) (3.5 2.5 10); } }
    { name near; type cellZoneSet; action new; source setToCellZone; sourceInfo { set near; } }
);
EOT
    run topoSet || return 1
    restartWith "$(airfoilCoeffs "selection greedy; tolerance 1e-2;") cellZone near;"
    warningText "was selected with other settings" 2 "no warning of the changed settings" log.moveDynamicMesh.1
    grep -q "region (none) -> cellZone near" warning || fail "the warning does not say what changed: $(head -c 400 warning)"
    grep -q "dcpRBF: region cellZone near" log.moveDynamicMesh.1 || fail "no region in the restarted run"
}

# Other patches (a static patch left out): no index error, selected anew
test_restart_otherPatches_selectsAnewSaysSo() {
    modeRun2D "selection greedy; tolerance 1e-2;"
    restartWith "movingPatches (wing); staticPatches (inlet outlet); supportRadius 4; qualityFloor 0.1; controlPoints { selection greedy; tolerance 1e-2; }"
    warningText "was selected with other settings" 2 "no warning of the changed settings" log.moveDynamicMesh.1
    grep -q "staticPatches (inlet outlet topAndBottom) -> (inlet outlet)" warning \
        || fail "the warning does not say what changed: $(head -c 400 warning)"
    tail -n 3 log.moveDynamicMesh.1 | grep -q '^End' || fail "the restarted run did not end"
}

# A restart inside a held trials' wait (a small pitch: the minimum quality
# falls by less than trialQualityDrop a step, the wait is not ended early):
# the restarted run waits as the uninterrupted one (no trial at t = 0.6),
# step for step (restartEqualsUninterrupted compares dcpRBF.dat's rows)
test_restart_insideAHeldTrialsWait() {
    write_motionControls .
    airfoilMesh 0.03 1.0
    airfoilPointDisplacement 0.35
    dynamicMeshDict "$(airfoilCoeffs "selection dynamic; tolerance 1e-2; nSwap 2;")"
    restartEqualsUninterrupted 1
    awk '$1 == "trialWait" { w = $2 + 0 } END { exit !(w > 1) }' 0.5/uniform/dcpRBFState \
        || fail "no trials' wait pending at t = 0.5: the restart does not fall in one"
    awk '!/^#/ && $1 == 0.6 { found = 1; if ($3 + $15 > 0) exit 1 } END { exit !found }' \
        postProcessing/dcpRBF/0/dcpRBF.dat \
        || fail "the uninterrupted run tries swaps at t = 0.6: the wait is not held there"
}
