# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration test: the wing3D tutorial shortened (coarse mesh, 5 steps to
# the full bending and twist at t = 0.25): moveDynamicMesh with
# wingBendingTwistDisplacement and dcpRBF, checkMesh passes at the written
# time, and the tip's leading-edge point is where the formula puts it; the
# same on 2 processors gives the serial points.

# pointsFile FILE: the points of a polyMesh/points file, "x y z" a line
pointsFile() {
    awk '/^\(.*\)$/ && NF == 3 { gsub(/[()]/, ""); print }' "$1"
}

# wing3DCoarse: the tutorial's case on its coarse mesh, to t = 0.25 in 5 steps
wing3DCoarse() {
    local py tut="$top/tutorials/wing3D"
    py=$(pythonWithGmsh) || fail "no python with gmsh" || return 1
    "$py" "$tut/wingMesh.py" wing.msh --coarse > log.mesh 2>&1 || fail "gmsh failed: $(tail -3 log.mesh)" || return 1
    cp -r "$tut/system" "$tut/constant" .
    rm -rf constant/polyMesh
    cp -r "$tut/0.orig" 0
    run gmshToFoam wing.msh || return 1
    foamDictionary constant/polyMesh/boundary -entry entry0/symmetry/type -set symmetryPlane > /dev/null
    foamDictionary constant/polyMesh/boundary -entry entry0/wing/type -set wall > /dev/null
    foamDictionary system/controlDict -entry endTime -set 0.25 > /dev/null
    foamDictionary system/controlDict -entry deltaT -set 0.05 > /dev/null
}

test_wing3D_bendTwist_meshValidTipAsFormula() {
    wing3DCoarse || return 1
    run moveDynamicMesh || return 1
    reportsSetUp WendlandC2 3D
    meshOkAtEveryTime || return 1
    [ -f 0.25/polyMesh/points ] || fail "no points at t = 0.25" || return 1

    # The tip's leading-edge point (0.690684 1.1963 0) at t = 0.25: tip
    # deflection 0.15 m, twist 6 deg nose-up about the quarter-chord point
    # (0.803934 1.1963 0): d = (r (cos - 1), 0, 0.15 - r sin), r = x - 0.803934
    paste -d' ' <(pointsFile constant/polyMesh/points) <(pointsFile 0.25/polyMesh/points) | awk '
        function abs(v) { return v < 0 ? -v : v }
        abs($1 - 0.690684) < 1e-5 && abs($2 - 1.1963) < 1e-6 && abs($3) < 1e-9 {
            n++
            th = 6*atan2(0, -1)/180; r = $1 - 0.803934
            ex = r*(cos(th) - 1); ez = 0.15 - r*sin(th)
            err = abs($4 - $1 - ex) + abs($5 - $2) + abs($6 - $3 - ez)
            printf "tip LE point moved (%g %g %g), formula (%g 0 %g), error %g\n", $4 - $1, $5 - $2, $6 - $3, ex, ez, err
            if (err > 1e-6) bad = 1
        }
        END { if (n != 1) { print "found " n " tip LE points"; exit 1 } exit bad }' \
        || fail "tip not where the formula puts it"
}

# The same motion on 2 processors (the tutorial's hierarchical decomposition,
# split in x through the wing) gives the serial points (parallelEqualsSerial,
# test_parallel.sh: 1e-10 of the domain size); decomposePar keeps the wing's
# wingBendingTwistDisplacement condition
test_wing3D_parallelEqualsSerial() {
    wing3DCoarse || return 1
    parallelEqualsSerial 0.25 'method hierarchical; coeffs { n (2 1 1); order xyz; }' || return 1
    local p
    for p in 0 1
    do
        grep -q wingBendingTwistDisplacement "par/processor$p/0/pointDisplacement" \
            || fail "decomposePar lost wingBendingTwistDisplacement (processor$p)"
    done
}
