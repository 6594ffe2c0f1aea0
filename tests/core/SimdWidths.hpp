// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Test helper: run a check at every wide width of the SIMD kernels this
// processor has (AVX-512, then AVX2 under a cap), the cap lifted after.
#pragma once

#include "TetBatch.hpp"

#include <vector>

namespace dcprbf
{
namespace test
{

//- f(bits) at each wide width the processor has; the widths run
template<class F>
std::vector<unsigned> atEachSimdWidth(F f)
{
    std::vector<unsigned> run;
    for (const unsigned bits : {512u, 256u})
    {
        TetBatch::limitWidth(bits);
        if (TetBatch::width() == bits)
        {
            f(bits);
            run.push_back(bits);
        }
    }
    TetBatch::limitWidth(512);
    return run;
}

} // namespace test
} // namespace dcprbf
