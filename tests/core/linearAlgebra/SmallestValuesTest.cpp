// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of smallestValues: the k smallest values, as a full sort gives
// them, for sizes and k around its sampled path's limits, with ties, sorted
// and reverse-sorted input (a sample that misjudges its bound) and NaN-free
// negative values.
#include "SmallestValues.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace dcprbf;

namespace
{

void check(const std::vector<double>& v, std::size_t k, const char* what)
{
    std::vector<double> got = smallestValues(v.data(), v.size(), k);
    std::vector<double> all(v);
    std::sort(all.begin(), all.end());
    all.resize(std::min(k, v.size()));
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, all) << what << ": n " << v.size() << " k " << k;
}

} // namespace


TEST(SmallestValues, EqualTheFirstValuesOfASort)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.5, 1.0);
    for (const std::size_t n : {0u, 1u, 100u, 1023u, 1024u, 5000u, 100000u})
    {
        std::vector<double> v(n);
        for (double& x : v) x = u(rng);
        for (const std::size_t k : {std::size_t(0), std::size_t(1), n/50, n/5, n/4, n/2, n, n + 3})
        {
            check(v, k, "random");
        }
        // ties: values on a coarse grid
        for (double& x : v) x = std::floor(8*x)/8;
        for (const std::size_t k : {std::size_t(1), n/50, n/5})
        {
            check(v, k, "ties");
        }
        // sorted both ways: the strided sample sees an extreme of each stretch
        std::sort(v.begin(), v.end());
        check(v, n/50, "ascending");
        std::reverse(v.begin(), v.end());
        check(v, n/50, "descending");
        // the small values between two samples (the sample's bound is
        // every value), and the samples alone small (the bound too low:
        // the whole set is selected instead)
        std::vector<double> w(n, 1.0);
        for (std::size_t i = 1; i < n && i < 60; ++i) w[i] = -double(i);
        check(w, std::min<std::size_t>(n, 50), "between samples");
        std::vector<double> s(n, 1.0);
        for (std::size_t i = 0; i < n; i += 64) s[i] = -1.0 - double(i);
        check(s, n/5, "samples alone small");
    }
}
