// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "PlanarMapBatch.hpp"

#include "TetKernel.hpp"

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
    const double fa0 = c[0], fa1 = c[s], fb0 = c[2*s], fb1 = c[3*s];
    const double i00 = c[4*s], i01 = c[5*s], i10 = c[6*s], i11 = c[7*s];
    const double f00 = fa0*i00 + fb0*i10, f01 = fa0*i01 + fb0*i11;
    const double f10 = fa1*i00 + fb1*i10, f11 = fa1*i01 + fb1*i11;
    const double Jf = f00*f11 - f01*f10;
    const double a2f = f00*f00 + f01*f01 + f10*f10 + f11*f11 + 1;
    const double J = c[8*s] > 0 ? -1.0 : Jf;
    const double a2 = c[8*s] > 0 ? -1.0 : a2f;
    out[t] = J;
    out[s + t] = a2;
    out[2*s + t] = tetKernel::key<M>(J, a2);
}
};

} // namespace


void PlanarMapBatch::measure(const TetQuality::Metric metric, const bool wide)
{
    tetKernel::dispatch<tetKernel::Lanes<Lane>>
    (
        metric, wide, lanes_.size(), lanes_.stride(), lanes_.inData(), lanes_.outData()
    );
}

} // namespace detail
} // namespace dcprbf
