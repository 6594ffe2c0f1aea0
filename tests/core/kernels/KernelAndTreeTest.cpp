// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the kernels' formulas and of the kd-tree.
#include "PointTree.hpp"
#include "RadialKernel.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace dcprbf;

namespace
{

TEST(RadialKernel, WendlandC2Formula)
{
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 2.0);
    for (double r : {0.0, 0.3, 1.0, 1.7, 1.999})
    {
        const double xi = r/2.0;
        EXPECT_NEAR(k(r), std::pow(1 - xi, 4)*(4*xi + 1), 1e-15);
    }
    EXPECT_EQ(k(2.0), 0.0);
    EXPECT_EQ(k(7.0), 0.0);
}

TEST(RadialKernel, AllKernelsNamedAndNormalised)
{
    for (const auto& name : RadialKernel::names())
    {
        const RadialKernel k = RadialKernel::fromName(name, 1.5);
        EXPECT_EQ(k.name(), name);
        if (name == "TPS")
        {
            EXPECT_EQ(k(0.0), 0.0);
            EXPECT_NEAR(k(3.0), 4.0*std::log(2.0), 1e-14);
            EXPECT_FALSE(k.positiveDefinite());
        }
        else
        {
            EXPECT_NEAR(k(0.0), 1.0, 1e-15) << name;
            EXPECT_TRUE(k.positiveDefinite());
            // decreasing in r
            EXPECT_GT(k(0.2), k(0.7)) << name;
        }
        EXPECT_EQ(k.compact(), name.rfind("Wendland", 0) == 0);
    }
}

TEST(RadialKernel, WendlandSmoothAtSupportEdge)
{
    // C2 and smoother: value and slope vanish at r = R
    for (const char* name : {"WendlandC2", "WendlandC4", "WendlandC6"})
    {
        const RadialKernel k = RadialKernel::fromName(name, 1.0);
        const double h = 1e-4;
        EXPECT_LT(k(1 - h), 1e-7) << name;
        EXPECT_LT((k(1 - h) - k(1 - 2*h))/h, 1e-5) << name;
    }
}

TEST(PointTree, RadiusSearchEqualsBruteForce)
{
    const Points p = test::randomPoints(2000, 3, 11);
    const Points q = test::randomPoints(200, 3, 12);
    const PointTree tree(p);
    const double R = 0.15;
    for (Eigen::Index i = 0; i < q.rows(); ++i)
    {
        std::set<std::size_t> fromTree, brute;
        tree.forEachWithin(q.row(i).data(), R, [&](std::size_t j, double d2)
        {
            EXPECT_NEAR(d2, (p.row(j) - q.row(i)).squaredNorm(), 1e-14);
            fromTree.insert(j);
        });
        for (Eigen::Index j = 0; j < p.rows(); ++j)
        {
            if ((p.row(j) - q.row(i)).norm() < R) brute.insert(j);
        }
        EXPECT_EQ(fromTree, brute);
    }
}

TEST(PointTree, AnyWithinEqualsBruteForce)
{
    // radii around the typical spacing: some queries with points in reach,
    // some without (both counted)
    const Points p = test::randomPoints(500, 3, 15);
    const Points q = test::randomPoints(400, 3, 16);
    const PointTree tree(p);
    int yes = 0, no = 0;
    for (const double R : {0.02, 0.05, 0.1})
    {
        for (Eigen::Index i = 0; i < q.rows(); ++i)
        {
            const bool brute = (p.rowwise() - q.row(i)).rowwise().norm().minCoeff() < R;
            EXPECT_EQ(tree.anyWithin(q.row(i).data(), R), brute) << i << ' ' << R;
            (brute ? yes : no)++;
        }
    }
    EXPECT_GT(yes, 100);
    EXPECT_GT(no, 100);
}

TEST(PointTree, NearestEqualsBruteForce)
{
    const Points p = test::randomPoints(500, 3, 13);
    const Points q = test::randomPoints(100, 3, 14);
    const PointTree tree(p);
    for (Eigen::Index i = 0; i < q.rows(); ++i)
    {
        double d2 = 0;
        const std::size_t j = tree.nearest(q.row(i).data(), d2);
        Eigen::Index jb = 0;
        (p.rowwise() - q.row(i)).rowwise().squaredNorm().minCoeff(&jb);
        EXPECT_EQ(Eigen::Index(j), jb);
        EXPECT_NEAR(d2, (p.row(jb) - q.row(i)).squaredNorm(), 1e-15);
    }
    const PointTree empty{Points(0, 3)};
    double d2;
    EXPECT_THROW(empty.nearest(q.row(0).data(), d2), Error);
}

} // namespace
