// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "BlockBoxIndex.hpp"

#include <algorithm>

namespace dcprbf
{

BlockBoxIndex::Box BlockBoxIndex::merged(const Box* first, const Box* last)
{
    Box m = *first;
    for (const Box* b = first + 1; b < last; ++b)
    {
        for (int k = 0; k < 3; ++k)
        {
            m.lo[k] = std::min(m.lo[k], b->lo[k]);
            m.hi[k] = std::max(m.hi[k], b->hi[k]);
        }
    }
    return m;
}


BlockBoxIndex::BlockBoxIndex(const double* x, const std::size_t n)
:
    x_(x),
    n_(n)
{
    const std::size_t nBlocks = (n + block - 1)/block;
    blocks_.resize(nBlocks);
    #pragma omp parallel for schedule(static)
    for (std::ptrdiff_t b = 0; b < std::ptrdiff_t(nBlocks); ++b)
    {
        const std::size_t i0 = std::size_t(b)*block, i1 = std::min(n, i0 + block);
        Box box;
        for (int k = 0; k < 3; ++k) box.lo[k] = box.hi[k] = x[3*i0 + k];
        for (std::size_t i = i0 + 1; i < i1; ++i)
        {
            for (int k = 0; k < 3; ++k)
            {
                box.lo[k] = std::min(box.lo[k], x[3*i + k]);
                box.hi[k] = std::max(box.hi[k], x[3*i + k]);
            }
        }
        blocks_[b] = box;
    }
    const std::size_t nGroups = (nBlocks + block - 1)/block;
    groups_.resize(nGroups);
    for (std::size_t g = 0; g < nGroups; ++g)
    {
        const std::size_t b0 = g*block, b1 = std::min(nBlocks, b0 + block);
        groups_[g] = merged(blocks_.data() + b0, blocks_.data() + b1);
    }
}

} // namespace dcprbf
