# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration test: the flap3D tutorial shortened (coarse mesh, 4 steps to the
# flap's +40 deg at t = 20): the hinge's three bodies (the wing still, the
# strip turning by the blend of hingeStripDisplacement, the flap turning
# rigidly about the hinge) land where the formulas put every point of their
# surfaces, checkMesh passes; the same on 2 processors split across the
# span gives the serial points; a hinge point off the motion's axis is
# refused, naming hingePoint. With rotationInterpolation and blendProfile
# hinge (the flap turning on the wing), the same surface and a valid mesh;
# the hinge's keywords refused where they cannot serve.

# flap3DCoarse: the tutorial's case on its coarse mesh, to t = 20 in 4 steps
flap3DCoarse() {
    local py tut="$top/tutorials/flap3D" wall
    py=$(pythonWithGmsh) || fail "no python with gmsh" || return 1
    "$py" "$tut/flapMesh.py" flap.msh --coarse > log.mesh 2>&1 || fail "gmsh failed: $(tail -3 log.mesh)" || return 1
    cp -r "$tut/system" "$tut/constant" .
    rm -rf constant/polyMesh
    cp -r "$tut/0.orig" 0
    run gmshToFoam flap.msh || return 1
    for wall in wing hinge flap
    do
        foamDictionary constant/polyMesh/boundary -entry entry0/$wall/type -set wall > /dev/null
    done
    foamDictionary constant/polyMesh/boundary -entry entry0/symmetry/type -set symmetryPlane > /dev/null
    foamDictionary system/controlDict -entry endTime -set 20 > /dev/null
    foamDictionary system/controlDict -entry deltaT -set 5 > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 20 > /dev/null
}

# surfaceAsFormula TIME DEG: every point of wing, hinge and flap at TIME is
# turned about the hinge line (x = 0.75, z = 0, along y) by s DEG, s the
# strip's quintic blend of x0 from 0 at x0 = 0.70 to 1 at x0 = 0.80 (1e-9 m)
surfaceAsFormula() {
    local p
    for p in wing hinge flap
    do
        awk -v patch=$p -f "$here/cases/patchPoints.awk" constant/polyMesh/boundary constant/polyMesh/faces
    done | sort -un > surface.labels
    [ "$(wc -l < surface.labels)" -gt 1000 ] || fail "only $(wc -l < surface.labels) surface points" || return 1
    paste -d' ' <(awk '/^\(.*\)$/ && NF == 3 { gsub(/[()]/, ""); print }' constant/polyMesh/points) \
                <(awk '/^\(.*\)$/ && NF == 3 { gsub(/[()]/, ""); print }' "$1/polyMesh/points") \
        | awk -v deg="$2" 'NR == FNR { on[$1 + 1] = 1; next }
        function abs(v) { return v < 0 ? -v : v }
        (FNR in on) {
            t = ($1 - 0.70)/0.10; t = t < 0 ? 0 : (t > 1 ? 1 : t)
            s = t*t*t*(10 - 15*t + 6*t*t)
            a = s*deg*atan2(0, -1)/180; u = $1 - 0.75
            ex = 0.75 + u*cos(a) + $3*sin(a); ez = -u*sin(a) + $3*cos(a)
            err = abs($4 - ex) + abs($5 - $2) + abs($6 - ez)
            if (err > worst) worst = err
            if (s > 0 && s < 1) nStrip++
            n++
        }
        END {
            printf "%d surface points (%d inside the strip), largest error %g m\n", n, nStrip, worst
            exit !(worst <= 1e-9 && nStrip > 100)
        }' surface.labels - || fail "the surface is not where the hinge formulas put it"
}

test_flap3D_hingeBodies_meshValidSurfaceAsFormula() {
    flap3DCoarse || return 1
    run moveDynamicMesh || return 1
    reportsSetUp WendlandC2 3D
    meshOkAtEveryTime || return 1
    surfaceAsFormula 20 40
}

# The same motion on 2 processors (the tutorial's decomposition, split in y
# across the span: through the wing, the strip and the flap) gives the serial
# points; decomposePar keeps hingeStripDisplacement
test_flap3D_parallelEqualsSerial() {
    flap3DCoarse || return 1
    parallelEqualsSerial 20 'method hierarchical; coeffs { n (1 2 1); order xyz; }' || return 1
    local p
    for p in 0 1
    do
        grep -q hingeStripDisplacement "par/processor$p/0/pointDisplacement" \
            || fail "decomposePar lost hingeStripDisplacement (processor$p)"
    done
}

# hingeRotation [ROTATION]: rotationInterpolation with the flap's hinge (the
# rotation dictionary ROTATION; default: the hinge line, blendProfile hinge,
# hingedTo the wing and the symmetry plane)
hingeRotation() {
    local rotation='{ centre (0.75 0 0); axis (0 1 0); blendProfile hinge; hingedTo (wing symmetry); }'
    [ $# -gt 0 ] && rotation="$1"
    foamDictionary constant/dynamicMeshDict -entry dcpRBFCoeffs/rotationInterpolation -add true > /dev/null
    foamDictionary constant/dynamicMeshDict -entry dcpRBFCoeffs/rotation -add "$rotation" > /dev/null
}

# rotationInterpolation on the flap, which turns on the static wing along
# the hinge line (the star ring has no room there: refused without the
# hinge): blendProfile hinge keeps the mesh valid to +40 deg, the surface
# where the hinge formulas put it, the wing and the symmetry plane out of
# the ring (the log says how many of their points)
test_flap3D_hingeBlend_meshValidSurfaceAsFormula() {
    flap3DCoarse || return 1
    hingeRotation
    run moveDynamicMesh || return 1
    grep -q "blendProfile hinge, hinged to [1-9][0-9]* static points" log.moveDynamicMesh \
        || fail "no hinge in the set-up: $(grep -m1 -A1 'rotationInterpolation, 1 body' log.moveDynamicMesh)" || return 1
    meshOkAtEveryTime || return 1
    surfaceAsFormula 20 40 || return 1
    # the flap turns about the span axis: no point moves along the span
    # (1e-12 m: round-off)
    paste -d' ' <(awk '/^\(.*\)$/ && NF == 3 { gsub(/[()]/, ""); print }' constant/polyMesh/points) \
                <(awk '/^\(.*\)$/ && NF == 3 { gsub(/[()]/, ""); print }' 20/polyMesh/points) \
        | awk '{ d = $5 - $2; if (d < 0) d = -d; if (d > m) m = d; n++ }
            END { printf "%d points, largest motion along the span %g m\n", n, m; exit !(n > 9000 && m <= 1e-12) }' \
        || fail "points moved along the span: the hinge blend turns off the hinge's axis"
}

# The hinge blend on 2 processors split across the span (the wing, the
# strip and the flap cut; hingedTo's points marked on each processor and
# gathered) gives the serial points
test_flap3D_hingeBlend_parallelEqualsSerial() {
    flap3DCoarse || return 1
    hingeRotation
    parallelEqualsSerial 20 'method hierarchical; coeffs { n (1 2 1); order xyz; }' || return 1
    grep -q "hinged to [1-9][0-9]* static points" par/log.mpirun \
        || fail "the parallel run has no hinge: $(grep -m1 'blendProfile' par/log.mpirun)"
}

# The hinge's refusals, each naming its keyword: hingedTo a moving patch,
# hingedTo without blendProfile hinge, blendProfile hinge without the
# hinge line's axis in 3D
test_flap3D_hingeBlendRefusals() {
    local case rotation expect
    flap3DCoarse || return 1
    cp constant/dynamicMeshDict dynamicMeshDict.orig
    for case in movingPartner notHinge noAxis
    do
        case $case in
        (movingPartner) rotation='{ centre (0.75 0 0); axis (0 1 0); blendProfile hinge; hingedTo (wing flap); }'
                        expect='Keyword hingedTo: patch flap is in movingPatches' ;;
        (notHinge)      rotation='{ centre (0.75 0 0); axis (0 1 0); hingedTo (wing); }'
                        expect='Keyword hingedTo has no effect with blendProfile star' ;;
        (noAxis)        rotation='{ centre (0.75 0 0); blendProfile hinge; hingedTo (wing); }'
                        expect='blendProfile hinge: body movingPatches needs its hinge line: centre (a point of it) and axis' ;;
        esac
        cp dynamicMeshDict.orig constant/dynamicMeshDict
        hingeRotation "$rotation"
        ! moveDynamicMesh > "log.$case" 2>&1 || fail "$case: accepted" || return 1
        grep -A4 "FOAM FATAL IO ERROR" "log.$case" | tr '\n' ' ' > fatal
        grep -qF "$expect" fatal || fail "$case: the FatalIOError does not say: $expect: $(head -c 300 fatal)" || return 1
    done
}

# A hinge point off the motion's axis: the strip could not meet the flap;
# refused at the first step that turns, naming hingePoint; a blend that ends
# before it starts: refused at the start, naming blendEnd
test_flap3D_hingeOffAxisRefused() {
    flap3DCoarse || return 1
    foamDictionary 0/pointDisplacement -entry boundaryField/hinge/hingePoint -set "(0.70 0 0)" > /dev/null
    ! moveDynamicMesh > log.moveDynamicMesh 2>&1 || fail "a hinge point off the axis was accepted"
    grep -A6 "FOAM FATAL ERROR" log.moveDynamicMesh | tr '\n' ' ' > fatal
    grep -q "patch hinge (hingeStripDisplacement).* moves hingePoint (0.69[0-9]* 0 0)" fatal \
        || fail "the FatalError does not name hingePoint: $(head -c 400 fatal)"
    foamDictionary 0/pointDisplacement -entry boundaryField/hinge/hingePoint -set "(0.75 0 0)" > /dev/null
    foamDictionary 0/pointDisplacement -entry boundaryField/hinge/blendEnd -set "-0.1" > /dev/null
    ! moveDynamicMesh > log.moveDynamicMesh.2 2>&1 || fail "blendEnd before blendStart was accepted"
    grep -A6 "FOAM FATAL IO ERROR" log.moveDynamicMesh.2 | tr '\n' ' ' > fatal
    grep -q "patch hinge: blendEnd -0.1[0-9]* must be greater than blendStart -0.05[0-9]*" fatal \
        || fail "the FatalIOError does not name blendEnd: $(head -c 400 fatal)"
}

# flap3D/flow (the flap oscillating under pimpleFoam) shortened to 10 steps,
# written at 5 and 10, without the steady cases: on 2 processors (split
# across the span) the points of the serial run at both times (1e-12 of the
# domain); restarted from 5, the uninterrupted run's points at 10 bit for
# bit (the time 0.1 the sum of its 5 steps exactly: OpenFOAM restarts at
# the time its folder's name says; the set restored in another order moves
# them by 3e-14 m); dcpRBF's share reported for both runs. (The
# forces are reported, not judged: in the impulsive start the parallel
# pressure solver, stopping elsewhere within its tolerance, moves Cl by 1 %)
test_flap3D_flow_parallelEqualsSerialRestartEqualsUninterrupted() {
    copyTutorials flap3D || return 1
    local flow=tutorials/flap3D/flow
    DCPRBF_DIR="$top" "$flow/Allrun" -endTime 0.2 -noSteady > log.Allrun 2>&1 \
        || fail "Allrun failed: $(tail -n 5 log.Allrun)" || return 1
    [ "$(countLines '^t = ' "$flow/log.compare.parallel")" -eq 2 ] \
        || fail "not 2 times compared: $(cat "$flow/log.compare.parallel")" || return 1
    sed 's/^/serial vs parallel, /' "$flow/log.compare.parallel"
    awk '{ if (!($5 <= 1e-12)) bad = 1 } END { exit bad }' "$flow/log.compare.parallel" \
        || fail "serial and parallel points differ" || return 1
    cat "$flow/log.compare.restart"
    grep -q "restart from t = 0.1: t = 0.2:" "$flow/log.compare.restart" \
        || fail "not restarted from 0.1" || return 1
    awk '{ exit !($NF > 9000 && $(NF - 2) == 0) }' "$flow/log.compare.restart" \
        || fail "the restart's points differ from the uninterrupted run's" || return 1
    grep -q "restarting with" "$flow/restart/log.pimpleFoam" \
        || fail "the restart did not read the control set's state" || return 1
    local plots="$flow/log.python3.plots"
    grep '^flow' "$plots"
    [ "$(countLines '^flow dcpRBF share' "$plots")" -eq 2 ] || fail "dcpRBF's share not reported"
}


# A roll of the whole wing (wing, hinge and flap turning 2 deg about the x
# axis through the root's chord line, by t = 20 in 4 steps) moves the
# interpolated points of the symmetry plane y = 0 off it, which its
# condition takes back. On 2 processors cut at x = 0.75, every cell that
# touches the plane by a vertex or an edge only sent to the other processor
# (manualDecomposition.awk), a processor holds points of the plane without
# any of its faces: the processors agree on the constrained displacement,
# the points are the serial ones (1e-10) and no point of the plane leaves it
test_flap3D_symmetryPointWithoutItsFace_parallelEqualsSerial() {
    flap3DCoarse || return 1
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    "(wing|hinge|flap)"
    {
        type solidBodyMotionDisplacement;
        solidBodyMotionFunction oscillatingRotatingMotion;
        origin (0 0 0); amplitude (2 0 0); omega 0.0785398163;
        value uniform (0 0 0);
    }
    symmetry { type symmetryPlane; }
    farfield { type fixedValue; value uniform (0 0 0); }
}
EOT
    foamDictionary constant/dynamicMeshDict -entry dcpRBFCoeffs/movingPatches -set "(wing hinge flap)" > /dev/null
    foamDictionary constant/dynamicMeshDict -entry dcpRBFCoeffs/staticPatches -set "(farfield)" > /dev/null
    manualDecomposition 0.75 "wing hinge flap" "symmetry" static || return 1
    parallelEqualsSerial 20 "$manualDecompositionDict" || return 1
    local p
    for p in wing hinge flap
    do
        awk -v patch=$p -f "$here/cases/patchPoints.awk" constant/polyMesh/boundary constant/polyMesh/faces
    done | sort -un > wing.labels
    awk -v patch=symmetry -f "$here/cases/patchPoints.awk" constant/polyMesh/boundary constant/polyMesh/faces \
        | sort -un > symmetry.labels
    # (the root section's points roll with the wing, out of the plane)
    awk 'FILENAME == ARGV[1] { wing[$1 + 1] = 1; next }
        FILENAME == ARGV[2] { if (!(($1 + 1) in wing)) on[$1 + 1] = 1; next }
        /^\(.*\)$/ && NF == 3 { gsub(/[()]/, ""); k++; if (k in on) { n++; if ($2 > 1e-12 || $2 < -1e-12) off++ } }
        END { printf "%d points of the symmetry plane off the wing, %d off y = 0\n", n, off; exit !(n > 100 && off == 0) }' \
        wing.labels symmetry.labels par/20/polyMesh/points || fail "points of the symmetry plane left it on 2 processors"
}
