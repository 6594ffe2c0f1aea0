// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "SmallestValues.hpp"

#include <algorithm>

namespace dcprbf
{

std::vector<double> smallestValues(const double* values, const std::size_t n, std::size_t k)
{
    k = std::min(k, n);
    std::vector<double> kept;
    if (k == 0)
    {
        return kept;
    }
    constexpr std::size_t stride = 64;
    if (k < n/4 && n >= 16*stride)
    {
        // the sample's value at the rank of 1.5 k + 64 among all
        std::vector<double> sample;
        sample.reserve(n/stride + 1);
        for (std::size_t i = 0; i < n; i += stride) sample.push_back(values[i]);
        const std::size_t r = std::min(sample.size() - 1, (3*k/2 + stride)/stride);
        std::nth_element(sample.begin(), sample.begin() + r, sample.end());
        const double bound = sample[r];
        for (std::size_t i = 0; i < n; ++i)
        {
            if (values[i] <= bound) kept.push_back(values[i]);
        }
        if (kept.size() < k)
        {
            kept.clear();
        }
    }
    if (kept.empty())
    {
        kept.assign(values, values + n);
    }
    std::nth_element(kept.begin(), kept.begin() + (k - 1), kept.end());
    kept.resize(k);
    return kept;
}

} // namespace dcprbf
