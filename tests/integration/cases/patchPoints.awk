# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# awk -v patch=NAME -f patchPoints.awk constant/polyMesh/boundary constant/polyMesh/faces
# The point labels of patch NAME (its meshPoints, sorted), one a line, from an
# ascii polyMesh. Exits 1 if the patch is not found or has no faces.
FNR == 1 { file++ }
file == 1 && $1 == patch { inPatch = 1; next }
file == 1 && inPatch && $1 == "nFaces" { nFaces = $2 + 0 }
file == 1 && inPatch && $1 == "startFace" { startFace = $2 + 0 }
file == 1 && inPatch && $1 == "}" { inPatch = 0; found = 1 }
# faces: after the count line and "(", one face a line: "4(a b c d)"
file == 2 && !started && /^\($/ { started = 1; facei = 0; next }
file == 2 && started && /^[0-9]+\(/ {
    if (facei >= startFace && facei < startFace + nFaces) {
        line = $0
        sub(/^[0-9]+\(/, "", line)
        sub(/\).*$/, "", line)
        n = split(line, v, " ")
        for (i = 1; i <= n; i++) onPatch[v[i] + 0] = 1
    }
    facei++
}
END {
    if (!found || nFaces == 0) { print "patch " patch " not found or empty" > "/dev/stderr"; exit 1 }
    for (p in onPatch) print p | "sort -n"
}
