# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
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

# restartEqualsUninterrupted [NP]: written at t = 0.5 and 1 only (points at
# full precision), so the uninterrupted run carries updated factorizations
# between writes; run to t = 1 here; in restart/, run to 0.5, restart from
# 0.5 to 1; the points at 1 agree to round-off (1e-14 of the domain size).
# NP = 2: both runs on 2 processors (simple decomposition), reconstructed
restartEqualsUninterrupted() {
    local np="${1:-1}"
    foamDictionary system/controlDict -entry writePrecision -set 17 > /dev/null
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
    pointsAgree 1/polyMesh/points restart/1/polyMesh/points 1e-14 \
        "uninterrupted vs restarted at t = 1 ($np processors)"
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
    restartEveryMode 1 modeRun2D
}

test_cube3D_restartEveryMode_parallel() {
    restartEveryMode 2 modeRun3D
}
