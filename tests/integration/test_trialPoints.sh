# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: error-guided trial swaps whose meshes are made at the
# window's points alone (trialPoints window, the default) decide as those
# made at every point (trialPoints all): the same swaps, the same time
# series but for the times, the same points bit for bit at every written
# time. In 2D (the front and back points of a pair), in 3D next to sliding
# walls (a symmetryPlane meeting slip walls: their change blended into the
# volume), on 2 processors (the processor points synchronised), with the
# matrix stored or not, and in a rescue (a mesh folding: trials past an
# undone one, the window grown around each leaving point).

# windowEqualsAll NP [rescue]: this case (selection dynamic) run as it is
# and, in all/, with trialPoints all, on NP processors (simple
# decomposition, 2 1 1); rescue: a step of two or more trials all undone
# (a rescue's) is asked for instead of one with two kept
windowEqualsAll() {
    local np="$1" rescue="${2:-}"
    foamDictionary system/controlDict -entry writePrecision -set 17 > /dev/null
    # each trial's window minimum and the one it must beat, every digit (the
    # library loaded with the controlDict: its debug switch is set then)
    foamDictionary system/controlDict -entry libs -set '("libdcpRBF.so")' > /dev/null
    foamDictionary system/controlDict -entry DebugSwitches -set "{ dcpRBF 1; }" > /dev/null
    writeSimpleDecomposition
    mkdir -p all
    cp -r constant system 0 all/
    sed -i 's/selection dynamic;/selection dynamic; trialPoints all;/' all/constant/dynamicMeshDict
    grep -q "trialPoints all;" all/constant/dynamicMeshDict || fail "trialPoints all not set" || return 1
    motionRun "$np" || return 1
    (cd all && motionRun "$np") || fail "the run with trialPoints all failed (see all/log.*)" || return 1

    # trials were made, at the window's points in the first run only; some
    # kept, in a step two or more (the next trial's cells measured on the
    # kept trial's mesh), some undone
    local log=log.moveDynamicMesh
    [ "$np" -eq 1 ] || log=log.mpirun
    grep -q "trials at [0-9]* points" "$log" \
        || fail "no trial made at the window's points" || return 1
    ! grep -q "trials at" "all/$log" \
        || fail "trialPoints all: trials made at the window's points" || return 1
    awk -v rescue="$rescue" \
        '/^Time = / { n = 0; u = 0 } / trial swap on .*, kept$/ { if (++n > most) most = n; kept++ }
         / trial swap on .*, undone$/ { undone++; if (++u > mostUndone) mostUndone = u }
         END { print kept + 0 " trials kept (at most " most + 0 " in a step), " undone " undone";
               exit rescue ? !(mostUndone >= 2) : !(most >= 2 && undone >= 1) }' "$log" \
        || fail "no step with two kept trials, or none undone (rescue: no step of two undone)" \
        || return 1

    # every trial's window minimum and the minimum it had to beat
    [ "$(grep -c "dcpRBF: trial swap on" "$log")" -ge 4 ] \
        || fail "fewer than 4 trials in the debug output" || return 1
    cmp -s <(grep "dcpRBF: trial swap on" "$log") <(grep "dcpRBF: trial swap on" "all/$log") \
        || fail "the trials differ: $(diff <(grep "dcpRBF: trial swap on" "$log") \
                 <(grep "dcpRBF: trial swap on" "all/$log") | head -n 4)" || return 1

    # the time series without the times (swap, select, interpolate, guard,
    # points, measure: columns 11-14, 16 and 18)
    # shellcheck disable=SC2016 # an awk program
    local series='!/^#/ { $11 = $12 = $13 = $14 = $16 = $18 = ""; print }'
    cmp -s <(awk "$series" postProcessing/dcpRBF/0/dcpRBF.dat) \
           <(awk "$series" all/postProcessing/dcpRBF/0/dcpRBF.dat) \
        || fail "the time series differ: $(diff <(awk "$series" postProcessing/dcpRBF/0/dcpRBF.dat) \
                 <(awk "$series" all/postProcessing/dcpRBF/0/dcpRBF.dat) | head -n 4)" || return 1

    # the points at every written time
    local dirs=(.) d t f n=0
    [ "$np" -eq 1 ] || dirs=(processor*)
    for d in "${dirs[@]}"
    do
        for t in $(writtenTimes "$d")
        do
            f="$d/$t/polyMesh/points"
            [ -f "$f" ] || continue
            cmp -s "$f" "all/$f" || fail "$f differs"
            n=$((n + 1))
        done
    done
    echo "$n points files the same"
    [ "$n" -ge 2 ] || fail "fewer than 2 written times"
}

test_trialPoints_windowEqualsAll_airfoil2D() {
    modeRun2D "selection dynamic; tolerance 5e-2; nSwap 2; swapBlendSteps 1;" || return 1
    foamDictionary system/controlDict -entry writeInterval -set 2 > /dev/null
    windowEqualsAll 1
}

test_trialPoints_windowEqualsAll_slipDuct3D() {
    slipDuctCase || return 1
    sed -i 's/selection dynamic;/selection dynamic; tolerance 3e-2;/' constant/dynamicMeshDict
    foamDictionary system/controlDict -entry writeInterval -set 5 > /dev/null
    windowEqualsAll 1
}

test_trialPoints_windowEqualsAll_slipDuct3D_parallel() {
    slipDuctCase || return 1
    sed -i 's/selection dynamic;/selection dynamic; tolerance 3e-2;/' constant/dynamicMeshDict
    foamDictionary system/controlDict -entry writeInterval -set 5 > /dev/null
    windowEqualsAll 2
}

# the matrix not stored (evaluationMemoryMB 0): the trials' points evaluated
# on the fly alone, as the whole evaluation would (its method)
test_trialPoints_windowEqualsAll_slipDuct3D_onTheFly() {
    slipDuctCase || return 1
    sed -i 's/selection dynamic;/selection dynamic; tolerance 3e-2;/; s/supportRadius 2.5;/supportRadius 2.5; evaluationMemoryMB 0;/' \
        constant/dynamicMeshDict
    grep -q "evaluationMemoryMB 0;" constant/dynamicMeshDict || fail "evaluationMemoryMB 0 not set" || return 1
    foamDictionary system/controlDict -entry writeInterval -set 5 > /dev/null
    windowEqualsAll 1
}

# the rescue (trials past an undone one, applied at once) on the bent wing
# whose last step folds
test_trialPoints_windowEqualsAll_rescue() {
    bendingWingTrialsCase || return 1
    windowEqualsAll 1 rescue || return 1
    grep -q ', rescue), quality min' log.moveDynamicMesh || fail "no rescue step"
}
