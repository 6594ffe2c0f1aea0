# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: OpenFOAM's mesh/moveDynamicMesh/SnakeRiverCanyon tutorial
# (the ground patch minZ uses surfaceDisplacement: it is projected onto a
# terrain STL, at most velocity*deltaT = 10 m per step; maxZ is fixed; the
# four sides are fixedNormalSlip), shrunk to 6x15x15 cells and 5 steps, run
# with the stock motion solver (displacementSBRStress) and with dcpRBF.

# snakeRiverCanyonCase: the shrunk tutorial in the current folder, meshed
snakeRiverCanyonCase() {
    local tut="$FOAM_TUTORIALS/mesh/moveDynamicMesh/SnakeRiverCanyon"
    [ -d "$tut" ] || fail "no OpenFOAM tutorial at $tut (FOAM_TUTORIALS: re-run ./Allwmake)" || return 1
    cp -r "$tut/0" "$tut/constant" "$tut/system" .
    sed -i 's/(20 60 60)/(6 15 15)/' system/blockMeshDict
    grep -q '(6 15 15)' system/blockMeshDict || fail "could not coarsen the tutorial's blockMeshDict" || return 1
    foamDictionary system/controlDict -entry endTime -set 5 > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 1 > /dev/null
    foamDictionary system/controlDict -entry writeFormat -set ascii > /dev/null
    foamDictionary system/controlDict -entry writePrecision -set 17 > /dev/null
    run blockMesh
}

# snakeRiverCanyonDcpRBF: the case's motion solver replaced by dcpRBF. The
# sides (fixedNormalSlip) are in neither list: their points follow the
# interpolation and their slip condition keeps them in their planes.
snakeRiverCanyonDcpRBF() {
    dynamicMeshDict "movingPatches (minZ); staticPatches (maxZ); supportRadius 2000;
    polynomial true; controlPoints { selection greedy; }"
}

test_snakeRiverCanyon_dcpRBF_meshValidEveryStep() {
    snakeRiverCanyonCase || return 1
    snakeRiverCanyonDcpRBF
    run moveDynamicMesh || return 1
    reportsSetUp WendlandC2 3D
    meshOkAtEveryTime
}

# The ground's motion comes from its boundary condition alone: it must not
# depend on the motion solver. surfaceDisplacement moves the ground by at most
# 10 m per evaluation, so a solver that evaluates it twice per step moves the
# ground twice as far.
test_snakeRiverCanyon_groundAsStockSolver() {
    local t diff bad=""
    snakeRiverCanyonCase || return 1
    mkdir stock
    cp -r 0 constant system stock/
    (cd stock && run moveDynamicMesh) || fail "stock solver (displacementSBRStress) failed: see stock/log.*" || return 1
    snakeRiverCanyonDcpRBF
    run moveDynamicMesh || return 1
    awk -v patch=minZ -f "$here/cases/patchPoints.awk" \
        constant/polyMesh/boundary constant/polyMesh/faces > minZ.labels || fail "no minZ points" || return 1
    echo "minZ points, stock solver vs dcpRBF: time, max difference [m], relative to the domain, max ground displacement stock, dcpRBF [m], points"
    for t in 1 2 3 4 5
    do
        [ -f "$t/polyMesh/points" ] && [ -f "stock/$t/polyMesh/points" ] || fail "time $t not written" || return 1
        diff=$(awk -f "$here/cases/comparePatchPoints.awk" minZ.labels constant/polyMesh/points \
            "stock/$t/polyMesh/points" "$t/polyMesh/points") || fail "$diff" || return 1
        echo "  t = $t: $diff"
        awk -v r="$(echo "$diff" | cut -d' ' -f2)" 'BEGIN { exit !(r <= 1e-9) }' || bad="$bad $t"
    done
    [ -z "$bad" ] || fail "the ground (minZ, surfaceDisplacement) moves differently under dcpRBF than under the stock solver at t =$bad (relative difference > 1e-9; displacements above: stock, dcpRBF; twice as far means the condition is evaluated twice per step)"
}
