# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: OpenFOAM's incompressible/pimpleFoam/laminar/movingCone,
# as it is (a 5 deg wedge about the x axis) and as a planar 2D case (its
# blockMeshDict with the same vertices in x and y, front and back empty
# planes, the axis a symmetryPlane). The cone (movingWall) moves 1 m/s in x
# (the tutorial's velocity as a displacement); the far field (farField,
# farFieldMoving) is slip and left out of both lists, fixedWall and left are
# static.

# movingConeSettings AXIS FRONTBACK [SELECTION]: what the planar and wedge
# cases share: the controlDict (100 steps of moveDynamicMesh), the cone's
# motion and the walls' conditions (the axis and the front and back patches
# of the types given), dcpRBF's settings; then blockMesh
movingConeSettings() {
    writeFile system/controlDict dictionary <<'EOT'
application moveDynamicMesh; startFrom startTime; startTime 0; stopAt endTime;
endTime 0.0005; deltaT 5e-06; writeControl timeStep; writeInterval 25;
writeFormat ascii; writePrecision 17; timeFormat general; timePrecision 8;
EOT
    writeFile 0/pointDisplacement pointVectorField <<EOT
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    movingWall { type uniformFixedValue; uniformValue table ((0 (0 0 0)) (1 (1 0 0))); value uniform (0 0 0); }
    "(farField|farFieldMoving)" { type slip; }
    "(fixedWall|left)" { type fixedValue; value uniform (0 0 0); }
    axis { type $1; }
    "(front|back)" { type $2; }
}
EOT
    dynamicMeshDict "movingPatches (movingWall); staticPatches (fixedWall left);
    supportRadius 0.01; controlPoints { selection ${3:-dynamic}; }"
    run blockMesh
}

movingConePlanarCase() {
    local tut="$FOAM_TUTORIALS/incompressible/pimpleFoam/laminar/movingCone"
    [ -d "$tut" ] || fail "no OpenFOAM tutorial at $tut (FOAM_TUTORIALS: re-run ./Allwmake)" || return 1
    mkdir -p system constant
    cp "$tut/system/fvSchemes" "$tut/system/fvSolution" system/
    # the tutorial's vertices with z = -+0.1 for the back and front planes
    # (the axis points duplicated: 20-23), its blocks and patches
    writeFile system/blockMeshDict dictionary <<'EOT'
scale 0.001;
vertices
(
    (-7.5 0 -0.1) (-7 0 -0.1) (-3.5 0 -0.1) (0 0 -0.1)
    (-7.5 0.75 -0.1) (-7 0.75 -0.1) (-3.5 2 -0.1) (0 2 -0.1)
    (-7.5 2.5 -0.1) (-7 2.5 -0.1) (-3.5 2.5 -0.1) (0 2.5 -0.1)
    (-7.5 0.75 0.1) (-7 0.75 0.1) (-3.5 2 0.1) (0 2 0.1)
    (-7.5 2.5 0.1) (-7 2.5 0.1) (-3.5 2.5 0.1) (0 2.5 0.1)
    (-7.5 0 0.1) (-7 0 0.1) (-3.5 0 0.1) (0 0 0.1)
);
blocks
(
    hex (0 1 5 4 20 21 13 12) (15 15 1) simpleGrading (1 1 1)
    hex (2 3 7 6 22 23 15 14) (20 20 1) simpleGrading (2 0.25 1)
    hex (4 5 9 8 12 13 17 16) (15 15 1) simpleGrading (1 1 1)
    hex (5 6 10 9 13 14 18 17) (50 15 1) simpleGrading (1 1 1)
    hex (6 7 11 10 14 15 19 18) (20 15 1) simpleGrading (2 1 1)
);
boundary
(
    movingWall { type wall; faces ((1 5 13 21) (5 6 14 13) (2 22 14 6)); }
    farFieldMoving { type patch; faces ((9 17 18 10)); }
    fixedWall { type wall; faces ((3 7 15 23) (7 11 19 15)); }
    axis { type symmetryPlane; faces ((0 1 21 20) (2 3 23 22)); }
    left { type patch; faces ((0 20 12 4) (4 12 16 8)); }
    farField { type patch; faces ((8 16 17 9) (10 18 19 11)); }
    back { type empty; faces ((0 4 5 1) (2 6 7 3) (4 8 9 5) (5 9 10 6) (6 10 11 7)); }
    front { type empty; faces ((20 21 13 12) (22 23 15 14) (12 13 17 16) (13 14 18 17) (14 15 19 18)); }
);
EOT
    movingConeSettings symmetryPlane empty "$@"
}

# movingConeWedgeCase [SELECTION]: the tutorial's own wedge mesh (its
# blockMeshDict: the axis an empty patch of collapsed faces, front and back
# wedge patches), the same motion and settings as the planar case
movingConeWedgeCase() {
    local tut="$FOAM_TUTORIALS/incompressible/pimpleFoam/laminar/movingCone"
    [ -d "$tut" ] || fail "no OpenFOAM tutorial at $tut (FOAM_TUTORIALS: re-run ./Allwmake)" || return 1
    mkdir -p system constant
    cp "$tut/system/fvSchemes" "$tut/system/fvSolution" "$tut/system/blockMeshDict" system/
    movingConeSettings empty wedge "$@"
}

# onWedgeAndAxis TIME MAXREL: at TIME every point of the wedge mesh is where
# OpenFOAM's wedge keeps it: the points off the axis on their wedge plane
# (| |z| - y tan a | with tan a the reference mesh's z/y at its largest y,
# the tutorial's vertices to 8 digits), the axis's points (y = z = 0 in the
# reference) on the axis; both at most MAXREL of the domain's diagonal
onWedgeAndAxis() {
    awk -v maxRel="$2" '
        function read(line, v) { gsub(/[()]/, "", line); return split(line, v, " ") }
        FNR == 1 { file++ }
        /^\(-?[0-9]/ {
            read($0, v); i = n[file]++
            x[file, i] = v[1]; y[file, i] = v[2]; z[file, i] = v[3]
        }
        END {
            yMax = -1
            for (i = 0; i < n[1]; i++) {
                if (y[1, i] > yMax) { yMax = y[1, i]; t = z[1, i] / y[1, i]; if (t < 0) t = -t }
                if (i == 0 || x[1, i] < xLo) xLo = x[1, i]; if (i == 0 || x[1, i] > xHi) xHi = x[1, i]
            }
            diag = sqrt((xHi - xLo)^2 + 4*yMax^2)
            for (i = 0; i < n[1]; i++) {
                if (y[1, i] == 0 && z[1, i] == 0) {
                    nAxis++; e = sqrt(y[2, i]^2 + z[2, i]^2); if (e > axisErr) axisErr = e
                } else {
                    e = z[2, i]; if (e < 0) e = -e; e -= t*y[2, i]; if (e < 0) e = -e
                    if (e > planeErr) planeErr = e
                }
            }
            printf "%d points, %d on the axis: off the wedge planes %g, off the axis %g (of the diagonal)\n",
                n[1], nAxis, planeErr/diag, axisErr/diag
            exit !(n[1] == n[2] && nAxis > 10 && planeErr/diag <= maxRel && axisErr/diag <= maxRel)
        }' constant/polyMesh/points "$1/polyMesh/points" \
        || fail "points off their wedge planes or off the axis at t = $1"
}

# The wedge moves as the planar case does: with every boundary point a
# control point (no swap: the quality measured on the wedge's cells in 3D,
# on the planar case's as polygons), each point of the wedge's back plane
# and axis ends where the planar case's back-plane point at the same x and
# y does (the interpolation in the wedge's centre plane, the wedge planes
# and the axis restored by OpenFOAM's twoDPointCorrector and wedge
# constraints): to 1e-9 of the diagonal. Measured 2.4e-10, all of it the
# axis's points' y: the planar case's symmetryPlane removes y exactly, the
# wedge's two constraints leave the line across their normals, 4e-9 off x
# (the tutorial's vertices to 8 digits), 1.7e-12 m at 0.44 mm along it
test_movingConeWedge_movesAsThePlanarCase() {
    movingConeWedgeCase all || return 1
    run moveDynamicMesh || return 1
    meshOkAtEveryTime || return 1
    onWedgeAndAxis 0.0005 1e-6 || return 1
    (mkdir planar && cd planar && movingConePlanarCase all && run moveDynamicMesh) \
        || fail "the planar case failed (see planar/log.*)" || return 1
    awk '
        function read(line, v) { gsub(/[()]/, "", line); return split(line, v, " ") }
        FNR == 1 { file++; i = 0 }
        /^\(-?[0-9]/ {
            read($0, v)
            k = sprintf("%.10e %.10e", v[1], v[2])   # x, y to 1e-10 (blockMesh: an ulp apart on the axis)
            if (file == 1 && v[3] < 0) { at[k] = i; nBack++; if (v[1] < lo) lo = v[1]; if (v[1] > hi) hi = v[1]; if (v[2] > yHi) yHi = v[2] }
            if (file == 2) { px[i] = v[1]; py[i] = v[2] }
            if (file == 3) { key[i] = (v[3] <= 0 && k in at) ? at[k] : -1 }
            if (file == 4 && key[i] >= 0) {
                nMatched++; d = sqrt((v[1] - px[key[i]])^2 + (v[2] - py[key[i]])^2); if (d > m) m = d
            }
            i++
        }
        END {
            diag = sqrt((hi - lo)^2 + yHi^2)
            printf "%d of %d planar back-plane points matched: largest difference %g of the diagonal\n", nMatched, nBack, m/diag
            exit !(nBack > 100 && nMatched == nBack && m/diag <= 1e-9)
        }' planar/constant/polyMesh/points planar/0.0005/polyMesh/points \
        constant/polyMesh/points 0.0005/polyMesh/points \
        || fail "the wedge moved otherwise than the planar case"
}

# The outer cylinder (farField, farFieldMoving) widening by 0.2 mm/ms with
# the cone still, the end walls slip: the radial motion moves the wedge
# planes' points off their planes unless OpenFOAM's wedge correction puts
# them back, and the axis's points off the axis unless its constraints hold
# them
test_movingConeWedge_radialMotionKeepsWedgeAndAxis() {
    movingConeWedgeCase all || return 1
    sed -i 's/"(farField|farFieldMoving)" { type slip; }/"(farField|farFieldMoving)" { type uniformFixedValue; uniformValue table ((0 (0 0 0)) (1 (0 0.2 0))); value uniform (0 0 0); }/
            s/"(fixedWall|left)" { type fixedValue; value uniform (0 0 0); }/"(fixedWall|left)" { type slip; }/
            s/movingWall { type uniformFixedValue.*/movingWall { type fixedValue; value uniform (0 0 0); }/' 0/pointDisplacement
    dynamicMeshDict "movingPatches (farField farFieldMoving); staticPatches (movingWall);
    supportRadius 0.01; controlPoints { selection all; }"
    run moveDynamicMesh || return 1
    meshOkAtEveryTime || return 1
    onWedgeAndAxis 0.0005 1e-6
}

# On 2 processors (simple 2 1 1: split in x through the cone, its wedge
# planes and its axis), with dynamic control points: the serial points
test_movingConeWedge_parallelEqualsSerial() {
    movingConeWedgeCase || return 1
    foamDictionary system/controlDict -entry endTime -set 0.00025 > /dev/null
    parallelEqualsSerial 0.00025
}

# The slip far field is flat to 1 ulp after blockMesh (y = 0.0025 +- 4e-19).
# Its condition removes the displacement's normal part; with the moved
# wall's normals (OpenFOAM's slip) the tilt from round-off turned part of
# the far field's x displacement (larger than its cells after ~60 steps)
# into a normal one, growing ~3 times a step: cells inverted from step 56 on.
test_movingConePlanar_slipFarFieldStaysFlat() {
    movingConePlanarCase || return 1
    run moveDynamicMesh || return 1
    ! grep -q "inverted" log.moveDynamicMesh || fail "inverted cells: $(grep -m1 -A1 inverted log.moveDynamicMesh)" || return 1
    meshOkAtEveryTime || return 1
    { awk -v patch=farField -f "$here/cases/patchPoints.awk" constant/polyMesh/boundary constant/polyMesh/faces \
        && awk -v patch=farFieldMoving -f "$here/cases/patchPoints.awk" constant/polyMesh/boundary constant/polyMesh/faces
    } | sort -un > farField.labels || fail "no farField or farFieldMoving points" || return 1
    # the far field's points (both patches) moved along x only: their y as at the start
    awk 'FNR == NR { want[$1] = 1; next }
         FILENAME == ARGV[2] && /^\([-0-9]/ { i++; if ((i - 1) in want) { gsub(/[()]/, ""); y0[i - 1] = $2; n++ } next }
         FILENAME == ARGV[3] && /^\([-0-9]/ { j++; if ((j - 1) in want) { gsub(/[()]/, ""); d = $2 - y0[j - 1]; if (d < 0) d = -d; if (d > m) m = d } next }
         END { printf "far field: %d points, max |y - y0| %g m\n", n, m; exit !(n > 50 && m < 1e-12) }' \
        farField.labels constant/polyMesh/points 0.0005/polyMesh/points \
        || fail "the slip far field left its plane" || return 1
}

# The same on 2 processors, the far field cut between them (simple 2 1 1
# splits in x through farFieldMoving): the slip normals and the motion as
# in serial
test_movingConePlanar_parallelEqualsSerial() {
    movingConePlanarCase || return 1
    foamDictionary system/controlDict -entry endTime -set 0.00025 > /dev/null
    parallelEqualsSerial 0.00025
}

# The cone pushed 3 times as fast: cells invert. The warning suggests what
# is not set already: selection dynamic and a qualityFloor for greedy; only
# the floor for dynamic; never selection dynamic for all (exact at every
# boundary point already). A warning that holds step after step is given in
# full on the first step of a run of them and every 100 steps (each step's
# dcpRBF line counts the cells: a run under a flow solver wrote 19 000
# warning lines); the fall of the minimum quality below 0.2 is said once,
# before the first inverted cell (this motion squeezes the cells over many
# steps: a step with 0 < q < 0.2 comes first; a motion that jumped past it
# would need another check)
test_movingConePlanar_invertedWarningSuggestsWhatIsNotSet() {
    local sel expected got low first
    movingConePlanarCase || return 1
    sed -i 's/(1 (1 0 0))/(1 (3 0 0))/' 0/pointDisplacement
    foamDictionary system/controlDict -entry endTime -set 0.0016 > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 1000 > /dev/null
    for sel in greedy dynamic all
    do
        dynamicMeshDict "movingPatches (movingWall); staticPatches (fixedWall left);
        supportRadius 0.01; controlPoints { selection $sel; }"
        rm -rf 0.0* postProcessing
        run moveDynamicMesh || return 1
        grep -A2 "inverted or degenerate" log.moveDynamicMesh | tr '\n' ' ' > warning.$sel
        [ -s warning.$sel ] || fail "$sel: no inverted cells (the test needs them)" || return 1
        grep -q "set a qualityFloor" warning.$sel || fail "$sel: no qualityFloor advice: $(head -c 400 warning.$sel)" || return 1
        # in full: one per started 100 steps of each run of inverted steps
        expected=$(awk '!/^#/ { if ($7 <= 0) { if (n % 100 == 0) w++; n++ } else n = 0 }
                        END { print w + 0 }' postProcessing/dcpRBF/0/dcpRBF.dat)
        got=$(grep -c "inverted or degenerate" log.moveDynamicMesh)
        echo "$sel: $got inverted-cell warnings in full, expected $expected"
        [ "$got" = "$expected" ] || fail "$sel: $got warnings in full, expected $expected" || return 1
        low=$(grep -c "minimum cell quality fell to" log.moveDynamicMesh)
        [ "$low" = 1 ] || fail "$sel: the low quality said $low times, not once" || return 1
        first=$(grep -n -m1 "inverted or degenerate" log.moveDynamicMesh | cut -d: -f1)
        [ "$(grep -n -m1 "minimum cell quality fell to" log.moveDynamicMesh | cut -d: -f1)" -lt "$first" ] \
            || fail "$sel: the low quality said after the first inverted cells" || return 1
        [ "$sel" = all ] || [ "$expected" -ge 2 ] \
            || fail "$sel: fewer than 101 inverted steps in a row (the test needs a repeat)" || return 1
        rm -f log.moveDynamicMesh*
    done
    grep -q "use selection dynamic" warning.greedy || fail "greedy: selection dynamic not suggested" || return 1
    ! grep -q "use selection dynamic" warning.dynamic || fail "dynamic: selection dynamic suggested although set" || return 1
    ! grep -q "use selection dynamic" warning.all || fail "all: selection dynamic suggested (every boundary point is a control point)" || return 1
}
