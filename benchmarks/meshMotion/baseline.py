# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The mesh-motion benchmark's dense baseline (see run): denseBaseline
(denseBaseline.cpp, built with CMake in build/meshMotion) on a case's mesh
points and the control points of its last step, and the core's
StoredEvaluation on the same data."""
import os, re, subprocess, sys

from cases import BUILD, HERE


def build():
    """denseBaseline built in BUILD (CMake, Release)."""
    subprocess.check_call(["cmake", "-S", HERE, "-B", BUILD, "-DCMAKE_BUILD_TYPE=Release"],
                          stdout=subprocess.DEVNULL)
    subprocess.check_call(["cmake", "--build", BUILD, "-j", "2"], stdout=subprocess.DEVNULL)


def read_foam_points(path):
    raw = open(path, "rb").read()
    hdr = raw[:raw.index(b"}")].decode()
    if re.search(r"format\s+binary", hdr):
        import array
        i = raw.index(b"(", len(hdr))
        n = int(raw[len(hdr) + 1:i].split()[-1])
        v = array.array("d")
        v.frombytes(raw[i + 1:i + 1 + 24*n])
        if sys.byteorder != "little":
            v.byteswap()
        return [("%.17g" % v[3*j], "%.17g" % v[3*j + 1], "%.17g" % v[3*j + 2]) for j in range(n)]
    txt = raw.decode()
    i = txt.index("(", txt.index("}"))
    n = int(txt[:i].split()[-1])
    nums = re.findall(r"\(([^()]*)\)", txt[i + 1:])[:n]
    return [s.split() for s in nums]


def read_vtk_points(path):
    lines = open(path).read().split("\n")
    for k, l in enumerate(lines):
        if l.startswith("POINTS"):
            n = int(l.split()[1])
            vals = " ".join(lines[k + 1:k + 1 + n + 2]).split()[:3*n]
            return [vals[3*j:3*j + 3] for j in range(n)]
    raise RuntimeError("no POINTS in " + path)


def write_pts(path, pts):
    with open(path, "w") as f:
        f.write("%d\n" % len(pts))
        for p in pts:
            f.write(" ".join(p) + "\n")


def baseline(o, m, dyn_case, nResample=0):
    """denseBaseline on the mesh points of dyn_case and its last control points
    (mesh m; nResample: the points resampled to that many), its record."""
    spec = o.specs[m]
    exe = os.path.join(BUILD, "denseBaseline")
    vtk = [f for f in os.listdir(os.path.join(dyn_case, "postProcessing", "dcpRBF"))
           if f.startswith("controlPoints_") and f.endswith(".vtk")]
    vtk = max(vtk, key=lambda f: float(f[len("controlPoints_"):-4]))
    pts = os.path.join(o.work, "points_%s.txt" % m)
    ctr = os.path.join(o.work, "centres_%s.txt" % m)
    P = read_foam_points(os.path.join(dyn_case, "constant", "polyMesh", "points"))
    C = read_vtk_points(os.path.join(dyn_case, "postProcessing", "dcpRBF", vtk))
    if spec.get("binary"):
        # dense n x N doubles twice (by columns and by rows) + the sparse copy
        # (<= 0.75 x dense at <= 50 % nonzeros) + 1 GB
        need = 8.0*len(P)*len(C)*2.75 + 2**30
        avail = 1024.0*int(re.search(r"MemAvailable:\s+(\d+)", open("/proc/meminfo").read()).group(1))
        if need > avail:
            return dict(skipped="needs ~%.1f GB (dense %d x %d doubles = %.1f GB, plus the sparse copy), "
                        "%.1f GB available" % (need/2**30, len(P), len(C), 8.0*len(P)*len(C)/2**30, avail/2**30),
                        points=len(P), centres=len(C))
    write_pts(pts, P)
    write_pts(ctr, C)
    del P, C
    env = dict(os.environ, OMP_NUM_THREADS=o.threads)
    # products timed: a short product varies up to 2x from run to run on this
    # shared machine; the median of many is stable (the large ones: 7)
    repeats = 7 if nResample or spec.get("binary") else 31
    args = ["/usr/bin/time", "-v", exe, pts, ctr, str(spec["dim"]), str(spec["R"]),
            str(repeats)]
    if nResample:
        args.append(str(nResample))
    # and the process run three times (the small meshes): the product's
    # median moves by up to 40 % from one process to the next here (its
    # memory's placement); the process with the median product is reported
    recs = []
    for _ in range(1 if nResample or spec.get("binary") else 3):
        out = subprocess.run(args, env=env, capture_output=True, text=True)
        if out.returncode:
            sys.exit("denseBaseline failed: " + out.stderr)
        rec = {k: float(v) for k, v in (l.split() for l in out.stdout.split("\n") if l.strip())}
        rec["rssMB"] = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)",
                                     out.stderr).group(1))/1024.0
        recs.append(rec)
    recs.sort(key=lambda r: r["denseProduct"])
    rec = recs[len(recs)//2]
    rec["denseRange"] = (recs[0]["denseProduct"], recs[-1]["denseProduct"])
    rec["processes"] = len(recs)
    rec["repeats"] = repeats
    # the reference of the ratios: the dense matrix by rows (the faster layout)
    # after a pass over 256 MB, as in a run, where dcpRBF's newPoints() is timed
    rec["denseReference"] = rec.get("denseRowsColdProduct", rec["denseProduct"])
    return rec

