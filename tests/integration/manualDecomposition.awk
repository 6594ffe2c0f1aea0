# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# awk -v moving="wing" -v static="inlet outlet topAndBottom" -v cut=0.5 \
#     -f manualDecomposition.awk constant/polyMesh/{boundary,points,faces,owner,neighbour} \
#     > constant/cellDecomposition
#
# A two-processor `manual` decomposition (a labelList for decomposePar's
# manualCoeffs { dataFile "cellDecomposition"; }) made to create the points
# that a processor holds on a moving or static patch without holding any of
# that patch's faces there:
#   - the cut: cells whose centre has x > cut go to processor 1, the others
#     to 0 (the plane x = cut should go through a moving and a static patch);
#   - then every cell that touches a moving patch by a vertex or an edge
#     only (no moving face), or a static patch likewise and has no moving
#     face, goes to the other processor.
# So each such cell holds patch points whose patch faces are all on the
# other processor.
#
# Writes the labelList to stdout; to stderr (one line):
#   cells N proc1 N1 movingDanger M staticDanger S mixedDanger X
# where M (S) counts (processor, point) pairs: a moving (static) patch point
# used by a cell of that processor and by none of its faces on a moving
# (static) patch owned by that processor; X: a point on both a moving and a
# static patch where that processor holds only static faces. Exits 1 if the mesh files do not
# parse.
#
# With -v bendPatch=wing -v bend="A X0 S" -v dir=constant/boundaryData/wing,
# also writes, for a timeVaryingMappedFixedValue (mapMethod nearest) point
# displacement of that patch, dir/points (the patch points) and
# dir/0/pointDisplacement (zero), dir/1/pointDisplacement: the non-rigid
#   d = (0, A (x - X0)^2 + S y, S z)      (S z only with -v threeD=1)
# i.e. a bending plus a stretch (2D: z is the extrusion direction).
#
# Needs ascii polyMesh files.

BEGIN {
    nm = split(moving, tmp, " "); for (i = 1; i <= nm; i++) role[tmp[i]] = "m"
    ns = split(static, tmp, " "); for (i = 1; i <= ns; i++) role[tmp[i]] = "s"
    if (cut == "") cut = 0
}

FNR == 1 {
    file = FILENAME; sub(/.*\//, "", file)
    inList = 0; count = -1; idx = 0; depth = 0
}

# --- boundary: patch name -> role, start, size
file == "boundary" {
    line = $0; gsub(/^[ \t]+|[ \t;]+$/, "", line)
    if (line == "(" || line == "{") { depth++; next }
    if (line == ")" || line == "}") { depth--; next }
    if (depth == 1 && line ~ /^[A-Za-z_][A-Za-z0-9_.:-]*$/) { patch = line; next }
    if (depth == 2 && $1 == "nFaces") { val = $2; sub(/;/, "", val); pn[patch] = val + 0 }
    if (depth == 2 && $1 == "startFace") { val = $2; sub(/;/, "", val); ps[patch] = val + 0 }
    next
}

# --- list files: count, "(", entries, ")"
!inList && count < 0 && /^[0-9]+[ \t]*$/ { count = $1 + 0; next }
!inList && count >= 0 && /^\($/ { inList = 1; next }
inList && /^\)$/ { inList = 0; n[file] = idx; next }
!inList { next }

file == "points" {
    line = $0; gsub(/[()]/, " ", line); split(line, v, " ")
    px[idx] = v[1]; py[idx] = v[2]; pz[idx] = v[3]; idx++
    next
}
file == "faces" {
    line = $0; k = index(line, "(")
    fn[idx] = substr(line, 1, k - 1) + 0
    line = substr(line, k + 1); gsub(/\)/, "", line)
    split(line, v, " ")
    for (j = 1; j <= fn[idx]; j++) fp[idx, j] = v[j]
    idx++
    next
}
file == "owner" { own[idx++] = $1 + 0; next }
file == "neighbour" { nei[idx++] = $1 + 0; next }

END {
    nFaces = n["faces"]; nInternal = n["neighbour"]; nPoints = n["points"]
    if (!nFaces || n["owner"] != nFaces || !nPoints) {
        print "manualDecomposition.awk: cannot parse the mesh (faces " nFaces \
            ", owner " n["owner"] ", points " nPoints ")" > "/dev/stderr"
        exit 1
    }
    # (the last cell may own no face: a gmsh mesh's)
    nCells = 0
    for (f = 0; f < nFaces; f++) if (own[f] + 1 > nCells) nCells = own[f] + 1
    for (f = 0; f < nInternal; f++) if (nei[f] + 1 > nCells) nCells = nei[f] + 1

    # patch faces: their points and their owner cells, per role
    for (p in pn) {
        r = role[p]
        if (r == "") continue
        for (f = ps[p]; f < ps[p] + pn[p]; f++) {
            faceRole[f] = r
            hasFace[r, own[f]] = 1
            for (j = 1; j <= fn[f]; j++) onPatch[r, fp[f, j]] = 1
        }
    }

    # cell -> points, cell centres (mean of the points)
    for (f = 0; f < nFaces; f++) {
        for (j = 1; j <= fn[f]; j++) {
            pt = fp[f, j]
            addCellPoint(own[f], pt)
            if (f < nInternal) addCellPoint(nei[f], pt)
        }
    }

    # the cut, then cells touching a patch without a face on it flip
    nProc1 = 0
    for (c = 0; c < nCells; c++) {
        proc[c] = (sx[c]/cn[c] > cut) ? 1 : 0
        flip = 0
        for (j = 1; j <= cn[c]; j++) {
            pt = cpt[c, j]
            if ((onPatch["m", pt] && !hasFace["m", c]) \
             || (onPatch["s", pt] && !hasFace["s", c] && !hasFace["m", c])) flip = 1
        }
        if (flip) proc[c] = 1 - proc[c]
        nProc1 += proc[c]
    }

    # dangerous (processor, point) pairs
    for (c = 0; c < nCells; c++)
        for (j = 1; j <= cn[c]; j++) held[proc[c], cpt[c, j]] = 1
    for (f = 0; f < nFaces; f++) {
        r = faceRole[f]
        if (r == "") continue
        for (j = 1; j <= fn[f]; j++) heldByFace[r, proc[own[f]], fp[f, j]] = 1
    }
    for (k in held) {
        split(k, v, SUBSEP)
        if (onPatch["m", v[2]] && !heldByFace["m", v[1], v[2]]) danger["m"]++
        if (onPatch["s", v[2]] && !heldByFace["s", v[1], v[2]]) danger["s"]++
        if (onPatch["m", v[2]] && onPatch["s", v[2]] \
         && heldByFace["s", v[1], v[2]] && !heldByFace["m", v[1], v[2]]) danger["x"]++
    }

    print "FoamFile { version 2.0; format ascii; class labelList; object cellDecomposition; }"
    print nCells
    print "("
    for (c = 0; c < nCells; c++) print proc[c]
    print ")"
    if (bendPatch != "") writeBend()
    printf "cells %d proc1 %d movingDanger %d staticDanger %d mixedDanger %d\n", \
        nCells, nProc1, danger["m"] + 0, danger["s"] + 0, danger["x"] + 0 > "/dev/stderr"
}

function writeBend(   b, f, j, pt, np, list) {
    split(bend, b, " ")
    for (f = ps[bendPatch]; f < ps[bendPatch] + pn[bendPatch]; f++)
        for (j = 1; j <= fn[f]; j++) {
            pt = fp[f, j]
            if (pt in inBend) continue
            inBend[pt] = 1; list[np++] = pt
        }
    system("mkdir -p " dir "/0 " dir "/1")
    print np > (dir "/points"); print "(" > (dir "/points")
    print np > (dir "/0/pointDisplacement"); print "(" > (dir "/0/pointDisplacement")
    print np > (dir "/1/pointDisplacement"); print "(" > (dir "/1/pointDisplacement")
    for (j = 0; j < np; j++) {
        pt = list[j]
        printf "(%.17g %.17g %.17g)\n", px[pt], py[pt], pz[pt] > (dir "/points")
        print "(0 0 0)" > (dir "/0/pointDisplacement")
        printf "(0 %.17g %.17g)\n", b[1]*(px[pt] - b[2])^2 + b[3]*py[pt], \
            (threeD ? b[3]*pz[pt] : 0) > (dir "/1/pointDisplacement")
    }
    print ")" > (dir "/points"); print ")" > (dir "/0/pointDisplacement")
    print ")" > (dir "/1/pointDisplacement")
}

function addCellPoint(c, pt) {
    if ((c, pt) in seen) return
    seen[c, pt] = 1
    cpt[c, ++cn[c]] = pt
    sx[c] += px[pt]
}
