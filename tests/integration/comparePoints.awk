# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
# awk -f comparePoints.awk A/points B/points
# Largest difference between two ascii OpenFOAM point lists, relative to the
# bounding-box diagonal of A. Prints "maxDiff relDiff nPoints"; exits 1 if
# the lists differ in length.
function parse(line, v) {
    gsub(/[()]/, " ", line)
    return split(line, v, " ")
}
FNR == 1 { file++; n[file] = 0 }
/^\(-?[0-9.eE+-]+ -?[0-9.eE+-]+ -?[0-9.eE+-]+\)$/ {
    k = ++n[file]
    parse($0, v)
    for (d = 1; d <= 3; d++) p[file, k, d] = v[d]
}
END {
    if (n[1] != n[2] || n[1] == 0) { print "point counts differ:", n[1], n[2]; exit 1 }
    for (d = 1; d <= 3; d++) { lo[d] = 1e300; hi[d] = -1e300 }
    maxd = 0
    for (k = 1; k <= n[1]; k++) {
        s = 0
        for (d = 1; d <= 3; d++) {
            x = p[1, k, d]; y = p[2, k, d]
            if (x < lo[d]) lo[d] = x
            if (x > hi[d]) hi[d] = x
            s += (x - y)^2
        }
        if (sqrt(s) > maxd) maxd = sqrt(s)
    }
    diag = 0
    for (d = 1; d <= 3; d++) diag += (hi[d] - lo[d])^2
    printf "%.3e %.3e %d\n", maxd, maxd/sqrt(diag), n[1]
}
