// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of DistinctRows: equal rows once, in order of first occurrence.
#include "DistinctRows.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace dcprbf;

TEST(DistinctRows, EqualRowsOnceInOrderOfFirstOccurrence)
{
    Points p(6, 3);
    p << 1, 2, 0,
         0, 0, 0,
         1, 2, 0,
         1, 2, 1e-300,
         0, 0, 0,
         -3, 4, 5;
    const DistinctRows d(p);
    ASSERT_EQ(d.points().rows(), 4);
    EXPECT_EQ(d.size(), 6u);
    const Eigen::Index expected[6] = {0, 1, 0, 2, 1, 3};
    for (Eigen::Index i = 0; i < 6; ++i)
    {
        EXPECT_EQ(d.of(i), expected[i]) << i;
        EXPECT_TRUE((d.points().row(d.of(i)).array() == p.row(i).array()).all()) << i;
    }
}


TEST(DistinctRows, TwinPlanesHalveTheRows)
{
    // a 2D mesh's points in plane coordinates: every point twice, shuffled
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-1, 1);
    const Eigen::Index n = 500;
    Points p(2*n, 3);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        p.row(i) << u(gen), u(gen), 0;
        p.row(n + i) = p.row(i);
    }
    std::vector<Eigen::Index> perm(std::size_t(2*n));
    for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = Eigen::Index(i);
    std::shuffle(perm.begin(), perm.end(), gen);
    Points q(2*n, 3);
    for (Eigen::Index i = 0; i < 2*n; ++i) q.row(i) = p.row(perm[std::size_t(i)]);

    const DistinctRows d(q);
    EXPECT_EQ(d.points().rows(), n);
    for (Eigen::Index i = 0; i < 2*n; ++i)
    {
        EXPECT_TRUE((d.points().row(d.of(i)).array() == q.row(i).array()).all()) << i;
    }
    // first occurrences in order: row of(i) is new only when larger than all before
    Eigen::Index next = 0;
    for (Eigen::Index i = 0; i < 2*n; ++i)
    {
        ASSERT_LE(d.of(i), next);
        if (d.of(i) == next) ++next;
    }
}


TEST(DistinctRows, RefusesAPointThatIsNotFinite)
{
    Points p(2, 3);
    p << 0, 0, 0,
         1, std::nan(""), 0;
    EXPECT_THROW(DistinctRows d(p), std::invalid_argument);
}
