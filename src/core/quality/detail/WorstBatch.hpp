// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: cells' worst tetrahedra (TetMeasures::Worst) to
// their qualities, each into its place: a ranked worst in SIMD lanes
// (TetBatch::qualities; ranked implies J and |A|^2 in TetMeasures::keyRange,
// the lanes' range), the others (none ranked: inverted, degenerate or
// beyond the range) by Worst::quality().
#pragma once

#include "TetMeasures.hpp"
#include "TetQuality.hpp"

#include <vector>

namespace dcprbf
{
namespace detail
{

class WorstBatch
{
public:
    explicit WorstBatch(const TetQuality::Metric metric, const bool wide = true)
    :
        metric_(metric),
        wide_(wide)
    {}

    //- The quality of w, to be written to *dest by finish()
    inline void add(const TetMeasures::Worst& w, double* dest)
    {
        if (w.ranked())
        {
            J_.push_back(w.J());
            a2_.push_back(w.a2());
            other_.push_back(w.other());
            dest_.push_back(dest);
        }
        else
        {
            *dest = w.quality();
        }
    }

    //- Write the qualities added since the last finish()
    void finish();

    //- The widest build (AVX-512 or AVX2) where there is one?
    bool wide() const { return wide_; }

private:
    TetQuality::Metric metric_;
    bool wide_;
    std::vector<double> J_, a2_, other_, q_;
    std::vector<double*> dest_;
};

} // namespace detail
} // namespace dcprbf
