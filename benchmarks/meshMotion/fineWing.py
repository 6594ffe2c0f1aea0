# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The mesh-motion benchmark's --fine-wing (see run): the wing tutorial's
--fine mesh, dcpRBF selection greedy and dynamic (and --stored-mb, and
displacementLaplacian with --laplacian), per-step rows, the dense baseline
with the greedy run's control set."""
import os, time

import baseline
from cases import DCP_CONFIGS, LAPLACIAN, STEPS_FINE, dcp_dict, make_case, make_mesh
from report import DENSE_HEADER, DENSE_RULE, FINE_BEGIN, FINE_END, dense_row, processes_note, publish
from runs import run_case, split_ms


def fine(o):
    m = "f"
    os.makedirs(o.work, exist_ok=True)
    baseline.build()
    tStart = time.time()
    load0 = os.getloadavg()[0]
    t = time.time()
    make_mesh(o, m)
    tMesh = time.time() - t
    print("mesh f: %.0f s" % tMesh, flush=True)
    res = {}
    for key, cp, mem in fine_runs(o):
        res[key] = run_case(o, make_case(o, m, key, dcp_dict(o.specs[m], cp, mem)))
        print(m, key, {k: v for k, v in res[key].items() if k != "rows"}, flush=True)
    if o.laplacian:
        res["laplacian"] = run_case(o, make_case(o, m, "laplacian", LAPLACIAN))
        print(m, "laplacian", {k: v for k, v in res["laplacian"].items() if k != "rows"}, flush=True)
    res["baseline"] = baseline.baseline(o, m, os.path.join(o.work, "f_greedy"))
    print(m, "baseline", res["baseline"], flush=True)
    publish(o, fine_table(o, res, load0, time.time() - tStart, tMesh), "report_fine.md",
            FINE_BEGIN, FINE_END)


def fine_runs(o):
    """(key, controlPoints, evaluationMemoryMB) of the fine wing's dcpRBF runs"""
    runs = [(key, cp, None) for key, cp in DCP_CONFIGS[1:]]
    if o.stored_mb:
        runs.append(("greedy_mem%d" % o.stored_mb, DCP_CONFIGS[1][1], o.stored_mb))
    return runs


def fine_table(o, res, load0, total, tMesh):
    L = []
    npts = res["baseline"]["points"]
    L.append("Command: `%s` (total %.0f s, of which mesh %.0f s%s; load average %.2f at start, "
             "%.2f at end; OMP_NUM_THREADS=%s; 2 cores, shared).\n" % (
                 o.command, total, tMesh, " (gmshToFoam of the given --msh)" if o.msh else "",
                 load0, os.getloadavg()[0], o.threads))
    L.append("\n### Mesh f: %s, %d points, motion: wing3D tutorial bending + twist (deltaT 0.025), "
             "%d steps\n" % (o.specs["f"]["title"], npts, STEPS_FINE))
    L.append("Per step (ms). swap/select/interpolate/guard/points: dcpRBF.dat, together the motion "
             "solver's newPoints(); step: ExecutionTime "
             "difference (process CPU time; step 1 is ExecutionTime at its end, so it includes "
             "reading the mesh and the solver's setup; the last step includes writing the "
             "moved points); wall: the same with ClockTime (1 s resolution); rest = step - newPoints "
             "(OpenFOAM's movePoints, moveDynamicMesh's checkMesh, I/O). evaluationMemoryMB default "
             "(1024). %s\n" % (
                 "displacementLaplacian (GAMG, 1e-8, relTol 0): its rows give the solve "
                 "(fvMatrix::solve.cellDisplacement from OpenFOAM's profiling, mean per step) "
                 "in the newPoints column." if "laplacian" in res else
                 "displacementLaplacian not run (--laplacian)."))
    L.append("| motion solver | step | N | swap | select | interpolate | guard | points | newPoints | "
             "step | wall (s) | rest | min quality | peak RSS of the run (MB) |")
    L.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for key, _, mem in fine_runs(o):
        r = res[key]
        if mem:
            key = "greedy, evaluationMemoryMB %d" % mem
        et, ct = [0.0] + r["et"], [0.0] + r["ct"]
        for k, row in enumerate(r["rows"]):
            sp = split_ms(row)
            step = 1000*(et[k + 1] - et[k]) if k + 1 < len(et) else float("nan")
            wall = (ct[k + 1] - ct[k]) if k + 1 < len(ct) else float("nan")
            L.append("| dcpRBF %s | %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.0f | %.0f | %.0f | %.3f | %s |" % (
                key, k + 1, int(float(row[1])), sp[0], sp[1], sp[2], sp[3], sp[4], sum(sp), step, wall,
                step - sum(sp), float(row[6]), "%.0f" % r["rssMB"] if k == 0 else ""))
    if "laplacian" in res:
        r = res["laplacian"]
        et, ct = [0.0] + r["et"], [0.0] + r["ct"]
        solve = r.get("solveMs", float("nan"))
        it = r.get("iters")
        for k in range(len(r["et"])):
            step = 1000*(et[k + 1] - et[k])
            L.append("| displacementLaplacian%s | %d | - | - | - | - | - | - | %.0f (solve) | %.0f | %.0f | %.0f | - | %s |" % (
                " (%d-%d iterations per component and step)" % it if it and k == 0 else "",
                k + 1, solve, step, ct[k + 1] - ct[k], step - solve,
                "%.0f" % r["rssMB"] if k == 0 else ""))
    b = res["baseline"]
    L.append("")
    if "skipped" in b:
        L.append("Dense baseline (%d mesh points x N = %d, the greedy run's control set): skipped, "
                 "%s.\n" % (b["points"], b["centres"], b["skipped"]))
    else:
        L.append("Products (%d mesh points x N = %d control points of the greedy run's last step, "
                 "3 right-hand sides + linear polynomial, OMP_NUM_THREADS=%s, median of %d%s):\n" % (
                     b["points"], b["centres"], o.threads, b["repeats"], processes_note(b)))
        L.append(DENSE_HEADER)
        L.append(DENSE_RULE)
        L.append(dense_row("mesh points", b))
    return "\n".join(L) + "\n"

