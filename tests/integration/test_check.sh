# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: the step's mesh check covers every cell whose points
# move (a new user's finds, issue 39): a patch in neither list moved by its
# own condition, a radius smaller than the cells. On the new user's case: a
# 3 x 1 2D channel, 10 cells per unit, whose bottom's middle third (bump)
# rises 0.1 (oscillatingDisplacement), the rest of the bottom, inlet and
# outlet static.

# bumpChannel TOP_CONDITION COEFFS: the channel, top with this condition
bumpChannel() {
    write_motionControls .
    writeFile system/blockMeshDict dictionary <<'EOT'
vertices
(
    (0 0 0) (1 0 0) (2 0 0) (3 0 0) (0 1 0) (1 1 0) (2 1 0) (3 1 0)
    (0 0 0.1) (1 0 0.1) (2 0 0.1) (3 0 0.1) (0 1 0.1) (1 1 0.1) (2 1 0.1) (3 1 0.1)
);
blocks
(
    hex (0 1 5 4 8 9 13 12) (10 10 1) simpleGrading (1 1 1)
    hex (1 2 6 5 9 10 14 13) (10 10 1) simpleGrading (1 1 1)
    hex (2 3 7 6 10 11 15 14) (10 10 1) simpleGrading (1 1 1)
);
boundary
(
    bump { type wall; faces ((1 2 10 9)); }
    bottom { type wall; faces ((0 1 9 8) (2 3 11 10)); }
    top { type wall; faces ((4 12 13 5) (5 13 14 6) (6 14 15 7)); }
    inlet { type patch; faces ((0 8 12 4)); }
    outlet { type patch; faces ((3 7 15 11)); }
    frontAndBack { type empty; faces ((0 4 5 1) (1 5 6 2) (2 6 7 3) (8 9 13 12) (9 10 14 13) (10 11 15 14)); }
);
EOT
    run blockMesh
    writeFile 0/pointDisplacement pointVectorField <<EOT
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    bump { type oscillatingDisplacement; amplitude (0 0.1 0); omega 1.5707963267948966; value uniform (0 0 0); }
    "(bottom|inlet|outlet)" { type fixedValue; value uniform (0 0 0); }
    top { $1 }
    frontAndBack { type empty; }
}
EOT
    dynamicMeshDict "movingPatches (bump); staticPatches (bottom inlet outlet); $2"
}

# top, in neither list, moved 0.15 down by its own fixedValue (1.5 cells):
# the cells under it fold; far from the bump, out of the region's reach
test_check_unlistedPatchMovedByItsCondition_invertedReported() {
    bumpChannel "type fixedValue; value uniform (0 -0.15 0);" "supportRadius 0.5;"
    run moveDynamicMesh
    # said at the start, with what to do
    warningText "whose pointDisplacement condition fixes their points' values" 3 \
        "no warning for top, moved by its own condition"
    grep -q "values: top .*List a patch that moves under movingPatches" warning \
        || fail "the warning does not name top or say what to do: $(head -c 400 warning)"
    grep -q "^dcpRBF: control points .*, [0-9]* inverted)" log.moveDynamicMesh \
        || fail "no step line reports inverted cells"
    warningText "inverted or degenerate cells" 3 "no inverted-cells warning"
    grep -q "list the patches moved by their own conditions (top) under movingPatches" warning \
        || fail "the inverted-cells warning does not name top: $(head -c 500 warning)"
    invertedWhereCheckMeshFails
}

# the same with qualityFloorAction stop: the run stops at the first step
test_check_unlistedPatchMovedByItsCondition_stopStops() {
    bumpChannel "type fixedValue; value uniform (0 -0.15 0);" \
        "supportRadius 0.5; qualityFloorAction stop;"
    stoppedBelowFloor "inverted cells"
    [ ! -d 0.1 ] || fail "the folded mesh of t = 0.1 was written"
}

# top moving from the first step while the bump is still (t = 0: the
# moving patches have not moved, nothing is interpolated): checked all the same
test_check_onlyAnUnlistedPatchMoves_invertedReported() {
    bumpChannel "type fixedValue; value uniform (0 -0.15 0);" "supportRadius 0.5;"
    foamDictionary 0/pointDisplacement -entry boundaryField/bump/amplitude -set "(0 0 0)" > /dev/null
    run moveDynamicMesh
    grep -q "^dcpRBF: control points .*, [0-9]* inverted)" log.moveDynamicMesh \
        || fail "no step line reports inverted cells"
    invertedWhereCheckMeshFails
}

# a radius below half a cell reaches no cell centre: refused at the start,
# naming supportRadius
test_check_radiusBelowTheCells_refused() {
    bumpChannel "type fixedValue; value uniform (0 0 0);" "supportRadius 0.01;"
    foamDictionary 0/pointDisplacement -entry boundaryField/bump/amplitude -set "(0 0.3 0)" > /dev/null
    ! moveDynamicMesh > log.moveDynamicMesh 2>&1 || fail "moveDynamicMesh accepted supportRadius 0.01"
    grep -A3 "FOAM FATAL IO ERROR" log.moveDynamicMesh | tr '\n' ' ' > fatal
    grep -q "supportRadius 0.01 reaches no cell centre" fatal \
        || fail "the error does not name supportRadius: $(head -c 400 fatal)"
    ! grep -q "^Time = " log.moveDynamicMesh || fail "refused only after a time step"
}

# a radius of less than a cell (0.08: it reaches the centres of the cells
# touching the bump, not their neighbours), the bump raised 0.3 (3 cells): whatever the
# mesh, the check sees the cells next to the bump (inverted where checkMesh
# finds them)
test_check_radiusOfACell_invertedReported() {
    bumpChannel "type fixedValue; value uniform (0 0 0);" "supportRadius 0.08;"
    foamDictionary 0/pointDisplacement -entry boundaryField/bump/amplitude -set "(0 0.3 0)" > /dev/null
    run moveDynamicMesh
    invertedWhereCheckMeshFails
}
