# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Source me: write_hollowCube DIR N -- a 3D case: a cube body (patch "body",
# half side 0.5) in a cube box (patch "outer", half side 2), six hex blocks
# of N^3 cells, with controlDict/fvSchemes/fvSolution for moveDynamicMesh.
write_hollowCube() {
    local dir="$1" n="$2"
    mkdir -p "$dir/system" "$dir/constant" "$dir/0"
    cat > "$dir/system/blockMeshDict" <<EOT
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices
(
    (-0.5 -0.5 -0.5) (0.5 -0.5 -0.5) (0.5 0.5 -0.5) (-0.5 0.5 -0.5)
    (-0.5 -0.5 0.5) (0.5 -0.5 0.5) (0.5 0.5 0.5) (-0.5 0.5 0.5)
    (-2 -2 -2) (2 -2 -2) (2 2 -2) (-2 2 -2)
    (-2 -2 2) (2 -2 2) (2 2 2) (-2 2 2)
);
blocks
(
    hex (8 0 3 11 12 4 7 15) ($n $n $n) simpleGrading (1 1 1)
    hex (1 9 10 2 5 13 14 6) ($n $n $n) simpleGrading (1 1 1)
    hex (8 9 1 0 12 13 5 4) ($n $n $n) simpleGrading (1 1 1)
    hex (3 2 10 11 7 6 14 15) ($n $n $n) simpleGrading (1 1 1)
    hex (8 9 10 11 0 1 2 3) ($n $n $n) simpleGrading (1 1 1)
    hex (4 5 6 7 12 13 14 15) ($n $n $n) simpleGrading (1 1 1)
);
boundary
(
    body
    {
        type wall;
        faces ((0 1 2 3) (4 7 6 5) (0 4 5 1) (3 2 6 7) (0 3 7 4) (1 5 6 2));
    }
    outer
    {
        type patch;
        faces ((8 11 10 9) (12 13 14 15) (8 9 13 12) (11 15 14 10) (8 12 15 11) (9 10 14 13));
    }
);
EOT
    write_motionControls "$dir"
}

# write_motionControls DIR -- controlDict (10 steps of 0.1, written every
# step, precision 16) and empty schemes for moveDynamicMesh
write_motionControls() {
    local dir="$1"
    mkdir -p "$dir/system"
    cat > "$dir/system/controlDict" <<'EOT'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application moveDynamicMesh; startFrom latestTime; startTime 0; stopAt endTime;
endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 1;
writeFormat ascii; writePrecision 16; timeFormat general; timePrecision 6;
runTimeModifiable false;
EOT
    cat > "$dir/system/fvSchemes" <<'EOT'
FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes {} gradSchemes {} divSchemes {} laplacianSchemes {}
interpolationSchemes {} snGradSchemes {}
EOT
    cat > "$dir/system/fvSolution" <<'EOT'
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
EOT
}
