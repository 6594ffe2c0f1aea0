# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The ASCII polyMesh of this case, read without OpenFOAM: points (of a
time), faces, the patches' face ranges and the written times."""
import os
import re

import numpy as np


def _body(path):
    text = open(path).read()
    text = text[text.index("}", text.index("FoamFile")) + 1:]
    m = re.search(r"^(\d+)\s*\n\(", text, re.M)
    return int(m.group(1)), text[m.end():]


def points(case, time="constant"):
    """The points of a time (constant: the reference mesh)."""
    path = os.path.join(case, time, "polyMesh", "points")
    n, body = _body(path)
    vals = re.findall(r"\(([-0-9.eE+]+) ([-0-9.eE+]+) ([-0-9.eE+]+)\)", body)[:n]
    return np.array(vals, dtype=float)


def faces(case):
    n, body = _body(os.path.join(case, "constant", "polyMesh", "faces"))
    return [list(map(int, f.split())) for f in re.findall(r"\d+\(([^()]*)\)", body)[:n]]


def patches(case):
    """Each patch's (startFace, nFaces)."""
    text = open(os.path.join(case, "constant", "polyMesh", "boundary")).read()
    out = {}
    for name, body in re.findall(r"(\w+)\s*\{([^}]*)\}", text):
        if name == "FoamFile":
            continue
        start = re.search(r"startFace\s+(\d+);", body)
        size = re.search(r"nFaces\s+(\d+);", body)
        if start and size:
            out[name] = (int(start.group(1)), int(size.group(1)))
    return out


def patchPoints(case, name):
    start, size = patches(case)[name]
    f = faces(case)
    return sorted({p for face in f[start:start + size] for p in face})


def times(case):
    """The written times but 0, in order."""
    ts = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if t > 0 and os.path.isfile(os.path.join(case, d, "polyMesh", "points")):
            ts.append(d)
    return sorted(ts, key=float)
