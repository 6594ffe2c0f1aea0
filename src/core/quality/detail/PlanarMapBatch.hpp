// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: the measures of many in-plane triangle maps at
// once, laid out for SIMD (PlanarCellQualityScan's inner loop).
//
// A map is F = (fa fb) E0^-1: the current edges fa, fb (2 x 1 each) and the
// inverse of the reference edge matrix (row major, precomputed), or a
// degenerate reference. Its tetrahedra have A = diag(F, 1): measure()
// computes J = det F, |A|_F^2 = |F|_F^2 + 1 and TetMeasures::rankKey in the
// SIMD kernels' range (tetKernel::key; else 0); a degenerate reference gives
// J = a2 = -1 (quality 1, TetQuality's convention). No branch, no division
// by zero or overflow in any lane: see TetKernel.hpp.
#pragma once

#include "LaneArrays.hpp"
#include "TetQuality.hpp"

#include <cstddef>

namespace dcprbf
{
namespace detail
{

class PlanarMapBatch
{
public:
    //- Room for n maps (their values undefined until set)
    void resize(const std::size_t n) { lanes_.resize(n); }

    //- Number of maps
    std::size_t size() const { return lanes_.size(); }

    //- Map t: current edges fa, fb (x y each), reference inverse inv (row
    //  major 2 x 2), degenerate reference or not
    inline void set
    (
        const std::size_t t,
        const double fa0, const double fa1,
        const double fb0, const double fb1,
        const double* inv,
        const bool degenerate
    )
    {
        lanes_.in(0, t) = fa0;
        lanes_.in(1, t) = fa1;
        lanes_.in(2, t) = fb0;
        lanes_.in(3, t) = fb1;
        for (int k = 0; k < 4; ++k) lanes_.in(4 + k, t) = inv[k];
        lanes_.in(8, t) = degenerate ? 1.0 : 0.0;
    }

    //- J, |A|_F^2 and the rank key of every map (wide false: the
    //  default-target build even with AVX2 or AVX-512; the same values)
    void measure(TetQuality::Metric metric, bool wide = true);

    double J(const std::size_t t) const { return lanes_.out(0, t); }
    double a2(const std::size_t t) const { return lanes_.out(1, t); }
    double key(const std::size_t t) const { return lanes_.out(2, t); }

private:
    //- In: 9 components (fa, fb, inverse, degenerate flag); out: J, a2,
    //  key
    LaneArrays lanes_{9, 3};
};

} // namespace detail
} // namespace dcprbf
