# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# Helpers for tests/integration/run (sourced).
nPassed=0
nFailed=0
failures=()

# runTest NAME FUNCTION: run FUNCTION in a fresh case folder, record the result
runTest() {
    local name="$1" fn="$2" case="$work/$1" start=$SECONDS out
    mkdir -p "$case"
    if out=$(cd "$case" && "$fn" 2>&1)
    then
        nPassed=$((nPassed + 1))
        printf 'PASS  %-40s (%ds)\n' "$name" $((SECONDS - start))
    else
        nFailed=$((nFailed + 1))
        failures+=("$name")
        printf 'FAIL  %-40s (%ds)\n' "$name" $((SECONDS - start))
        printf '%s\n' "$out" | tail -n 15 | sed 's/^/      | /'
        echo "      | case kept in $case"
    fi
}

# fail MESSAGE: print and return 1
fail() { echo "$*"; return 1; }

# warningText START LINES WHY: the warning of log.moveDynamicMesh starting
# with START (and its next LINES lines) on one line in the file warning;
# fails with WHY when there is none
warningText() {
    grep -A"$2" "$1" log.moveDynamicMesh | tr '\n' ' ' > warning
    [ -s warning ] || fail "$3"
}

# pointsAgree A B MAXREL WHAT: the largest difference between the point
# files A and B (comparePoints.awk: relative to A's bounding-box diagonal) is
# at most MAXREL; prints it
pointsAgree() {
    local diff
    diff=$(awk -f "$here/comparePoints.awk" "$1" "$2") || fail "$diff" || return 1
    echo "$4: max difference, relative, points: $diff"
    awk -v r="$(echo "$diff" | cut -d' ' -f2)" -v m="$3" 'BEGIN { exit !(r <= m) }' \
        || fail "$4 differ: $diff"
}

# run APP ARGS...: run an OpenFOAM application, log to log.APP[.n]
run() {
    local log="log.$1"
    [ -f "$log" ] && log="$log.$(ls log.$1* | wc -l)"
    "$@" > "$log" 2>&1 || fail "$* failed: see $(pwd)/$log" || return 1
}

# writeFile PATH CLASS <<body: a dictionary with a FoamFile header
writeFile() {
    mkdir -p "$(dirname "$1")"
    {
        printf 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n' "$2" "$(basename "$1")"
        cat
    } > "$1"
}

# meshOkAtEveryTime: checkMesh passes at every written time after 0
meshOkAtEveryTime() {
    local nTimes
    run checkMesh -noZero -noTopology || return 1
    nTimes=$(ls -d [0-9]* | grep -v '^0$' | wc -l)
    [ "$nTimes" -gt 0 ] || fail "no time written"
    local nOk
    nOk=$(grep -c '^Mesh OK' log.checkMesh)
    [ "$nOk" -eq "$nTimes" ] || fail "checkMesh: $nOk of $nTimes times OK: $(grep -m3 'Failed\|\*\*\*' log.checkMesh)"
}

# pythonWithGmsh: a python that imports gmsh
pythonWithGmsh() {
    local py
    for py in /usr/bin/python3 python3
    do
        "$py" -c "import gmsh" 2>/dev/null && { echo "$py"; return 0; }
    done
    return 1
}

# airfoilMesh SIZE_WING SIZE_FAR: the tutorial's NACA0012 mesh, patch types set
airfoilMesh() {
    local py
    py=$(pythonWithGmsh) || fail "no python with gmsh" || return 1
    "$py" "$top/tutorials/pitchingAirfoil2D/naca0012Mesh.py" airfoil.msh \
        --size-wing "$1" --size-far "$2" > log.mesh 2>&1 || fail "gmsh failed" || return 1
    run gmshToFoam airfoil.msh || return 1
    foamDictionary constant/polyMesh/boundary -entry entry0/frontAndBack/type -set empty > /dev/null
    foamDictionary constant/polyMesh/boundary -entry entry0/wing/type -set wall > /dev/null
}
