# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# shellcheck shell=bash disable=SC2154 # here, top, work: set by tests/integration/run
# Integration tests: parallel runs on `manual` decompositions built to give a
# processor points of a moving (static) patch without any face of that patch
# there: cells that touch the patch only at a vertex or an edge go to the
# other processor (manualDecomposition.awk). Such a point must still get the
# prescribed (zero) displacement, or the processors disagree about it
# (issue 7, item 3: "face area does not match neighbour").

manualDecompositionDict='method manual; manualCoeffs { dataFile "cellDecomposition"; }'

# manualDecomposition CUT MOVING STATIC NEED [AWK ARGS...]: write
# constant/cellDecomposition (cut at x = CUT, see manualDecomposition.awk);
# fail unless it creates dangerous points of each kind in NEED ("moving",
# "static", "mixed": see manualDecomposition.awk)
manualDecomposition() {
    local cut="$1" moving="$2" static="$3" need="$4" counts kind n
    shift 4
    counts=$(awk -v cut="$cut" -v moving="$moving" -v static="$static" "$@" \
        -f "$here/manualDecomposition.awk" \
        constant/polyMesh/boundary constant/polyMesh/points constant/polyMesh/faces \
        constant/polyMesh/owner constant/polyMesh/neighbour \
        2>&1 > constant/cellDecomposition) || fail "$counts" || return 1
    echo "manual decomposition: $counts"
    for kind in $need
    do
        n=$(echo "$counts" | awk -v k="${kind}Danger" '{ for (i = 1; i < NF; i++) if ($i == k) print $(i + 1) }')
        [ "${n:-0}" -gt 0 ] || fail "the decomposition creates no $kind-patch point without its faces: $counts" || return 1
    done
}

# cubeVertex I J K: the label of vertex (I, J, K) of write_cubeIn26Blocks
cubeVertex() { echo $(($1 + 4*$2 + 16*$3)); }

# write_cubeIn26Blocks N [lid]: the hollow cube's geometry (body: half side 0.5,
# outer: half side 2) meshed as 3x3x3 blocks of N^3 cells minus the centre
# one: unlike write_hollowCube's six blocks (an O-grid: every cell that
# touches the body has a face on it), the diagonal blocks put cells on the
# body's edges and corners that touch it by an edge or a vertex only. With
# "lid", the body's top face (z = 0.5) is a patch of its own, "lid".
write_cubeIn26Blocks() {
    local n="$1" i j k c=(-2 -0.5 0.5 2) top
    write_motionControls .
    top="($(cubeVertex 1 1 2) $(cubeVertex 2 1 2) $(cubeVertex 2 2 2) $(cubeVertex 1 2 2))"
    {
        echo "FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }"
        echo "vertices ("
        for k in 0 1 2 3; do for j in 0 1 2 3; do for i in 0 1 2 3
        do
            echo "(${c[i]} ${c[j]} ${c[k]})"
        done; done; done
        echo "); blocks ("
        for k in 0 1 2; do for j in 0 1 2; do for i in 0 1 2
        do
            [ "$i$j$k" = 111 ] && continue
            echo "hex ($(cubeVertex $i $j $k) $(cubeVertex $((i+1)) $j $k) $(cubeVertex $((i+1)) $((j+1)) $k) $(cubeVertex $i $((j+1)) $k)" \
                "$(cubeVertex $i $j $((k+1))) $(cubeVertex $((i+1)) $j $((k+1))) $(cubeVertex $((i+1)) $((j+1)) $((k+1))) $(cubeVertex $i $((j+1)) $((k+1))))" \
                "($n $n $n) simpleGrading (1 1 1)"
        done; done; done
        echo "); boundary ( body { type wall; faces ("
        # the faces of the centre block, pointing into it (out of the domain)
        echo "($(cubeVertex 1 1 1) $(cubeVertex 1 2 1) $(cubeVertex 2 2 1) $(cubeVertex 2 1 1))"
        [ "$2" = lid ] || echo "$top"
        echo "($(cubeVertex 1 1 1) $(cubeVertex 2 1 1) $(cubeVertex 2 1 2) $(cubeVertex 1 1 2))  ($(cubeVertex 1 2 1) $(cubeVertex 1 2 2) $(cubeVertex 2 2 2) $(cubeVertex 2 2 1))"
        echo "($(cubeVertex 1 1 1) $(cubeVertex 1 1 2) $(cubeVertex 1 2 2) $(cubeVertex 1 2 1))  ($(cubeVertex 2 1 1) $(cubeVertex 2 2 1) $(cubeVertex 2 2 2) $(cubeVertex 2 1 2))"
        echo "); }"
        [ "$2" = lid ] && echo "lid { type wall; faces ($top); }"
        echo ");"
        echo "defaultPatch { name outer; type patch; }"
    } > system/blockMeshDict
}

# everySelectionParallelEqualsSerial TIME COEFFS [correctionMoves]: for each selection (all,
# greedy and dynamic with tolerance 1e-2, and greedy with tolerance 0.3,
# "greedyCoarse") and boundaryCorrection true and false, in its own folder:
# dcpRBFCoeffs COEFFS, serial and manual-parallel moveDynamicMesh, the
# reconstructed points equal the serial ones, checkMesh passes on the
# reconstructed mesh. Tries every combination, then fails if any failed.
# With correctionMoves (a motion the polynomial does not reproduce): the
# coarse set leaves boundary errors that the correction blends into the
# volume, across the cuts (each processor fetching the errors its points
# need from the others): its points must differ from those without it.
everySelectionParallelEqualsSerial() {
    local time="$1" coeffs="$2" spec selection correction dir failed=() out diff
    for spec in "all|selection all;" "greedy|selection greedy; tolerance 1e-2;" \
        "dynamic|selection dynamic; tolerance 1e-2;" "greedyCoarse|selection greedy; tolerance 0.3;"
    do
        selection="${spec#*|}"
        for correction in true false
        do
            dir="${spec%%|*}_boundaryCorrection_$correction"
            mkdir -p "$dir"
            cp -r constant system 0 "$dir/"
            if out=$(
                cd "$dir" || exit 1
                dynamicMeshDict "$coeffs boundaryCorrection $correction; controlPoints { $selection }"
                parallelEqualsSerial "$time" "$manualDecompositionDict" || exit 1
                cd par || exit 1
                run checkMesh -time "$time" -noTopology || exit 1
                grep -q '^Mesh OK' log.checkMesh || fail "checkMesh of the reconstructed mesh failed"
            )
            then
                echo "ok   $dir: ${out##*points: }"
            else
                failed+=("$dir")
                echo "FAIL $dir: $(echo "$out" | tail -n 1)"
                # the first fatal error's message
                grep -h -m1 -A1 'FOAM FATAL' "$dir"/log.* "$dir"/par/log.* 2>/dev/null \
                    | sed -n 2p | cut -c1-160 | sed 's/^/       /'
            fi
        done
    done
    [ ${#failed[@]} -eq 0 ] || fail "${#failed[@]} of 8 runs failed: ${failed[*]}"
    [ "${3:-}" = correctionMoves ] || return 0
    diff=$(awk -f "$here/comparePoints.awk" "greedyCoarse_boundaryCorrection_true/$time/polyMesh/points" \
        "greedyCoarse_boundaryCorrection_false/$time/polyMesh/points") || fail "$diff"
    echo "greedyCoarse: the correction's effect, max relative, points: $diff"
    awk -v r="$(echo "$diff" | cut -d' ' -f2)" 'BEGIN { exit !(r > 1e-6) }' \
        || fail "the boundary correction moved no point of the coarse set: $diff"
}

# bendingWingCase: the airfoil, its wing bent and stretched (non-rigid)
# through a timeVaryingMappedFixedValue point condition, to t = 0.5, with a
# manual decomposition cutting through the wing (chord 0..1) and topAndBottom
bendingWingCase() {
    write_motionControls .
    airfoilMesh 0.04 1.0 || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    manualDecomposition 0.5 "wing" "inlet outlet topAndBottom" "moving static" \
        -v bendPatch=wing -v bend="0.3 0.25 0.2" -v dir=constant/boundaryData/wing || return 1
    writeFile 0/pointDisplacement pointVectorField <<'EOT'
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    wing { type timeVaryingMappedFixedValue; mapMethod nearest; value uniform (0 0 0); }
    "(inlet|outlet|topAndBottom)" { type fixedValue; value uniform (0 0 0); }
    frontAndBack { type empty; }
}
EOT
}

test_parallelManual_airfoil2D_bendingWing_equalsSerial() {
    bendingWingCase || return 1
    everySelectionParallelEqualsSerial 0.5 \
        "movingPatches (wing); staticPatches (inlet outlet topAndBottom); supportRadius 2.5;" \
        correctionMoves
}

# bentBodyPointDisplacement STATIC: the body follows the mapped bending
# (constant/boundaryData/body, written by manualDecomposition); STATIC
# (a patch name or regex) stays put
bentBodyPointDisplacement() {
    writeFile 0/pointDisplacement pointVectorField <<EOT
dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    body { type timeVaryingMappedFixedValue; mapMethod nearest; value uniform (0 0 0); }
    $1 { type fixedValue; value uniform (0 0 0); }
}
EOT
}

# the hollow cube (26 blocks), its body bent and stretched (non-rigid)
test_parallelManual_cube3D_bendingBody_equalsSerial() {
    write_cubeIn26Blocks 4
    run blockMesh || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    # cut through the body and the outer box
    manualDecomposition 0.1 "body" "outer" "moving" \
        -v bendPatch=body -v bend="0.3 0 0.2" -v threeD=1 -v dir=constant/boundaryData/body || return 1
    bentBodyPointDisplacement outer
    everySelectionParallelEqualsSerial 0.5 "movingPatches (body); staticPatches (outer); supportRadius 1.5;"
}

# the hollow cube (26 blocks) with the roles swapped: the outer box rotates,
# the body is static, so the edge and corner cells hold static points
# without faces
test_parallelManual_cube3D_staticBody_equalsSerial() {
    write_cubeIn26Blocks 4
    run blockMesh || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    manualDecomposition 0.1 "outer" "body" "static" || return 1
    pitchingPointDisplacement outer "(1 1 1)" "(0 0 0)" 0.15 body ""
    everySelectionParallelEqualsSerial 0.5 "movingPatches (outer); staticPatches (body); supportRadius 3;" \
        correctionMoves
}

# the hollow cube (26 blocks) whose top face is a static patch "lid": the
# lid's edge points move (moving wins); a processor that holds them only
# through lid faces must move them too
test_parallelManual_cube3D_staticLid_equalsSerial() {
    write_cubeIn26Blocks 4 lid
    run blockMesh || return 1
    foamDictionary system/controlDict -entry endTime -set 0.5 > /dev/null
    manualDecomposition 0.1 "body" "outer lid" "moving mixed" \
        -v bendPatch=body -v bend="0.3 0 0.2" -v threeD=1 -v dir=constant/boundaryData/body || return 1
    bentBodyPointDisplacement '"(outer|lid)"'
    everySelectionParallelEqualsSerial 0.5 "movingPatches (body); staticPatches (outer lid); supportRadius 1.5;"
}

# bendingWingTrialsCase: bendingWingCase in steps of 0.025 (written every
# 4th) with a fixed set of 5 points, no boundary correction and no guard:
# trials at many steps, and at the last, whose mesh folds, the rescue
bendingWingTrialsCase() {
    bendingWingCase || return 1
    foamDictionary system/controlDict -entry deltaT -set 0.025 > /dev/null
    foamDictionary system/controlDict -entry writeInterval -set 4 > /dev/null
    dynamicMeshDict "movingPatches (wing); staticPatches (inlet outlet topAndBottom);
        supportRadius 2.5; boundaryCorrection false; guardIterations 0;
        controlPoints { selection dynamic; tolerance 1e-12; minPoints 5; maxPoints 5;
            reselectTolerance 1e9; }"
}

# The error-guided rule's trials in parallel: a fixed set of 5 points without
# boundary correction on the bent wing, in steps of 0.025, so that the trials
# (judged on a window of cells spread over both processors: the worst cells
# and those around the leaving points) run at many steps, and at the last,
# whose mesh folds, the rescue (trials past an undone one). Parallel equals
# serial, and the serial run made trials at an inverted step (a row of
# dcpRBF.dat with minQuality <= 0 and nUndone >= 2)
test_parallelManual_airfoil2D_bendingWing_dcpTrials_equalsSerial() {
    bendingWingTrialsCase || return 1
    parallelEqualsSerial 0.5 "$manualDecompositionDict" || return 1
    awk '!/^#/ && $7 <= 0 && $15 >= 2 { n++ } END { exit !(n > 0) }' \
        postProcessing/dcpRBF/0/dcpRBF.dat \
        || fail "no trials at an inverted step in the serial run (dcpRBF.dat: no row with minQuality <= 0 and nUndone >= 2)" \
        || return 1
    # the log lines as the README shows them, the trials' (wait ended, undone, points) and the rescue's tags included
    grep -q ', rescue), quality min' log.moveDynamicMesh || fail "no ', rescue' in the log" || return 1
    local bad
    bad=$(awk '/^dcpRBF: control points/ && !/^dcpRBF: control points [0-9]+ \(\+[0-9]+ -[0-9]+, guard \+[0-9]+(, wait ended)?(, [0-9]+ trial swap\(s\) undone)?(, trials at [0-9]+ points)?(, rescue)?\), quality min / { print; exit }' \
        log.moveDynamicMesh)
    [ -z "$bad" ] || fail "a log line not as documented: ${bad:0:120}" || return 1
    # the trials' points counted as in serial (a point on the processors'
    # boundary once)
    local serial parallel
    serial=$(grep -o 'trials at [0-9]* points' log.moveDynamicMesh | tr '\n' ' ')
    parallel=$(grep -o 'trials at [0-9]* points' par/log.mpirun | tr '\n' ' ')
    [ -n "$serial" ] || fail "no trials at the window's points in the serial run" || return 1
    [ "$serial" = "$parallel" ] \
        || fail "trial points: serial ${serial:0:80}, parallel ${parallel:0:80}"
}
