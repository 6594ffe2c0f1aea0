// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of mortonOrder: a permutation along the Z-curve.
#include "MortonOrder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace dcprbf;

TEST(MortonOrder, CubeCornersInBitOrderAndAPermutation)
{
    // the corners of a box, listed backwards: Morton order is x + 2y + 4z
    std::vector<double> x;
    for (int b = 7; b >= 0; --b)
    {
        x.insert(x.end(), {double(b & 1), 2.0*((b >> 1) & 1), 0.5*((b >> 2) & 1)});
    }
    const std::vector<int> order(mortonOrder(x.data(), 8));
    for (int k = 0; k < 8; ++k) EXPECT_EQ(order[k], 7 - k) << k;

    // random points: a permutation; equal points keep their index order
    std::mt19937 gen(1);
    std::uniform_real_distribution<double> u(-5, 5);
    std::vector<double> y(3*1000);
    for (double& v : y) v = u(gen);
    std::copy(y.begin(), y.begin() + 3, y.begin() + 3*500);
    std::vector<int> p(mortonOrder(y.data(), 1000));
    const auto at0 = std::find(p.begin(), p.end(), 0), at500 = std::find(p.begin(), p.end(), 500);
    EXPECT_EQ(at500 - at0, 1);
    std::sort(p.begin(), p.end());
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(p[i], i);
}
