# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: a body close to sliding walls in 3D (from a new user's
# trial). A box wing (chord 1 in x, span 1 in y, thickness 0.2 in z) on a
# symmetryPlane (y = 0) in a duct with slip sides (z = +-0.75, 0.65 from
# the body) and top (y = 1.5), inlet and outlet static, pitching +-20 deg
# about the spanwise axis at the quarter chord, supportRadius 2.5. Where the
# symmetry plane meets a side wall, a blend of the nearest sliding point's
# change alone left the points next to the corner uncorrected (the nearest
# was a corner point of the plane, its change the plane's): they crossed
# the side wall by 0.1 and cells folded from 10 deg.

slipDuctCase() {
    cat > duct.py <<'EOT'
X = [-2.0, 0.0, 1.0, 4.0]; Y = [0.0, 1.0, 1.5]; Z = [-0.75, -0.1, 0.1, 0.75]
NX = [12, 12, 16]; NY = [12, 6]; NZ = [10, 5, 10]
GX = ["0.25", "1", "4"]; GY = ["1", "3"]; GZ = ["0.25", "1", "4"]
vid = {}
verts = []
for k, z in enumerate(Z):
    for j, y in enumerate(Y):
        for i, x in enumerate(X):
            vid[(i, j, k)] = len(verts)
            verts.append((x, y, z))
def hexv(i, j, k):
    return [vid[(i, j, k)], vid[(i + 1, j, k)], vid[(i + 1, j + 1, k)], vid[(i, j + 1, k)],
            vid[(i, j, k + 1)], vid[(i + 1, j, k + 1)], vid[(i + 1, j + 1, k + 1)], vid[(i, j + 1, k + 1)]]
body = (1, 0, 1)
blocks = [(i, j, k) for k in range(3) for j in range(2) for i in range(3) if (i, j, k) != body]
sides = {'-x': (0, 4, 7, 3), '+x': (1, 2, 6, 5), '-y': (0, 1, 5, 4), '+y': (3, 7, 6, 2),
         '-z': (0, 3, 2, 1), '+z': (4, 5, 6, 7)}
def face(b, d):
    h = hexv(*b)
    return [h[a] for a in sides[d]]
faces = {n: [] for n in ["inlet", "outlet", "symmetry", "top", "sides", "body"]}
for b in blocks:
    i, j, k = b
    if i == 0: faces["inlet"].append(face(b, '-x'))
    if i == 2: faces["outlet"].append(face(b, '+x'))
    if j == 0: faces["symmetry"].append(face(b, '-y'))
    if j == 1: faces["top"].append(face(b, '+y'))
    if k == 0: faces["sides"].append(face(b, '-z'))
    if k == 2: faces["sides"].append(face(b, '+z'))
    for d, nb in {'+x': (i + 1, j, k), '-x': (i - 1, j, k), '+y': (i, j + 1, k),
                  '-y': (i, j - 1, k), '+z': (i, j, k + 1), '-z': (i, j, k - 1)}.items():
        if nb == body: faces["body"].append(face(b, d))
types = {"inlet": "patch", "outlet": "patch", "symmetry": "symmetryPlane", "top": "patch",
         "sides": "patch", "body": "wall"}
with open("system/blockMeshDict", "w") as o:
    o.write("FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }\n")
    o.write("convertToMeters 1;\nvertices\n(\n")
    for v in verts: o.write("  (%g %g %g)\n" % v)
    o.write(");\nblocks\n(\n")
    for (i, j, k) in blocks:
        o.write("  hex (%s) (%d %d %d) simpleGrading (%s %s %s)\n"
                % (" ".join(map(str, hexv(i, j, k))), NX[i], NY[j], NZ[k], GX[i], GY[j], GZ[k]))
    o.write(");\nedges ();\nboundary\n(\n")
    for n, fl in faces.items():
        o.write("  %s { type %s; faces (%s); }\n" % (n, types[n], " ".join("(%s)" % " ".join(map(str, f)) for f in fl)))
    o.write(");\nmergePatchPairs ();\n")
EOT
    write_motionControls .
    foamDictionary system/controlDict -entry endTime -set 0.15 > /dev/null
    foamDictionary system/controlDict -entry deltaT -set 0.01 > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 15 > /dev/null
    python3 duct.py > log.duct 2>&1 || fail "duct.py failed: $(tail -n 3 log.duct)" || return 1
    run blockMesh || return 1
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    body
    {
        type angularOscillatingDisplacement; axis (0 1 0); origin (0.25 0 0);
        angle0 0; amplitude 0.34906585; omega 6.2831853; value uniform (0 0 0);
    }
    "(inlet|outlet)" { type fixedValue; value uniform (0 0 0); }
    "(top|sides)" { type slip; }
    symmetry { type symmetryPlane; }
}
EOT
    dynamicMeshDict "movingPatches (body); staticPatches (inlet outlet); supportRadius 2.5;
    controlPoints { selection dynamic; }"
}

# To 16 deg (t = 0.15): no inverted cell, no point beyond a side wall (was:
# inverted from 10 deg, the symmetry plane's points 0.1 beyond the wall)
test_slipDuct3D_symmetryPlaneMeetsSlipWall() {
    slipDuctCase || return 1
    run moveDynamicMesh || return 1
    ! grep -q "inverted" log.moveDynamicMesh || fail "inverted cells: $(grep -m1 inverted log.moveDynamicMesh)" || return 1
    meshOkAtEveryTime || return 1
    awk '/^\([-0-9]/ { gsub(/[()]/, ""); z = $3 < 0 ? -$3 : $3; if (z > m) m = z; n++ }
         END { printf "%d points: max |z| %.6f\n", n, m; exit !(n > 1000 && m <= 0.75 + 1e-12) }' \
        0.15/polyMesh/points || fail "points beyond the side walls"
}

