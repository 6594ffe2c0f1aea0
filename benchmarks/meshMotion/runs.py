# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The mesh-motion benchmark's runs (see run): moveDynamicMesh in a case
under /usr/bin/time -v, its log, dcpRBF.dat and OpenFOAM's profiling read
into a record."""
import os, re, statistics, sys, time

from cases import sh     # foamCase's (cases puts tutorials/common on sys.path)


def split_ms(row):
    """swap, select, interpolate, guard, points (ms) of a dcpRBF.dat row: together newPoints()."""
    return [1000*float(x) for x in row[10:14] + row[15:16]]


def run_case(o, c):
    env = dict(os.environ, OMP_NUM_THREADS=o.threads)
    t0 = time.time()
    rc = sh(["/usr/bin/time", "-v", "moveDynamicMesh"], c, os.path.join(c, "log.run"), env)
    wall = time.time() - t0
    log = open(os.path.join(c, "log.run")).read()
    if rc:
        sys.exit("moveDynamicMesh failed in %s (see log.run)" % c)
    et = [float(x) for x in re.findall(r"^ExecutionTime = (\S+) s", log, re.M)]
    # steps 2..n-1 (the last one writes the case); ExecutionTime is printed
    # to 0.01 s, so the mean over the steps, not a median of differences
    nS = max(1, len(et) - 2)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", log).group(1))
    rec = dict(case=c, wall=wall, stepMs=1000*(et[-2] - et[0])/nS,
               firstMs=1000*(et[0] if et else 0), rssMB=rss/1024.0)
    ct = [float(x) for x in re.findall(r"^ExecutionTime = \S+ s\s+ClockTime = (\S+) s", log, re.M)]
    rec["et"], rec["ct"] = et, ct
    it = [int(x) for x in re.findall(r"cellDisplacement\w*, Initial residual.*No Iterations (\d+)", log)]
    if it:
        rec["iters"] = (min(it), max(it))
    dat = os.path.join(c, "postProcessing", "dcpRBF", "0", "dcpRBF.dat")
    if os.path.isfile(dat):
        rows = [l.split() for l in open(dat) if l.strip() and not l.startswith("#")]
        rec["rows"] = rows
        rows = rows[1:]                                 # steps after the first
        cols = list(zip(*[split_ms(r) for r in rows]))
        rec["split"] = [statistics.median(col) for col in cols]
        steps = [sum(split_ms(r)) for r in rows]
        rec["dcpMs"] = statistics.median(steps)
        rec["dcpMean"], rec["dcpMax"] = statistics.mean(steps), max(steps)
        # steps with swaps or trials (swap time > 1 % of the median step)
        rec["swapSteps"] = [t for r, t in zip(rows, steps) if 1000*float(r[10]) > 0.01*rec["dcpMs"]]
        rec["nSteps"] = len(steps)
        rec["N"] = (int(float(rows[0][1])), int(float(rows[-1][1])))
    prof = profiling(c)
    if prof is not None:
        rec["solveMs"] = prof / max(1, len(et)) * 1000
    return rec


def profiling(c):
    """Total time of fvMatrix::solve.cellDisplacement* (profiling, last time)."""
    times = [d for d in os.listdir(c) if re.match(r"^[0-9.]+$", d) and d != "0"]
    if not times:
        return None
    f = os.path.join(c, max(times, key=float), "uniform", "profiling")
    if not os.path.isfile(f):
        return None
    txt = open(f).read()
    tot = 0.0
    for blk in re.findall(r"description\s+\"fvMatrix::solve\.cellDisplacement[^\"]*\";(.*?)\}", txt, re.S):
        mm = re.search(r"totalTime\s+([0-9.eE+-]+);", blk)
        if mm:
            tot += float(mm.group(1))
    return tot if tot > 0 else None
