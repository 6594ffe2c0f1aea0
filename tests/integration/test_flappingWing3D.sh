# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration test: the flappingWing3D tutorial's motion without the flow
# (coarse mesh, moveDynamicMesh, 4 steps to the largest angles at t = T/4:
# flap +60 deg, pitch +45 deg): every point of the wing lands where the
# kinematics put it (pitch about the span axis through the pivot, then flap
# about the chordwise axis), the far-field sphere stays, checkMesh passes at
# every time; the same on 2 processors split across the span gives the serial
# points. The flow (both cases, the forces' agreement) runs in
# test_tutorials.sh.

# flappingWing3DCoarse: the tutorial's case on its coarse mesh, moved by
# moveDynamicMesh to t = pi/2 in 4 steps
flappingWing3DCoarse() {
    local py tut="$top/tutorials/flappingWing3D"
    py=$(pythonWithGmsh) || fail "no python with gmsh" || return 1
    "$py" "$tut/flappingWingMesh.py" wing.msh --coarse > log.mesh 2>&1 \
        || fail "gmsh failed: $(tail -3 log.mesh)" || return 1
    cp -r "$tut/system" "$tut/constant" .
    cp -r "$tut/0.orig" 0
    run gmshToFoam wing.msh || return 1
    foamDictionary constant/polyMesh/boundary -entry entry0/wing/type -set wall > /dev/null
    foamDictionary system/controlDict -entry application -set moveDynamicMesh > /dev/null
    foamDictionary system/controlDict -entry functions -remove > /dev/null
    foamDictionary system/controlDict -entry endTime -set 1.5707963267948966 > /dev/null
    foamDictionary system/controlDict -entry deltaT -set 0.39269908169872414 > /dev/null
    foamDictionary system/controlDict -entry writeControl -set timeStep > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 2 > /dev/null
}

# wingAsFormula TIME: every point of the wing at TIME is where the rest
# point p goes by c + Rx(60 deg) Ry(45 deg) (p - c), c = (0.25 0 0)
# (1e-9 m); every far-field point is where it was (exactly)
wingAsFormula() {
    local p
    for p in wing farfield
    do
        awk -v patch=$p -f "$here/cases/patchPoints.awk" constant/polyMesh/boundary \
            constant/polyMesh/faces | sed "s/^/$p /"
    done > patch.labels
    [ "$(grep -c '^wing ' patch.labels)" -gt 500 ] || fail "only $(grep -c '^wing ' patch.labels) wing points" || return 1
    paste -d' ' <(awk '/^\(.*\)$/ && NF == 3 { gsub(/[()]/, ""); print }' constant/polyMesh/points) \
                <(awk '/^\(.*\)$/ && NF == 3 { gsub(/[()]/, ""); print }' "$1/polyMesh/points") \
        | awk 'NR == FNR { on[$2 + 1] = $1; next }
        function abs(v) { return v < 0 ? -v : v }
        (FNR in on) {
            pi = atan2(0, -1); f = pi/3; q = pi/4
            u = $1 - 0.25; v = $2; w = $3
            # pitch about y: x -> (cos, 0, -sin); then flap about x: y -> (0, cos, sin)
            pu = u*cos(q) + w*sin(q); pv = v; pw = -u*sin(q) + w*cos(q)
            ex = 0.25 + pu; ey = pv*cos(f) - pw*sin(f); ez = pv*sin(f) + pw*cos(f)
            if (on[FNR] == "farfield") { ex = $1; ey = $2; ez = $3 }
            err = abs($4 - ex) + abs($5 - ey) + abs($6 - ez)
            if (err > worst[on[FNR]]) worst[on[FNR]] = err
            n[on[FNR]]++
        }
        END {
            printf "%d wing points, largest error %g m; %d far-field points, largest move %g m\n",
                n["wing"], worst["wing"], n["farfield"], worst["farfield"]
            exit !(worst["wing"] <= 1e-9 && worst["farfield"] == 0 && n["wing"] > 500)
        }' patch.labels - || fail "the wing or the far field is not where the kinematics put it"
}

test_flappingWing3D_kinematics_meshValidWingAsFormula() {
    flappingWing3DCoarse || return 1
    run moveDynamicMesh || return 1
    reportsSetUp WendlandC2 3D
    grep -q "rotationInterpolation, 1 body" log.moveDynamicMesh || fail "no rotationInterpolation set-up line" || return 1
    meshOkAtEveryTime || return 1
    wingAsFormula 1.570796
}

# The same motion on 2 processors (the tutorial's decomposition, split in y
# across the span, through the wing) gives the serial points
test_flappingWing3D_parallelEqualsSerial() {
    flappingWing3DCoarse || return 1
    parallelEqualsSerial 1.570796 'method hierarchical; coeffs { n (1 2 1); order xyz; }'
}
