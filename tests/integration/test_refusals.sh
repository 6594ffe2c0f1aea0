# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: meshes dcpRBF cannot move correctly are refused at the
# start, with a message naming the patch (not a crash later, not a silent run).

# refusedWith WORDS...: moveDynamicMesh fails and its log has every WORD
refusedWith() {
    if moveDynamicMesh > log.moveDynamicMesh 2>&1
    then
        fail "moveDynamicMesh accepted the case"
    fi
    grep -q "FOAM FATAL" log.moveDynamicMesh || fail "no FatalError: $(tail -n 5 log.moveDynamicMesh)"
    local w
    for w in "$@"
    do
        grep -q -- "$w" log.moveDynamicMesh || fail "the error does not say '$w': $(grep -A4 'FOAM FATAL' log.moveDynamicMesh)"
    done
}

# channelBlock LEFT_RIGHT_TYPE FRONT_BACK_TYPE VERTICES: a 4 x 4 x NZ block with
# patches bottom (wall) top, left/right and front/back of the given types
channelBlock() {
    local nbrL="" nbrR=""
    [ "$1" = cyclic ] && nbrL="neighbourPatch right;" && nbrR="neighbourPatch left;"
    write_motionControls .
    writeFile system/blockMeshDict dictionary <<EOT
vertices ($3);
blocks (hex (0 1 2 3 4 5 6 7) (4 4 ${4:-4}) simpleGrading (1 1 1));
boundary
(
    bottom { type wall; faces ((0 1 5 4)); }
    top { type patch; faces ((3 7 6 2)); }
    left { type $1; $nbrL faces ((0 4 7 3)); }
    right { type $1; $nbrR faces ((1 2 6 5)); }
    front { type $2; faces ((0 3 2 1)); }
    back { type $2; faces ((4 5 6 7)); }
);
EOT
    run blockMesh || return 1
}

# bottomRaised EXTRA: pointDisplacement lifting the bottom wall; EXTRA: more patches
bottomRaised() {
    writeFile 0/pointDisplacement pointVectorField <<EOT
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    bottom { type uniformFixedValue; uniformValue (0 0.01 0); value uniform (0 0 0); }
    top { type fixedValue; value uniform (0 0 0); }
    $1
}
EOT
}

test_cyclic_refusedNamingThePatch() {
    channelBlock cyclic wall "(0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1)" || return 1
    bottomRaised "\"(left|right)\" { type cyclic; }
    \"(front|back)\" { type fixedValue; value uniform (0 0 0); }"
    # unlisted (the usual case): refused at the start, not at step 2
    dynamicMeshDict "movingPatches (bottom); staticPatches (top front back); supportRadius 1;"
    refusedWith "left" "cyclic"
    ! grep -q "^Time = " log.moveDynamicMesh || fail "refused only after a time step"
}

test_calculatedMovingPatch_refused() {
    channelBlock patch wall "(0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1)" || return 1
    bottomRaised "\"(left|right|front|back)\" { type fixedValue; value uniform (0 0 0); }"
    foamDictionary 0/pointDisplacement -entry boundaryField/bottom -set "{ type calculated; value uniform (0 0 0); }" > /dev/null
    dynamicMeshDict "movingPatches (bottom); staticPatches (top left right front back); supportRadius 1;"
    refusedWith "movingPatches" "bottom" "calculated"
}

# amiChannel: a channel of two blocks joined by a cyclicAMI pair (coupled()
# is false for AMI: its geometry is not coupled, its fields are), the bottom
# wall lifted; the left block is the cellZone left
amiChannel() {
    write_motionControls .
    writeFile system/blockMeshDict dictionary <<'EOT'
vertices
(
    (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 0.1) (1 0 0.1) (1 1 0.1) (0 1 0.1)
    (1 0 0) (2 0 0) (2 1 0) (1 1 0) (1 0 0.1) (2 0 0.1) (2 1 0.1) (1 1 0.1)
);
blocks
(
    hex (0 1 2 3 4 5 6 7) left (5 5 1) simpleGrading (1 1 1)
    hex (8 9 10 11 12 13 14 15) (4 4 1) simpleGrading (1 1 1)
);
boundary
(
    bottom { type wall; faces ((0 1 5 4) (8 9 13 12)); }
    top { type wall; faces ((3 7 6 2) (11 15 14 10)); }
    inlet { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((9 10 14 13)); }
    amiLeft { type cyclicAMI; neighbourPatch amiRight; faces ((1 2 6 5)); }
    amiRight { type cyclicAMI; neighbourPatch amiLeft; faces ((8 12 15 11)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7) (8 11 10 9) (12 13 14 15)); }
);
EOT
    run blockMesh
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    bottom { type uniformFixedValue; uniformValue (0 0.01 0); value uniform (0 0 0); }
    "(top|inlet|outlet)" { type fixedValue; value uniform (0 0 0); }
    "ami.*" { type cyclicAMI; }
    frontAndBack { type empty; }
}
EOT
}

# The AMI in neither list: refused at the start, naming the patch
test_cyclicAMI_refusedNamingThePatch() {
    amiChannel || return 1
    dynamicMeshDict "movingPatches (bottom); staticPatches (top inlet outlet); supportRadius 0.5;"
    refusedWith "amiLeft" "cyclicAMI" "coupled"
    ! grep -q "^Time = " log.moveDynamicMesh || fail "refused only after a time step"
}

# Two blocks whose touching faces are two patches at the same place to
# round-off (a baffle's two sides), both listed: refused at the start,
# naming both patches (not "duplicate control points 670 and 671")
test_coincidentPatches_refusedNamingThem() {
    write_motionControls .
    writeFile system/blockMeshDict dictionary <<'EOT'
vertices
(
    (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 0.1) (1 0 0.1) (1 1 0.1) (0 1 0.1)
    (1.0000000000001 0 0) (2 0 0) (2 1 0) (1.0000000000001 1 0)
    (1.0000000000001 0 0.1) (2 0 0.1) (2 1 0.1) (1.0000000000001 1 0.1)
);
blocks
(
    hex (0 1 2 3 4 5 6 7) (5 5 1) simpleGrading (1 1 1)
    hex (8 9 10 11 12 13 14 15) (4 4 1) simpleGrading (1 1 1)
);
boundary
(
    bottom { type wall; faces ((0 1 5 4) (8 9 13 12)); }
    top { type wall; faces ((3 7 6 2) (11 15 14 10)); }
    inlet { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((9 10 14 13)); }
    baffleLeft { type wall; faces ((1 2 6 5)); }
    baffleRight { type wall; faces ((8 12 15 11)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7) (8 11 10 9) (12 13 14 15)); }
);
EOT
    run blockMesh
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    bottom { type uniformFixedValue; uniformValue (0 0.01 0); value uniform (0 0 0); }
    "(top|inlet|outlet|baffle.*)" { type fixedValue; value uniform (0 0 0); }
    frontAndBack { type empty; }
}
EOT
    dynamicMeshDict "movingPatches (bottom); staticPatches (top inlet outlet baffleLeft baffleRight); supportRadius 0.5;"
    refusedWith "baffleLeft" "baffleRight" "coincide"
}

# A region (cellZone lower, the lower of two stacked blocks) whose moving
# patch (the lower half of the left wall) ends on the region's border: its
# end points are shared with the upper block's cells, which dcpRBF neither
# moves nor checks: refused, naming the patch (not moved only in part)
test_movingPatchOnTheRegionsBorder_refused() {
    write_motionControls .
    writeFile system/blockMeshDict dictionary <<'EOT'
vertices
(
    (0 0 0) (1 0 0) (1 0.5 0) (0 0.5 0) (0 0 0.1) (1 0 0.1) (1 0.5 0.1) (0 0.5 0.1)
    (0 1 0) (1 1 0) (0 1 0.1) (1 1 0.1)
);
blocks
(
    hex (0 1 2 3 4 5 6 7) lower (6 3 1) simpleGrading (1 1 1)
    hex (3 2 9 8 7 6 11 10) (6 3 1) simpleGrading (1 1 1)
);
boundary
(
    bottom { type wall; faces ((0 1 5 4)); }
    top { type wall; faces ((8 10 11 9)); }
    leftLower { type wall; faces ((0 4 7 3)); }
    leftUpper { type wall; faces ((3 7 10 8)); }
    right { type wall; faces ((1 2 6 5) (2 9 11 6)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7) (3 8 9 2) (7 6 11 10)); }
);
EOT
    run blockMesh
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    leftLower { type uniformFixedValue; uniformValue (0.01 0 0); value uniform (0 0 0); }
    "(bottom|top|leftUpper|right)" { type fixedValue; value uniform (0 0 0); }
    frontAndBack { type empty; }
}
EOT
    dynamicMeshDict "movingPatches (leftLower); staticPatches (bottom right); supportRadius 0.5; cellZone lower;"
    refusedWith "movingPatches" "leftLower" "crosses the border"
}

# A region's side of a sliding interface is static by itself: listing the
# cyclicAMI patch is refused, naming the keyword and saying so (without a
# region, the whole mesh holds both sides: refused as in the test above)
test_cyclicAMIListed_refused() {
    amiChannel || return 1
    dynamicMeshDict "movingPatches (bottom); staticPatches (top inlet amiLeft); supportRadius 0.5; cellZone left;"
    refusedWith "staticPatches" "amiLeft" "static without being listed"
}
