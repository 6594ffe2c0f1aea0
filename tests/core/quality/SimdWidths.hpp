// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Test helper: run a check at every wide width of the SIMD kernels this
// processor has (AVX-512, then AVX2 under a cap); the cap as before after.
#pragma once

#include "SimdWidth.hpp"

#include <vector>

namespace dcprbf
{
namespace test
{

//- Restores the SIMD width cap it found, however the scope ends
class WidthCapGuard
{
public:
    WidthCapGuard() : cap_(SimdWidth::cap()) {}
    ~WidthCapGuard() { SimdWidth::limit(cap_); }
    WidthCapGuard(const WidthCapGuard&) = delete;
    WidthCapGuard& operator=(const WidthCapGuard&) = delete;

private:
    unsigned cap_;
};

//- f(bits) at each wide width the processor has, widest first; the widths
//  run
template<class F>
std::vector<unsigned> atEachSimdWidth(F f)
{
    const WidthCapGuard guard;
    std::vector<unsigned> run;
    for (const unsigned bits : {512u, 256u})
    {
        SimdWidth::limit(bits);
        if (SimdWidth::bits() == bits)
        {
            f(bits);
            run.push_back(bits);
        }
    }
    return run;
}

} // namespace test
} // namespace dcprbf
