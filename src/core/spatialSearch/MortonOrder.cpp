// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "MortonOrder.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace dcprbf
{

namespace
{

//- The 21 low bits of v spread to every third bit
std::uint64_t spread(std::uint64_t v)
{
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

} // namespace


std::vector<int> mortonOrder(const double* x, const std::size_t n)
{
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = i ? std::min(lo[d], x[3*i + d]) : x[3*i + d];
            hi[d] = i ? std::max(hi[d], x[3*i + d]) : x[3*i + d];
        }
    }
    const double cells = double((1 << 21) - 1);
    std::vector<std::uint64_t> key(n, 0);
    for (std::size_t i = 0; i < n; ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            const double s = hi[d] > lo[d] ? (x[3*i + d] - lo[d])/(hi[d] - lo[d]) : 0;
            key[i] |= spread(std::uint64_t(std::min(cells, std::max(0.0, s*cells)))) << d;
        }
    }
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort
    (
        order.begin(), order.end(),
        [&key](int a, int b) { return key[a] < key[b] || (key[a] == key[b] && a < b); }
    );
    return order;
}

} // namespace dcprbf
