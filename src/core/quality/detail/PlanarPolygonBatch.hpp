// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the qualities of a 2D mesh's triangular (N = 3) or
// quadrilateral (N = 4) cells, one cell per SIMD lane from its current
// points to its quality (PlanarCellQualityScan's cells of three and four
// points: nearly all of a 2D mesh).
//
// The maps are PlanarCellQualityScan's: a triangle's own, F = (b - a, c - a)
// E0^-1; a quadrilateral's four, the triangles of the vertex average c and
// the edge from point j, F = (a - c, b - c) E0^-1 (E0^-1 precomputed, kept
// here in lanes); per lane the maps' J and |A|^2, their rank keys, the
// ranked worst (TetMeasures::Worst's rule: the least key, the first of equal
// keys), the least quality of the inverted (J) and degenerate (1) maps and
// the final quality (tetKernel::quality): the same operations, so the same
// bits, as PlanarMapBatch, TetMeasures::Worst and WorstBatch. A cell with
// a map of positive J beyond the key's range (J or |A|^2 extreme) is
// finished from its maps' J and |A|^2 by those classes.
#pragma once

#include "LaneArrays.hpp"
#include "TetQuality.hpp"
#include "WorstBatch.hpp"

#include <cstddef>
#include <vector>

namespace dcprbf
{
namespace detail
{

template<int N>
class PlanarPolygonBatch
{
public:
    static_assert(N == 3 || N == 4, "triangles or quadrilaterals");

    //- Maps per cell
    static constexpr int nMaps = N == 3 ? 1 : N;

    //- Add a cell: its index, its N points (indices of the x y pairs
    //  measure() reads, in order around it), per map j the reference
    //  inverse (row major 2 x 2, from inverse + 4 j) and whether that
    //  reference is degenerate
    void add
    (
        std::size_t cell,
        const int points[N],
        const double inverse[4*nMaps],
        const bool degenerate[nMaps]
    );

    //- Lay the added cells out for measure() (after the last add)
    void finishAdding();

    //- Number of cells
    std::size_t size() const { return cells_.size(); }

    //- The quality of every cell into q[its index] for the current points
    //  x (x y per point). Called by every thread of an OpenMP parallel
    //  region (the cells shared among them; the values do not depend on
    //  the number of threads) or outside one. wide false: the
    //  default-target build even with AVX2 or AVX-512; the same values
    void measure(const double* x, double* q, TetQuality::Metric metric, bool wide) const;

private:
    //- Per cell: its index, its points
    std::vector<std::size_t> cells_;
    std::vector<int> points_;

    //- While adding: 5 nMaps values per cell (the maps' inverses, 4
    //  entries each, then their flags); after finishAdding: component k of
    //  cell t at k stride_ + t
    std::vector<double> reference_;
    std::size_t stride_ = 0;

    //- Cells [t0, t1) (part of one thread's share) with its
    //  scratch: lanes s, the scalar path's finals
    void measureChunk
    (
        std::size_t t0,
        std::size_t t1,
        const double* x,
        double* q,
        TetQuality::Metric metric,
        LaneArrays& s,
        WorstBatch& finals
    ) const;
};

extern template class PlanarPolygonBatch<3>;
extern template class PlanarPolygonBatch<4>;

} // namespace detail
} // namespace dcprbf
