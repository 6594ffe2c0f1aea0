// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core, module quality: cell quality relative to the
// reference mesh: the tetrahedron metric (TetQuality), the flat per-cell
// scans of 3D cells (CellQualityScan, CellShapes; CellQualityBound: a cheap
// lower bound of a cell's quality, for scans of the lowest cells) and of the polygons of 2D
// meshes (PlanarCellQualityScan), the vector width their kernels run at
// (SimdWidth). The SIMD batches and kernels are internals (quality/detail,
// namespace dcprbf::detail).
#pragma once

#include "TetQuality.hpp"
#include "CellShapes.hpp"
#include "CellQualityBound.hpp"
#include "CellQualityScan.hpp"
#include "PlanarCellQualityScan.hpp"
#include "SimdWidth.hpp"
