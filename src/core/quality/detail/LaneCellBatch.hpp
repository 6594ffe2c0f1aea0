// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: many cells of one shape at once, one cell per SIMD
// lane, each cell's NT tetrahedra of the decomposition computed and its worst
// kept in the lane (the storage and the read-out of PrismBatch, NV = 6, NT =
// 18, and HexBatch, NV = 8, NT = 24; each of them its measure()).
//
// Per cell: NV vertices, reference and current; out: what TetMeasures::Worst
// keeps (the ranked worst's J and |A|^2, its key, the least quality of the
// inverted and degenerate ones, the number beyond the key's range: exact()
// false, the caller ranks that cell's NT tetrahedra, kept, with
// TetMeasures::Worst).
#pragma once

#include "LaneArrays.hpp"
#include "TetMeasures.hpp"
#include "TetQuality.hpp"

#include <cstddef>

namespace dcprbf
{
namespace detail
{

template<int NV, int NT>
class LaneCellBatch
{
public:
    //- Room for n cells (their values undefined until set)
    void resize(const std::size_t n) { lanes_.resize(n); }

    //- Number of cells
    std::size_t size() const { return lanes_.size(); }

    //- Cell p: vertex k's reference coordinates at r0 + 3 v[k], current at
    //  x + 3 v[k]
    inline void set
    (
        const std::size_t p,
        const double* r0,
        const double* x,
        const int v[NV]
    )
    {
        for (int k = 0; k < NV; ++k)
        {
            const double* r = r0 + 3*std::size_t(v[k]);
            const double* y = x + 3*std::size_t(v[k]);
            for (int d = 0; d < 3; ++d)
            {
                lanes_.in(3*k + d, p) = r[d];
                lanes_.in(3*NV + 3*k + d, p) = y[d];
            }
        }
    }

    //- Cell p: all its tetrahedra were ranked or inverted or degenerate
    //  (no scalar path needed)
    bool exact(const std::size_t p) const { return lanes_.out(4, p) == 0; }

    //- Cell p: J and |A|_F^2 of the ranked worst; ranked(p) false if
    //  every tetrahedron is inverted or degenerate
    double J(const std::size_t p) const { return lanes_.out(0, p); }
    double a2(const std::size_t p) const { return lanes_.out(1, p); }
    bool ranked(const std::size_t p) const { return lanes_.out(2, p) < 1e308; }

    //- Cell p: the least quality of its inverted and degenerate
    //  tetrahedra (1e308 if none)
    double other(const std::size_t p) const { return lanes_.out(3, p); }

    //- Cell p (exact) as TetMeasures::Worst keeps it
    TetMeasures::Worst worst(const std::size_t p, const TetQuality::Metric metric) const
    {
        return TetMeasures::Worst(metric, J(p), a2(p), ranked(p), other(p));
    }

    //- Cell p: J and |A|_F^2 of its tetrahedron t (0 .. NT-1; for the
    //  scalar path)
    double tetJ(const std::size_t p, const int t) const
    {
        return lanes_.out(5 + 2*t, p);
    }
    double tetA2(const std::size_t p, const int t) const
    {
        return lanes_.out(6 + 2*t, p);
    }

    //- Number of tetrahedra of a cell
    static constexpr int nTets = NT;

protected:
    //- In: 6 NV components (NV reference then NV current vertices, x y z
    //  each); out: J, a2, key, other, the number beyond the key's range,
    //  then J and a2 of each of the NT tetrahedra
    LaneArrays lanes_{6*NV, 5 + 2*NT};
};

} // namespace detail
} // namespace dcprbf
