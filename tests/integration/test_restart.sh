# Integration tests: a run restarted from a written time reproduces the
# uninterrupted run.

# restartEqualsUninterrupted: run to t = 1 here; in restart/, run to 0.5 and
# restart from 0.5 to 1; the points at 1 agree to 1e-12 of the domain size
restartEqualsUninterrupted() {
    mkdir -p restart
    cp -r constant system 0 restart/
    run moveDynamicMesh || return 1
    (
        cd restart || exit 1
        foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
        run moveDynamicMesh || exit 1
        foamDictionary system/controlDict -entry endTime -set 1 > /dev/null
        run moveDynamicMesh || exit 1
        grep -q "^Create time\|Starting time loop" log.moveDynamicMesh.1 || exit 1
    ) || fail "restarted run failed (see restart/log.*)" || return 1
    local diff
    diff=$(awk -f "$here/comparePoints.awk" 1/polyMesh/points restart/1/polyMesh/points) \
        || fail "$diff" || return 1
    echo "uninterrupted vs restarted at t = 1: $diff"
    awk -v r="$(echo "$diff" | cut -d' ' -f2)" 'BEGIN { exit !(r <= 1e-12) }' \
        || fail "restart differs: $diff"
}

test_hollowCube3D_restartEqualsUninterrupted() {
    write_hollowCube . 4
    run blockMesh || return 1
    hollowCubeRotation 0.5236
    dynamicMeshDict "movingPatches (body); staticPatches (outer); supportRadius 1.5;"
    restartEqualsUninterrupted
}
