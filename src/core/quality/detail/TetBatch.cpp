// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "TetBatch.hpp"

#include "TetKernel.hpp"

#include <algorithm>

namespace dcprbf
{
namespace detail
{

namespace
{

struct Lane
{
template<int M>
static DCPRBF_ALWAYS_INLINE void item
(
    const std::size_t t,
    const std::size_t s,
    const double* __restrict in,
    double* __restrict out
)
{
    const double* c = in + t;
    double J, a2;
    tetKernel::measures
    (
        c[0], c[s], c[2*s], c[3*s], c[4*s], c[5*s], c[6*s], c[7*s], c[8*s],
        c[9*s], c[10*s], c[11*s], c[12*s], c[13*s], c[14*s], c[15*s], c[16*s], c[17*s],
        J, a2
    );
    out[t] = J;
    out[s + t] = a2;
    out[2*s + t] = tetKernel::key<M>(J, a2);
}
};

struct QualityKernel
{
template<int M>
static DCPRBF_ALWAYS_INLINE void run
(
    const std::size_t n,
    const double* __restrict J,
    const double* __restrict a2,
    double* __restrict q
)
{
    #pragma omp simd
    for (std::size_t i = 0; i < n; ++i)
    {
        q[i] = tetKernel::quality<M>(J[i], a2[i]);
    }
}
};

} // namespace


bool TetBatch::wideAvailable()
{
    return tetKernel::widest() > 0;
}


unsigned TetBatch::width()
{
    return tetKernel::widest();
}


unsigned TetBatch::widthCap()
{
    return tetKernel::widthLimit().load(std::memory_order_relaxed);
}


unsigned TetBatch::widthCapOf(const char* value)
{
    return tetKernel::widthCapOf(value);
}


void TetBatch::limitWidth(const unsigned bits)
{
    tetKernel::widthLimit().store(bits, std::memory_order_relaxed);
}


void TetBatch::qualities
(
    const std::size_t n,
    const double* J,
    const double* a2,
    double* q,
    const TetQuality::Metric metric,
    const bool wide
)
{
    tetKernel::dispatch<QualityKernel>(metric, wide, n, J, a2, q);
}


void TetBatch::measure(const TetQuality::Metric metric, const bool wide)
{
    tetKernel::dispatch<tetKernel::Lanes<Lane>>
    (
        metric, wide, lanes_.size(), lanes_.stride(), lanes_.inData(), lanes_.outData()
    );
}

} // namespace detail
} // namespace dcprbf
