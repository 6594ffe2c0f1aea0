// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the qualities of a 2D mesh's quadrilateral cells,
// one cell per SIMD lane from its four current points to its quality
// (PlanarCellQualityScan's cells of four points: most of a 2D mesh).
//
// A quadrilateral's four maps are PlanarCellQualityScan's (the triangles of
// the vertex average c and the edge from point j: F = (a - c, b - c) E0^-1,
// E0^-1 precomputed, kept here in lanes); per lane the maps' J and |A|^2,
// their rank keys, the ranked worst (TetMeasures::Worst's rule: the least
// key, the first of equal keys), the least quality of the inverted (J) and
// degenerate (1) maps and the final quality (tetKernel::quality): the same
// operations, so the same bits, as PlanarMapBatch, TetMeasures::Worst and
// WorstBatch. A cell with a map of positive J beyond the key's range (J or
// |A|^2 extreme) is finished from its maps' J and |A|^2 by those classes.
#pragma once

#include "LaneArrays.hpp"
#include "TetQuality.hpp"
#include "WorstBatch.hpp"

#include <cstddef>
#include <vector>

namespace dcprbf
{

class PlanarQuadBatch
{
public:
    //- Add a quadrilateral: its cell's index, its four points (indices of
    //  the x y pairs measure() reads, in order around it), per map j (the
    //  edge from point j) the reference inverse (row major 2 x 2, from
    //  inverse + 4 j) and whether that reference is degenerate
    void add
    (
        std::size_t cell,
        const int points[4],
        const double inverse[16],
        const bool degenerate[4]
    );

    //- Lay the added quadrilaterals out for measure() (after the last add)
    void finishAdding();

    //- Number of quadrilaterals
    std::size_t size() const { return cells_.size(); }

    //- The quality of every quadrilateral into q[its cell] for the current
    //  points x (x y per point). Called by every thread of an OpenMP
    //  parallel region (the quadrilaterals shared among them; the values
    //  do not depend on the number of threads) or outside one. wide false:
    //  the default-target build even where AVX2 is there; the same values
    void measure(const double* x, double* q, TetQuality::Metric metric, bool wide) const;

private:
    //- Per quadrilateral: its cell, its points
    std::vector<std::size_t> cells_;
    std::vector<int> points_;

    //- While adding: 20 values per quadrilateral (16 inverse entries, 4
    //  flags); after finishAdding: component k of quadrilateral t at
    //  k stride_ + t
    std::vector<double> reference_;
    std::size_t stride_ = 0;

    //- Quadrilaterals [t0, t1) (part of one thread's share) with its
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

} // namespace dcprbf
