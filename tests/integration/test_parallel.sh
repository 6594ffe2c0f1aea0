# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: parallel runs give the serial points.

# parallelEqualsSerial TIME [DECOMPOSITION]: run moveDynamicMesh serial
# (here) and on 2 processors (in par/), reconstruct, compare the points at
# TIME: 1e-10 relative to the domain size, and the reconstructed
# cellDisplacement (cell and boundary values: 1e-10 relative to the
# displacements' range). DECOMPOSITION: the method entries
# of decomposeParDict (default: simple, split in x)
parallelEqualsSerial() {
    local time="$1" decomposition='method simple; coeffs { n (2 1 1); }'
    [ $# -gt 1 ] && decomposition="$2"
    mkdir -p par
    cp -r constant system 0 par/
    writeFile par/system/decomposeParDict dictionary <<EOT
numberOfSubdomains 2;
$decomposition
EOT
    run moveDynamicMesh || return 1
    (
        cd par || exit 1
        run decomposePar || exit 1
        OMP_NUM_THREADS=1 run mpirun -np 2 moveDynamicMesh -parallel || exit 1
        run reconstructPar -time "$time" || exit 1
    ) || fail "parallel run failed (see par/log.*)" || return 1
    pointsAgree "$time/polyMesh/points" "par/$time/polyMesh/points" 1e-10 \
        "serial vs parallel at t = $time" || return 1
    [ -f "$time/cellDisplacement" ] && [ -f "par/$time/cellDisplacement" ] \
        || fail "no cellDisplacement at t = $time, serial or reconstructed" || return 1
    pointsAgree "$time/cellDisplacement" "par/$time/cellDisplacement" 1e-10 \
        "cellDisplacement, serial vs parallel at t = $time"
}

test_airfoil2D_parallelEqualsSerial() {
    write_motionControls .
    airfoilMesh 0.04 1.0 || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    airfoilPointDisplacement 0.698
    dynamicMeshDict "movingPatches (wing); staticPatches (inlet outlet topAndBottom); supportRadius 2.5;"
    parallelEqualsSerial 0.5
}

test_hollowCube3D_parallelEqualsSerial() {
    write_hollowCube . 5
    run blockMesh || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    hollowCubeRotation 0.5236
    dynamicMeshDict "movingPatches (body); staticPatches (outer); supportRadius 1.5;"
    parallelEqualsSerial 0.5
}

# The result does not depend on the number of OpenMP threads (the core's
# loops are per point, Eigen's own threading is off): 1 and 2 threads give the
# same points, every selection mode, to round-off of the written digits, and
# the same cell-quality summary (nCells, minQuality, meanQuality) to the digit
test_threads_sameResultOn1And2Threads() {
    local selection dir diff failed=()
    for selection in "selection all;" "selection greedy; tolerance 1e-3;" "selection dynamic; tolerance 1e-2;"
    do
        dir="${selection%%;*}"; dir="${dir#selection }"
        mkdir -p "$dir"
        if ! (
            cd "$dir" || exit 1
            modeRun3D "$selection" || exit 1
            foamDictionary system/controlDict -entry writePrecision -set 17 > /dev/null
            foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
            mkdir -p two && cp -r constant system 0 two/
            OMP_NUM_THREADS=1 run moveDynamicMesh || exit 1
            (cd two && OMP_NUM_THREADS=2 run moveDynamicMesh) || exit 1
        )
        then
            failed+=("$dir: run failed")
            continue
        fi
        diff=$(awk -f "$here/comparePoints.awk" "$dir/0.5/polyMesh/points" "$dir/two/0.5/polyMesh/points") \
            || { failed+=("$dir: $diff"); continue; }
        echo "$dir: 1 vs 2 threads: $diff"
        awk -v r="$(echo "$diff" | cut -d' ' -f2)" 'BEGIN { exit !(r <= 1e-14) }' || failed+=("$dir differs: $diff")
        # the quality scan: nCells, minQuality, meanQuality identical (17 digits)
        local q1 q2
        q1=$(grep -v '^#' "$dir/postProcessing/dcpRBF/0/dcpRBF.dat" | cut -d' ' -f6-8)
        q2=$(grep -v '^#' "$dir/two/postProcessing/dcpRBF/0/dcpRBF.dat" | cut -d' ' -f6-8)
        [ -n "$q1" ] && [ "$q1" = "$q2" ] || failed+=("$dir: quality differs: [$q1] vs [$q2]")
    done
    [ ${#failed[@]} -eq 0 ] || fail "$(printf '%s\n' "${failed[@]}")"
}

# Default thread count (OMP_NUM_THREADS unset): a serial run uses the cores
# it may run on (all of them with pointsPerThread 0; 1 under taskset -c 0),
# ranks share the node's cores (bound or not: ranks x threads <= cores); a
# mesh smaller than pointsPerThread (default 250000) points uses 1 thread
test_threads_defaultNeverOversubscribes() {
    local cores n
    cores=$(nproc)
    modeRun3D "selection greedy;" || return 1
    foamDictionary system/controlDict -entry endTime -set 0.1 > /dev/null
    threadsIn() { sed -n 's/^dcpRBF: \([0-9]*\) OpenMP thread(s).*/\1/p' "$1" | head -n 1; }
    (unset OMP_NUM_THREADS; run moveDynamicMesh) || return 1
    n=$(threadsIn log.moveDynamicMesh)
    [ "$n" = 1 ] || fail "serial, $(grep -c . constant/polyMesh/points) lines of points (< 250000 points): $n threads, not 1" || return 1
    dynamicMeshDict "$(cubeCoeffs "selection greedy;") pointsPerThread 0;"
    (unset OMP_NUM_THREADS; run moveDynamicMesh) || return 1
    n=$(threadsIn log.moveDynamicMesh.1)
    [ "$n" = "$cores" ] || fail "serial, pointsPerThread 0: $n threads, $cores cores available" || return 1
    (unset OMP_NUM_THREADS; run taskset -c 0 moveDynamicMesh) || return 1
    n=$(threadsIn log.taskset)
    [ "$n" = 1 ] || fail "serial on one core (taskset -c 0): $n threads" || return 1
    writeFile system/decomposeParDict dictionary <<EOT
numberOfSubdomains 2;
method simple; coeffs { n (2 1 1); }
EOT
    run decomposePar || return 1
    (
        unset OMP_NUM_THREADS
        run mpirun --bind-to none -np 2 moveDynamicMesh -parallel
    ) || return 1
    n=$(threadsIn log.mpirun)
    [ -n "$n" ] && [ $((2*n)) -le $((cores > 2 ? cores : 2)) ] \
        || fail "2 unbound ranks on $cores cores: $n threads each" || return 1
    echo "threads: serial 1 (small mesh), $cores (pointsPerThread 0), taskset 1, 2 ranks $n each ($cores cores)"
}
