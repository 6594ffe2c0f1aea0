// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of BlockBoxIndex: its radius queries find exactly the points a
// brute-force search finds (strictly within, ascending, the same squared
// distances), in Morton order and in a random order, for sizes around the
// block size, and the same points as PointTree.
#include "BlockBoxIndex.hpp"
#include "MortonOrder.hpp"
#include "PointTree.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

using namespace dcprbf;

namespace
{

//- (index, squared distance) of the points strictly within r of q
std::vector<std::pair<std::size_t, double>> bruteForce
(
    const std::vector<double>& x,
    const double* q,
    double r
)
{
    std::vector<std::pair<std::size_t, double>> found;
    for (std::size_t i = 0; 3*i < x.size(); ++i)
    {
        const double d0 = x[3*i] - q[0], d1 = x[3*i + 1] - q[1], d2 = x[3*i + 2] - q[2];
        const double d = d0*d0 + d1*d1 + d2*d2;
        if (d < r*r) found.emplace_back(i, d);
    }
    return found;
}

std::vector<std::pair<std::size_t, double>> query
(
    const BlockBoxIndex& index,
    const double* q,
    double r
)
{
    std::vector<std::pair<std::size_t, double>> found;
    index.forEachWithin(q, r, [&](std::size_t i, double d) { found.emplace_back(i, d); });
    return found;
}

//- n random points in the unit cube, in Morton order or not, flat
std::vector<double> flatPoints(int n, bool morton, unsigned seed)
{
    const Points p = test::randomPoints(n, 3, seed);
    std::vector<double> x(3*std::size_t(n));
    for (int i = 0; i < n; ++i) for (int k = 0; k < 3; ++k) x[3*i + k] = p(i, k);
    if (!morton || n == 0) return x;
    std::vector<double> y(x.size());
    const std::vector<int> order = mortonOrder(x.data(), std::size_t(n));
    for (int i = 0; i < n; ++i) for (int k = 0; k < 3; ++k) y[3*i + k] = x[3*order[i] + k];
    return y;
}

} // namespace


TEST(BlockBoxIndex, FindsWhatABruteForceSearchFinds)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-0.2, 1.2);
    for (const int n : {0, 1, 63, 64, 65, 4095, 4096, 4097, 20000})
    {
        for (const bool morton : {true, false})
        {
            const std::vector<double> x = flatPoints(n, morton, 11 + n);
            const BlockBoxIndex index(x.data(), std::size_t(n));
            ASSERT_EQ(index.size(), std::size_t(n));
            for (int k = 0; k < 40; ++k)
            {
                const double q[3] = {u(rng), u(rng), u(rng)};
                for (const double r : {0.0, 0.01, 0.05, 0.2, 2.0})
                {
                    EXPECT_EQ(query(index, q, r), bruteForce(x, q, r))
                        << "n " << n << (morton ? " (Morton)" : " (random order)") << " r " << r;
                }
            }
        }
    }
}


TEST(BlockBoxIndex, PointsAtTheRadiusAreLeftOut)
{
    // a grid of spacing 1/8 (exact in binary): from a grid point, the
    // neighbours at exactly 1/8 are not strictly within it
    std::vector<double> x;
    for (int i = 0; i < 9; ++i) for (int j = 0; j < 9; ++j) for (int k = 0; k < 9; ++k)
    {
        x.insert(x.end(), {i/8.0, j/8.0, k/8.0});
    }
    const BlockBoxIndex index(x.data(), x.size()/3);
    const double q[3] = {0.5, 0.5, 0.5};
    const auto found = query(index, q, 0.125);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].second, 0.0);
    EXPECT_EQ(query(index, q, std::nextafter(0.125, 1.0)).size(), 7u);
}


TEST(BlockBoxIndex, FindsThePointsAKdTreeFinds)
{
    const int n = 30000;
    const std::vector<double> x = flatPoints(n, true, 5);
    Points p(n, 3);
    for (int i = 0; i < n; ++i) for (int k = 0; k < 3; ++k) p(i, k) = x[3*i + k];
    const BlockBoxIndex index(x.data(), std::size_t(n));
    const PointTree tree(p);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (int k = 0; k < 50; ++k)
    {
        const double q[3] = {u(rng), u(rng), u(rng)};
        const double r = 0.02 + 0.1*u(rng);
        std::vector<std::pair<std::size_t, double>> fromTree;
        tree.forEachWithin(q, r, [&](std::size_t i, double d) { fromTree.emplace_back(i, d); });
        std::sort(fromTree.begin(), fromTree.end());
        EXPECT_EQ(query(index, q, r), fromTree) << "query " << k;
    }
}
