# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# awk -f comparePatchPoints.awk LABELS REF/points A/points B/points
# Compares the points whose labels are listed in LABELS (one a line, e.g. from
# patchPoints.awk) between two ascii OpenFOAM point lists A and B; REF (the
# reference mesh) gives the displacements and the domain size.
# Prints "maxDiff relDiff maxDispA maxDispB nPoints" (relDiff: relative to
# REF's bounding-box diagonal); exits 1 if the lists differ in length.
FNR == 1 { file++; n[file] = 0 }
file == 1 { if ($1 ~ /^[0-9]+$/) label[$1 + 1] = 1; next }
/^\(-?[0-9.eE+-]+ -?[0-9.eE+-]+ -?[0-9.eE+-]+\)$/ {
    k = ++n[file]
    line = $0
    gsub(/[()]/, " ", line)
    split(line, v, " ")
    for (d = 1; d <= 3; d++) p[file, k, d] = v[d]
}
function dist(f, g, k,    d, s) {
    s = 0
    for (d = 1; d <= 3; d++) s += (p[f, k, d] - p[g, k, d])^2
    return sqrt(s)
}
END {
    if (n[2] != n[3] || n[2] != n[4] || n[2] == 0) {
        print "point counts differ:", n[2], n[3], n[4]; exit 1
    }
    for (d = 1; d <= 3; d++) { lo[d] = 1e300; hi[d] = -1e300 }
    for (k = 1; k <= n[2]; k++)
        for (d = 1; d <= 3; d++) {
            if (p[2, k, d] < lo[d]) lo[d] = p[2, k, d]
            if (p[2, k, d] > hi[d]) hi[d] = p[2, k, d]
        }
    diag = 0
    for (d = 1; d <= 3; d++) diag += (hi[d] - lo[d])^2
    diag = sqrt(diag)
    maxd = 0; maxa = 0; maxb = 0; m = 0
    for (kk in label) {
        k = kk + 0
        if (k > n[2]) { print "label", k - 1, "out of range"; exit 1 }
        m++
        if (dist(3, 4, k) > maxd) maxd = dist(3, 4, k)
        if (dist(3, 2, k) > maxa) maxa = dist(3, 2, k)
        if (dist(4, 2, k) > maxb) maxb = dist(4, 2, k)
    }
    if (m == 0) { print "no labels"; exit 1 }
    printf "%.3e %.3e %.6g %.6g %d\n", maxd, maxd/diag, maxa, maxb, m
}
