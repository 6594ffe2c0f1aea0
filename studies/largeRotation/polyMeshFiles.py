# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Readers of the ASCII files of an OpenFOAM case that the study's scripts (run,
foldScan) need: polyMesh points, faces, owner and neighbour, a patch's faces, and
a point field's nonuniform scalar list."""
import os
import re

import numpy as np


def read_list(path):
    """The count and the text after the opening parenthesis of a file's list."""
    text = open(path).read()
    start = re.search(r"\n(\d+)\s*\n\(", text)
    return int(start.group(1)), text[start.end():]


def read_points(path):
    n, body = read_list(path)
    return np.array(re.findall(r"\(([-\d.eE+]+) ([-\d.eE+]+) ([-\d.eE+]+)\)", body)[:n], float)


def read_labels(path):
    n, body = read_list(path)
    return np.array(body.split(")")[0].split()[:n], int)


def read_faces(path):
    n, body = read_list(path)
    return [list(map(int, s.split())) for s in re.findall(r"\d+\(([^()]*)\)", body)[:n]]


def read_point_scalars(path):
    """The internal field of a pointScalarField written nonuniform (rotationBlend)."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", text)
    return np.array(text[m.end():].split(")")[0].split()[:int(m.group(1))], float)


def patch_faces(case, name):
    """The first face and the number of faces of patch name (constant/polyMesh/boundary)."""
    text = open(os.path.join(case, "constant", "polyMesh", "boundary")).read()
    m = re.search(r"(?m)^\s*" + re.escape(name)
                  + r"\s*\{[^}]*nFaces\s+(\d+);[^}]*startFace\s+(\d+);", text)
    return int(m.group(2)), int(m.group(1))
