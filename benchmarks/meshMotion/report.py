# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The mesh-motion benchmark's report (see run): the tables of meshes a, b,
c, the products' table (also the fine wing's), and the report's copies in
build/meshMotion and benchmarks/README.md (between the markers)."""
import os

from cases import BUILD, DCP_CONFIGS, STEPS_2D, STEPS_3D, TOP

BEGIN = "<!-- meshMotion: begin (written by benchmarks/meshMotion/run) -->"
END = "<!-- meshMotion: end -->"
FINE_BEGIN = "<!-- meshMotion fine wing: begin (written by benchmarks/meshMotion/run --fine-wing) -->"
FINE_END = "<!-- meshMotion fine wing: end -->"
HEX_BEGIN = "<!-- meshMotion hex-dominant: begin (written by benchmarks/meshMotion/hexDominant) -->"
HEX_END = "<!-- meshMotion hex-dominant: end -->"
SCALE_BEGIN = "<!-- meshMotion scaling: begin (written by benchmarks/meshMotion/scaling) -->"
SCALE_END = "<!-- meshMotion scaling: end -->"


def write_readme(begin, end, report):
    """The report into benchmarks/README.md between its markers (appended the first time)."""
    readme = os.path.join(TOP, "benchmarks", "README.md")
    txt = open(readme).read()
    block = begin + "\n" + report + end
    if begin in txt:
        txt = txt[:txt.index(begin)] + block + txt[txt.index(end) + len(end):]
    else:
        txt = txt.rstrip("\n") + "\n\n" + block + "\n"
    open(readme, "w").write(txt)



def publish(o, report, name, begin, end):
    """The report printed, written to build/meshMotion/<name> and (unless
    --no-readme) into benchmarks/README.md between begin and end."""
    print(report)
    with open(os.path.join(BUILD, name), "w") as f:
        f.write(report)
    if not o.no_readme:
        write_readme(begin, end, report)


DENSE_HEADER = ("| data | kernel nonzeros | dense build (s) | dense product by columns (ms) | "
                "dense product by rows (ms) | by rows, cold (ms) | dense matrix (MB) | "
                "StoredEvaluation build (s) | sparse product (ms) | sparse matrix (MB) | "
                "sparse/dense time | sparse/dense memory | max rel. diff | peak RSS (MB) |")
DENSE_RULE = "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"


def dense_row(label, b):
    """a row of the products' table: sparse/dense time against the dense reference"""
    ms = lambda k: "%.2f" % (1000*b[k]) if k in b else "-"
    return "| %s | %.1f %% | %.2f | %.2f | %s | %s | %.0f | %.2f | %.2f | %.0f | %.2f | %.2f | %.0e | %.0f |" % (
        label, 100*b["nnzFraction"], b["denseBuild"], 1000*b["denseProduct"],
        ms("denseRowsProduct"), ms("denseRowsColdProduct"), b["denseBytes"]/2**20,
        b["sparseBuild"], 1000*b["sparseProduct"], b["sparseBytes"]/2**20,
        b["sparseProduct"]/b["denseReference"], b["sparseBytes"]/b["denseBytes"],
        b["maxRelDiff"], b["rssMB"])


def processes_note(b):
    """the baseline's processes: how many, the range of their dense products"""
    if b.get("processes", 1) < 2:
        return ""
    return "; the median of %d processes, their dense products %.2f-%.2f ms" % (
        b["processes"], 1000*b["denseRange"][0], 1000*b["denseRange"][1])


def tables(o, res, load0, total):
    L = []
    L.append("Command: `%s` (total %.0f s; load average %.2f at start, %.2f at end; "
             "OMP_NUM_THREADS=%s for every run).\n" % (o.command, total, load0, os.getloadavg()[0], o.threads))
    for m in o.meshes:
        spec = o.specs[m]
        base = res[(m, "baseline")]
        L.append("\n### Mesh %s: %s, %d points, motion: %s\n" % (
            m, spec["title"], base["points"],
            "rigid pitch 1 deg/step, %d steps" % STEPS_2D if spec["dim"] == 2 else
            "wing3D tutorial bending + twist (deltaT 0.025), %d steps" % STEPS_3D))
        L.append("Per step, median over the steps after the first (ms). swap/select/interpolate/"
                 "guard/points: dcpRBF.dat, together the motion solver's newPoints(); / dense: "
                 "newPoints() over the dense baseline's product below with its matrix by rows (each row's "
                 "three sums in one stream), cold (after a pass over 256 MB, as in a run: the warm "
                 "products, and Eigen's K alpha by columns, in the table below; OMP_NUM_THREADS=" + o.threads +
                 " both); step: ExecutionTime difference of moveDynamicMesh "
                 "(mesh.update() + moveDynamicMesh's checkMesh; process CPU time, = wall with 1 thread), mean "
                 "over steps 2 .. n-1 (ExecutionTime is printed to 0.01 s); rest = step - newPoints "
                 "(OpenFOAM's movePoints, checkMesh, I/O); newPoints mean (max): over the same steps, "
                 "the steps with swap trials included.\n")
        L.append("| motion solver | evaluationMemoryMB | N (first -> last) | swap | select | "
                 "interpolate | guard | points | newPoints | newPoints mean (max) | / dense | step | rest | newPoints / step | peak RSS (MB) |")
        L.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for key, _ in DCP_CONFIGS:
            for mem in ("default", "0"):
                r = res[(m, "%s_mem%s" % (key, mem))]
                s = r["split"]
                L.append("| dcpRBF %s | %s | %d -> %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f (%.2f) | %.2f | %.1f | %.1f | %.2f | %.0f |" % (
                    key, "1024 (default)" if mem == "default" else "0 (on the fly)",
                    r["N"][0], r["N"][1], s[0], s[1], s[2], s[3], s[4], r["dcpMs"],
                    r["dcpMean"], r["dcpMax"],
                    r["dcpMs"]/(1000*base["denseReference"]), r["stepMs"],
                    r["stepMs"] - r["dcpMs"], r["dcpMs"]/r["stepMs"] if r["stepMs"] else 0,
                    r["rssMB"]))
        r = res[(m, "laplacian")]
        it = r.get("iters", (0, 0))
        L.append("| displacementLaplacian (GAMG, 1e-8, relTol 0; %d-%d iterations per component and step) | - | - | - | - | - | - | - | %s | - | %s | %.1f | %s | %s | %.0f |" % (
            it[0], it[1], "%.2f (solve)" % r["solveMs"] if "solveMs" in r else "-",
            "%.2f" % (r["solveMs"]/(1000*base["denseReference"])) if "solveMs" in r else "-", r["stepMs"],
            "%.1f" % (r["stepMs"] - r["solveMs"]) if "solveMs" in r else "-",
            "%.2f" % (r["solveMs"]/r["stepMs"]) if "solveMs" in r and r["stepMs"] else "-", r["rssMB"]))
        L.append("")
        g, d = res[(m, "greedy_memdefault")], res[(m, "dynamic_memdefault")]
        sw = d["swapSteps"]
        L.append("Dynamic / greedy (stored): median step %.2fx, mean %.2fx; the dynamic run's steps with "
                 "swap trials: %d of %d%s. The stored product patched with 3 / 6 columns (a set after "
                 "swaps): %s ms, unpatched %.2f ms.\n" % (
                     d["dcpMs"]/g["dcpMs"], d["dcpMean"]/g["dcpMean"], len(sw), d["nSteps"],
                     " (newPoints %.1f-%.1f ms)" % (min(sw), max(sw)) if sw else "",
                     " / ".join("%.2f" % (1000*base[k]) for k in ("sparsePatched3Product", "sparsePatched6Product")
                                if k in base) or "-", 1000*base["sparseProduct"]))
        L.append("Products (%d mesh points x N = %d control points of the dynamic run's last step, "
                 "3 right-hand sides + linear polynomial, OMP_NUM_THREADS=%s, median of %d (the "
                 "resampled: 7 in 1 process)%s):\n" % (base["points"], base["centres"], o.threads, base["repeats"],
                                          processes_note(base)))
        L.append(DENSE_HEADER)
        L.append(DENSE_RULE)
        for k in ("baseline", "baseline1M"):
            if (m, k) not in res:
                continue
            b = res[(m, k)]
            L.append(dense_row("mesh points" if k == "baseline" else
                               "resampled to %d points" % b["points"], b))
    return "\n".join(L) + "\n"


