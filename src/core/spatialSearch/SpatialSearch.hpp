// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module spatialSearch: points near points: a kd-tree
// (PointTree, nanoflann), radius queries by the boxes of Morton-ordered
// blocks (BlockBoxIndex, MortonOrder), the distinct rows of a point set
// (DistinctRows: the twin planes of a 2D mesh once) and checks of a control
// set (PointSetChecks: duplicates, coplanar seeds).
#pragma once

#include "PointTree.hpp"
#include "MortonOrder.hpp"
#include "BlockBoxIndex.hpp"
#include "DistinctRows.hpp"
#include "PointSetChecks.hpp"
