// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the worst tetrahedron of many hexahedra at once,
// one hexahedron per SIMD lane (CellQualityScan's hexahedral cells: most of
// a snappyHexMesh or blockMesh mesh). PrismBatch's counterpart.
//
// A hexahedron is given by its eight vertices, reference and current: a
// quadrilateral (0 1 2 3) and the points joined to its points (4 5 6 7).
// Its decomposition is CellQualityScan's: face centres (vertex averages),
// the cell centre (the average of the six face centres) and the 24
// tetrahedra (cell centre, face centre, face edge), computed in the lane
// instead of gathered into a TetBatch; a tetrahedron's A does not depend
// on the order of its vertices, so neither the faces' orientation nor
// their point order matters (the face centres' sums, in another order
// than the faces', differ in round-off only). measure() keeps per
// hexahedron what TetMeasures::Worst keeps: the ranked worst (J, |A|^2 of
// the least rank key), the least quality of the inverted (J) and
// degenerate (1) ones, and whether a tetrahedron is beyond the key's range
// (exact() false; the caller ranks that hexahedron's 24 tetrahedra, kept,
// with TetMeasures::Worst).
#pragma once

#include "LaneCellBatch.hpp"

namespace dcprbf
{
namespace detail
{

class HexBatch
:
    public LaneCellBatch<8, 24>
{
public:
    //- The worst tetrahedron of every hexahedron
    //  (wide false: the default-target build even with AVX2 or AVX-512;
    //  the values are the same)
    void measure(TetQuality::Metric metric, bool wide = true);
};

} // namespace detail
} // namespace dcprbf
