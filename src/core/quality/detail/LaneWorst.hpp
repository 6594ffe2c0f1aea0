// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: what TetMeasures::Worst keeps of a cell's
// tetrahedra (or 2D maps), as SIMD lane values updated by selects only
// (PrismBatch, PlanarPolygonBatch). Include after TetKernel.hpp, in the
// kernels' .cpp files only (its pragmas apply to these functions).
#pragma once

#include "TetKernel.hpp"

namespace dcprbf
{
namespace detail
{

struct LaneWorst
{
    //- The ranked worst's J and |A|^2 and its key (1e308: none ranked);
    //  the least quality of the inverted (J) and degenerate (1) ones
    //  (1e308: none); how many have a positive J beyond the key's range
    //  (the scalar path's)
    double J = 1, a2 = 3, key = 1e308, other = 1e308, beyond = 0;

    //- TetMeasures::Worst::add with the key k = tetKernel::key (ranked:
    //  key in (1e-250, 1e250); keys are <= 1 here: |A|^2 >= 3 J^(2/3)),
    //  the first of equal keys kept
    DCPRBF_ALWAYS_INLINE void add(const double J1, const double a21, const double k)
    {
        const double kk = k > 1e-250 ? k : 1e308;
        const double key0 = key;
        J = kk < key0 ? J1 : J;
        a2 = kk < key0 ? a21 : a2;
        key = kk < key0 ? kk : key0;

        // inverted (quality J) or degenerate reference (quality 1)
        double q = J1 > 0 ? 1e308 : J1;
        q = a21 < 0 ? 1.0 : q;
        other = q < other ? q : other;

        // positive J beyond the key's range, counted (a ranked key implies
        // J > 0; as a sum: a max of selects made GCC 12 fail)
        beyond += (J1 > 0 ? 1.0 : 0.0) - (k > 1e-250 ? 1.0 : 0.0);
    }

    //- Into lane p of out (rows s apart): J, a2, key, other, beyond (the
    //  cell batches' first five rows, LaneCellBatch)
    DCPRBF_ALWAYS_INLINE void write(double* out, const std::size_t p, const std::size_t s) const
    {
        out[p] = J;
        out[s + p] = a2;
        out[2*s + p] = key;
        out[3*s + p] = other;
        out[4*s + p] = beyond;
    }

    //- WorstBatch's final quality: the ranked worst's, the least with the
    //  others (where nothing is beyond the range)
    template<int M>
    DCPRBF_ALWAYS_INLINE double quality() const
    {
        const double qr = tetKernel::quality<M>(J, a2);
        const double qm = qr < other ? qr : other;
        return key < 1e308 ? qm : other;
    }
};

} // namespace detail
} // namespace dcprbf
