# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: a body pitching between curved slip walls (from a new
# user's trial). A 2D annulus-segment channel (centre (0 0), radii 2 and 5,
# 30-150 deg; inlet and outlet static) with an ellipse (chord 1) at (0 3.5)
# pitching +-20 deg about (-1 3.5); the walls are slip, in neither list. The
# interpolant's linear part carries the body's rotation out to the walls;
# their slip condition removes its normal part at the wall points only, and
# before dcpRBFSlipCorrection the points next to the walls crossed them:
# inverted cells from t = 0.2, minimum quality -2.5.

slipChannelCase() {
    local py
    py=$(pythonWithGmsh) || fail "no python with gmsh" || return 1
    cat > channel.py <<'EOT'
import gmsh, math
R1, R2, a0, a1 = 2.0, 5.0, math.radians(30), math.radians(150)
gmsh.initialize(); gmsh.option.setNumber("General.Terminal", 0)
g = gmsh.model.geo
O = g.addPoint(0, 0, 0, 0.15)
p = lambda r, a: g.addPoint(r*math.cos(a), r*math.sin(a), 0, 0.15)
i0, i1, o0, o1 = p(R1, a0), p(R1, a1), p(R2, a0), p(R2, a1)
inner = g.addCircleArc(i0, O, i1)
# SPLIT_OUTER=1: the outer wall as two patches, meeting at 90 deg
split = __import__("os").environ.get("SPLIT_OUTER") == "1"
top = p(R2, math.pi/2)
outer = [g.addCircleArc(o1, O, top), g.addCircleArc(top, O, o0)] if split else [g.addCircleArc(o1, O, o0)]
outlet, inlet = g.addLine(o0, i0), g.addLine(i1, o1)
C = g.addPoint(0, 3.5, 0, 0.03)
E = [g.addPoint(0.5, 3.5, 0, 0.03), g.addPoint(0, 3.65, 0, 0.03),
     g.addPoint(-0.5, 3.5, 0, 0.03), g.addPoint(0, 3.35, 0, 0.03)]
el = [g.addEllipseArc(E[k], C, E[0], E[(k + 1) % 4]) for k in range(4)]
s = g.addPlaneSurface([g.addCurveLoop([inner, inlet] + outer + [outlet]), g.addCurveLoop(el)])
g.synchronize()
f = gmsh.model.mesh.field
d = f.add("Distance"); f.setNumbers(d, "CurvesList", el); f.setNumber(d, "NumPointsPerCurve", 200)
t = f.add("Threshold"); f.setNumber(t, "InField", d); f.setNumber(t, "SizeMin", 0.03)
f.setNumber(t, "SizeMax", 0.15); f.setNumber(t, "DistMin", 0.05); f.setNumber(t, "DistMax", 1.5)
f.setAsBackgroundMesh(t)
gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
ex = g.extrude([(2, s)], 0, 0, 0.1, numElements=[1], recombine=True)
g.synchronize()
lat = [e[1] for e in ex[2:]]
k = len(outer)
walls = [(2, [lat[2]], "outerWallA"), (2, [lat[3]], "outerWallB")] if split else [(2, [lat[2]], "outerWall")]
for dim, tags, name in [(2, [s, ex[0][1]], "frontAndBack"), (2, [lat[0]], "innerWall"),
                        (2, [lat[1]], "inlet")] + walls + [
                        (2, [lat[2 + k]], "outlet"), (2, lat[3 + k:7 + k], "body"), (3, [ex[1][1]], "fluid")]:
    gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
gmsh.model.mesh.generate(3)
gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
gmsh.write("channel.msh"); gmsh.finalize()
EOT
    write_motionControls .
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    foamDictionary system/controlDict -entry deltaT -set 0.05 > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 10 > /dev/null
    "$py" channel.py > log.mesh 2>&1 || fail "gmsh failed: $(tail -n 3 log.mesh)" || return 1
    run gmshToFoam channel.msh || return 1
    foamDictionary constant/polyMesh/boundary -entry entry0/frontAndBack/type -set empty > /dev/null
    foamDictionary constant/polyMesh/boundary -entry entry0/body/type -set wall > /dev/null
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    body
    {
        type angularOscillatingDisplacement; axis (0 0 1); origin (-1 3.5 0);
        angle0 0; amplitude 0.3490658503988659; omega 1.5707963267948966;
        value uniform (0 0 0);
    }
    "(inlet|outlet)" { type fixedValue; value uniform (0 0 0); }
    "(innerWall|outerWall.*)" { type slip; }
    frontAndBack { type empty; }
}
EOT
    dynamicMeshDict "movingPatches (body); staticPatches (inlet outlet); supportRadius 3;
    controlPoints { selection dynamic; } $1"
}

# slipChannelInside TIME: every point off the walls lies between them
slipChannelInside() {
    { awk -v patch=innerWall -f "$here/cases/patchPoints.awk" constant/polyMesh/boundary constant/polyMesh/faces \
        && awk -v patch=outerWall -f "$here/cases/patchPoints.awk" constant/polyMesh/boundary constant/polyMesh/faces
    } | sort -un > walls.labels || fail "no wall points" || return 1
    awk 'FNR == NR { wall[$1] = 1; next }
         /^\([-0-9]/ { gsub(/[()]/, ""); if (!((i + 0) in wall)) { r = sqrt($1*$1 + $2*$2); if (r < lo || n == 0) lo = r; if (r > hi || n == 0) hi = r; n++ } i++ }
         END { printf "%d points off the walls: radius %.6f .. %.6f\n", n, lo, hi; exit !(n > 1000 && lo > 2 && hi < 5) }' \
        walls.labels "$1/polyMesh/points" || fail "points beyond the slip walls at t = $1"
}

# The default settings to the motion's largest normal mismatch at the walls
# so far (t = 0.5: 14 deg): no inverted cell, nothing beyond the walls
test_slipChannel_pointsStayBetweenTheWalls() {
    slipChannelCase "" || return 1
    run moveDynamicMesh || return 1
    ! grep -q "inverted" log.moveDynamicMesh || fail "inverted cells: $(grep -m1 inverted log.moveDynamicMesh)" || return 1
    meshOkAtEveryTime || return 1
    slipChannelInside 0.5
}

# polynomial false (the README's advice for a body rotating between slip
# walls), the whole +-20 deg: the cells next to the walls keep their shape
# (minimum quality 0.58; 0.09 before the slip correction)
test_slipChannel_polynomialFalseKeepsQuality() {
    local q
    slipChannelCase "polynomial false;" || return 1
    foamDictionary system/controlDict -entry endTime -set 1.5 > /dev/null
    run moveDynamicMesh || return 1
    meshOkAtEveryTime || return 1
    slipChannelInside 1 || return 1
    q=$(awk '!/^#/ { if (n == 0 || $7 < q) q = $7; n++ } END { print q }' postProcessing/dcpRBF/0/dcpRBF.dat)
    echo "minimum quality $q"
    awk -v q="$q" 'BEGIN { exit !(q > 0.4) }' || fail "minimum quality $q <= 0.4"
}

# On 2 processors (simple 2 1 1: the cut runs through the body and both
# walls): the slip correction's sources are gathered from both
test_slipChannel_parallelEqualsSerial() {
    slipChannelCase "" || return 1
    parallelEqualsSerial 0.5
}

# The whole +-20 deg with the linear polynomial: cells next to the outer wall
# fold near the largest angle (t = 0.9-1.1); the warning names polynomial
# false (with sliding walls and the polynomial on) and staticPatches, and
# does not suggest a larger supportRadius
test_slipChannel_invertedWarningSuggestsPolynomialFalse() {
    slipChannelCase "" || return 1
    foamDictionary system/controlDict -entry endTime -set 1.2 > /dev/null
    run moveDynamicMesh || return 1
    warningText "inverted or degenerate" 2 "no inverted cells (the test needs them)" || return 1
    grep -q "with sliding (slip) walls polynomial false" warning \
        || fail "polynomial false not suggested: $(head -c 400 warning)" || return 1
    # and staticPatches for the walls, not a larger supportRadius (which
    # carries more of the motion out to them)
    grep -q "list those the body does not touch under staticPatches" warning \
        || fail "staticPatches not suggested: $(head -c 400 warning)" || return 1
    ! grep -q "enlarge supportRadius" warning || fail "a larger supportRadius suggested with slip walls"
}

# On 2 processors, the manual decomposition (manualDecomposition.awk, the
# slip walls as its "static" patches) giving a processor wall points
# without any wall face there (triangles touching a wall at a vertex only):
# such a processor records no change at them; the changes are synchronised
# before they are gathered
test_slipChannel_parallelWallPointsWithoutFacesEqualSerial() {
    slipChannelCase "" || return 1
    manualDecomposition 0.1 "body" "innerWall outerWall" "static" || return 1
    parallelEqualsSerial 0.5 "$manualDecompositionDict"
}

# The outer wall as two slip patches meeting at 90 deg (above the body,
# where the correction is largest) against the same mesh with them merged
# into one: one wall (their reference normals agree at the seam), one blend.
# Corrected once per patch, the points next to the seam got up to twice the
# normal correction (0.18 m from the merged wall's points, 1.9e-2 of the
# domain); as one wall 4e-3 m (4e-4: OpenFOAM's slip condition projects the
# seam point with each patch's own normal there, half a face angle from
# the merged patch's)
test_slipChannel_splitWallCorrectedAsOne() {
    export SPLIT_OUTER=1
    mkdir -p merged && (
        cd merged || exit 1
        slipChannelCase "" || exit 1
        mergeOuterWall || exit 1
        run moveDynamicMesh
    ) || fail "the merged run failed (see merged/log.*)" || return 1
    slipChannelCase "" || return 1
    grep -q outerWallB constant/polyMesh/boundary || fail "no split wall" || return 1
    run moveDynamicMesh || return 1
    pointsAgree 0.5/polyMesh/points merged/0.5/polyMesh/points 2e-3 \
        "split vs merged outer wall at t = 0.5"
}

# The adjoining patches outerWallA and outerWallB (contiguous faces) of
# constant/polyMesh/boundary as one patch outerWall
mergeOuterWall() {
    local b=constant/polyMesh/boundary nA sA nB sB
    nA=$(foamDictionary $b -entry entry0/outerWallA/nFaces -value) || return 1
    sA=$(foamDictionary $b -entry entry0/outerWallA/startFace -value) || return 1
    nB=$(foamDictionary $b -entry entry0/outerWallB/nFaces -value) || return 1
    sB=$(foamDictionary $b -entry entry0/outerWallB/startFace -value) || return 1
    [ $((sA + nA)) -eq "$sB" ] || fail "outerWallA and outerWallB are not contiguous" || return 1
    foamDictionary $b -entry entry0/outerWallA/nFaces -set $((nA + nB)) > /dev/null || return 1
    foamDictionary $b -entry entry0/outerWallB -remove > /dev/null || return 1
    sed -i 's/^\( *\)outerWallA$/\1outerWall/' $b
    grep -q "^ *outerWall$" $b && ! grep -q outerWallB $b || fail "boundary not merged" || return 1
}

# The split wall on 2 processors (simple 2 1 1: the cut runs through the
# seam at x = 0, each processor holds one of the two patches): one wall on
# both (the patches' normals synchronised), and at the seam points the
# change is the constrained displacement minus the one before the wall's
# conditions, the same on both (each processor's own patch's change there:
# 3.2e-4 of the domain from serial; as two walls 1.9e-2)
test_slipChannel_splitWallParallelEqualsSerial() {
    export SPLIT_OUTER=1
    slipChannelCase "" || return 1
    parallelEqualsSerial 0.5
}

# The guard's shortfall with sliding walls: its advice names staticPatches
# for them, not only a larger supportRadius (a new user's trial: a larger
# radius carries more of the motion out to sliding walls)
test_slipChannel_guardShortfallNamesStaticPatches() {
    slipChannelCase "qualityFloor 0.99; guardIterations 1;" || return 1
    foamDictionary system/controlDict -entry endTime -set 0.1 > /dev/null
    run moveDynamicMesh || return 1
    warningText "below qualityFloor" 3 "the floor was met (the test needs it unmet)" || return 1
    grep -q "guardIterations 1; where more points do not raise the minimum, raise supportRadius or, with sliding walls near the body, list them under staticPatches" warning \
        || fail "no staticPatches advice: $(head -c 500 warning)"
}
