# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Helpers for tests/integration/run (sourced).
nPassed=0
nFailed=0
failures=()

# runTest NAME FUNCTION: run FUNCTION in a fresh case folder and record the
# result. The test runs in a subshell of its own under errexit and pipefail:
# a command that fails outside a condition ends it (failed), and so does
# fail(). Its output goes to log.test in the case folder.
runTest() {
    local name="$1" fn="$2" case="$work/$1" start=$SECONDS rc
    mkdir -p "$case"
    (
        cd "$case" || exit 1
        set -eE -o pipefail
        trap 'echo "FAILED: $BASH_COMMAND (status $?, line $LINENO of ${BASH_SOURCE[0]##*/})"' ERR
        "$fn"
    ) > "$case/log.test" 2>&1
    rc=$?
    if [ "$rc" -eq 0 ]
    then
        nPassed=$((nPassed + 1))
        printf 'PASS  %-40s (%ds)\n' "$name" $((SECONDS - start))
    else
        nFailed=$((nFailed + 1))
        failures+=("$name")
        printf 'FAIL  %-40s (%ds)\n' "$name" $((SECONDS - start))
        tail -n 15 "$case/log.test" | sed 's/^/      | /'
        echo "      | case kept in $case"
    fi
}

# fail MESSAGE: print MESSAGE and end the test (its subshell) as failed,
# wherever it is called: in a helper, after ||, in a condition
fail() { echo "FAILED: $*"; exit 1; }

# reportsSetUp KERNEL DIM: the log's set-up line names KERNEL and DIM (2D or 3D)
reportsSetUp() {
    grep -q "^dcpRBF: [0-9]* boundary points ($1, supportRadius [^,]*, polynomial [a-z]*, $2, selection " log.moveDynamicMesh \
        || fail "no set-up line for $1 in $2: $(grep -m1 'boundary points' log.moveDynamicMesh)"
}

# stoppedBelowFloor TEXT: moveDynamicMesh stops with the FatalError of
# qualityFloorAction stop (not the warning of qualityFloorAction warn, which
# has the same opening), whose message has TEXT
stoppedBelowFloor() {
    ! moveDynamicMesh > log.moveDynamicMesh 2>&1 || fail "moveDynamicMesh went on below the quality floor"
    grep -A4 "FOAM FATAL ERROR" log.moveDynamicMesh | tr '\n' ' ' > fatal
    [ -s fatal ] || fail "no FatalError: $(tail -n 5 log.moveDynamicMesh)"
    grep -q "below qualityFloor .*Stopping (qualityFloorAction stop)" fatal \
        || fail "the FatalError is not the floor's: $(head -c 400 fatal)"
    grep -q -- "$1" fatal || fail "the FatalError does not say '$1': $(head -c 600 fatal)"
}

# warningText START LINES WHY [LOG]: the warning of LOG (default
# log.moveDynamicMesh) starting with START (and its next LINES lines) on one
# line in the file warning; fails with WHY when there is none
warningText() {
    grep -A"$2" "$1" "${4:-log.moveDynamicMesh}" | tr '\n' ' ' > warning
    [ -s warning ] || fail "$3"
}

# pointsAgree A B MAXREL WHAT: the largest difference between the point
# files A and B (comparePoints.awk: relative to A's bounding-box diagonal) is
# at most MAXREL; prints it
pointsAgree() {
    local diff
    diff=$(awk -f "$here/comparePoints.awk" "$1" "$2") || fail "$diff"
    echo "$4: max difference, relative, points: $diff"
    awk -v r="$(echo "$diff" | cut -d' ' -f2)" -v m="$3" 'BEGIN { exit !(r <= m) }' \
        || fail "$4 differ: $diff"
}

# asciiPoints BINARY ASCII: a points file written with writeFormat binary
# (label size 32 or 64, double precision) written as ascii points at full
# precision, for pointsAgree
asciiPoints() {
    python3 - "$1" "$2" <<'EOT' || fail "cannot read $1 as binary points"
import re, struct, sys
data = open(sys.argv[1], "rb").read()
body = data.index(b"}", data.index(b"FoamFile")) + 1
m = re.compile(rb"\s(\d+)\s*\(").search(data, body)
n, start = int(m.group(1)), m.end()
values = struct.unpack("<%dd" % (3*n), data[start:start + 24*n])
if data[start + 24*n:start + 24*n + 1] != b")":
    sys.exit("%s: not %d binary points" % (sys.argv[1], n))
with open(sys.argv[2], "w") as out:
    out.write("%d\n(\n" % n)
    for i in range(n):
        out.write("(%.17g %.17g %.17g)\n" % values[3*i:3*i + 3])
    out.write(")\n")
EOT
}

# run APP ARGS...: run an OpenFOAM application, log to log.APP[.n] (n: the
# number of its logs so far); fails the test if the application fails or
# runs longer than DCPRBF_APP_TIMEOUT seconds (default 1200: a hang, e.g.
# processors waiting on each other, ends the test, not the whole tier)
run() {
    local log="log.$1" logs rc=0 limit="${DCPRBF_APP_TIMEOUT:-1200}"
    if [ -f "$log" ]
    then
        logs=("log.$1"*)
        log="$log.${#logs[@]}"
    fi
    timeout --kill-after=10 "$limit" "$@" > "$log" 2>&1 || rc=$?
    if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]
    then
        fail "$* did not end within $limit s (DCPRBF_APP_TIMEOUT): see $(pwd)/$log"
    fi
    [ "$rc" -eq 0 ] \
        || fail "$* failed: see $(pwd)/$log$(grep -h -A4 "FOAM FATAL" "$log" | grep -v '^ *$' | head -n 6 | sed 's/^/\n    /')"
}

# countLines REGEX FILE: the number of lines of FILE matching REGEX (awk),
# 0 included (grep -c fails on 0); fails the test if FILE is missing
countLines() {
    [ -f "$2" ] || fail "no $2"
    awk -v re="$1" '$0 ~ re { n++ } END { print n + 0 }' "$2"
}

# writtenTimes DIR: the time folders of DIR other than 0, one a line
writtenTimes() {
    local d
    for d in "$1"/[0-9]*
    do
        d="${d##*/}"
        [[ "$d" =~ ^[0-9.eE+-]+$ ]] && [ "$d" != 0 ] && echo "$d"
    done
    return 0
}

# writeFile PATH CLASS <<body: a dictionary with a FoamFile header
writeFile() {
    local object
    object=$(basename "$1")
    mkdir -p "$(dirname "$1")"
    {
        printf 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n' "$2" "$object"
        cat
    } > "$1"
}

# meshOkAtEveryTime: checkMesh passes at every written time after 0
meshOkAtEveryTime() {
    local nTimes nOk
    run checkMesh -noZero -noTopology
    nTimes=$(writtenTimes . | wc -l)
    [ "$nTimes" -gt 0 ] || fail "no time written"
    nOk=$(countLines '^Mesh OK' log.checkMesh)
    [ "$nOk" -eq "$nTimes" ] || fail "checkMesh: $nOk of $nTimes times OK: $(grep -m3 'Failed\|\*\*\*' log.checkMesh)"
}

# invertedWhereCheckMeshFails [any]: at every written time, dcpRBF's step
# row (dcpRBF.dat, column nInverted) reports inverted cells exactly where
# checkMesh finds the mesh invalid, and it does somewhere (any: or nowhere)
invertedWhereCheckMeshFails() {
    local t nBad=0 inverted ok
    run checkMesh -noZero -noTopology
    for t in $(writtenTimes .)
    do
        inverted=$(awk -v t="$t" '!/^#/ && $1 == t { print $17 }' postProcessing/dcpRBF/0/dcpRBF.dat)
        [ -n "$inverted" ] || fail "no dcpRBF.dat row at t = $t"
        # checkMesh's verdict at t: the line after "Time = t" up to the next
        ok=$(awk -v t="$t" '/^Time = / { cur = ($3 == t) } cur && /^Mesh OK/ { print "ok" }' log.checkMesh)
        if [ "$ok" = ok ]
        then
            [ "$inverted" -eq 0 ] || fail "t = $t: dcpRBF reports $inverted inverted cells, checkMesh none"
        else
            [ "$inverted" -gt 0 ] || fail "t = $t: checkMesh fails, dcpRBF reports no inverted cell"
            nBad=$((nBad + 1))
        fi
    done
    [ "$nBad" -gt 0 ] || [ "${1:-}" = any ] || fail "checkMesh never fails: the case does not test the check"
    echo "inverted cells reported at the $nBad times checkMesh fails, at no other"
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
