// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the worst tetrahedron of many triangular prisms at
// once, one prism per SIMD lane (CellQualityScan's prism cells: the
// boundary layers of 3D meshes).
//
// A prism is given by its six vertices, reference and current: a triangle
// (0 1 2) and the points above its points (3 4 5). Its decomposition is
// CellQualityScan's: face centres (vertex averages), the cell centre (the
// average of the five face centres) and the 18 tetrahedra (cell centre,
// face centre, face edge); a tetrahedron's A does not depend on the order
// of its vertices, so neither the faces' orientation nor their point order
// matters. measure() computes every tetrahedron (tetKernel) and keeps per
// prism what TetMeasures::Worst keeps: the ranked worst (J, |A|^2 of the
// least rank key), the least quality of the inverted (J) and degenerate (1)
// ones, and whether a tetrahedron is beyond the key's range (positive J,
// key 0 or below 1e-250: exact() false; the caller ranks that prism's 18
// tetrahedra, kept, with TetMeasures::Worst).
#pragma once

#include "LaneCellBatch.hpp"

namespace dcprbf
{
namespace detail
{

class PrismBatch
:
    public LaneCellBatch<6, 18>
{
public:
    //- The worst tetrahedron of every prism
    //  (wide false: the default-target build even with AVX2 or AVX-512;
    //  the values are the same)
    void measure(TetQuality::Metric metric, bool wide = true);
};

} // namespace detail
} // namespace dcprbf
