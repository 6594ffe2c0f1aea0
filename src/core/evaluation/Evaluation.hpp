// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module evaluation: the interpolant at the mesh
// points: evaluated on the fly (RbfEvaluator: compact kernels through a kd-
// tree or block boxes) or from stored kernel matrices (StoredEvaluation: kept
// while the control set stays, rows merged when it changes).
#pragma once

#include "RbfEvaluator.hpp"
#include "StoredEvaluation.hpp"
