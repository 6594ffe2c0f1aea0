// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of DynamicControlSet: the nearest-point rules, the guards, and
// that after swaps the interpolant equals a fresh solve on the same set.
#include "DynamicControlSet.hpp"
#include "RbfInterpolant.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

using namespace dcprbf;
using test::randomPoints;
using test::smoothField;

namespace
{

using Index = Eigen::Index;

struct Fixture
{
    Points cand = randomPoints(300, 3, 21);
    std::vector<char> removable = std::vector<char>(300, 1);
    RadialKernel kernel = RadialKernel::fromName("WendlandC2", 0.6);

    DynamicControlSet make(DynamicControlSet::Options o = {}) const
    {
        DynamicControlSet s(cand, removable, kernel, true, 3, o);
        std::vector<Index> first;
        for (Index i = 0; i < 40; ++i) first.push_back(7*i);
        s.reset(first);
        return s;
    }
};

Index bruteNearest(const Points& p, const Eigen::RowVector3d& x, const std::function<bool(Index)>& ok)
{
    Index best = -1;
    double d = 1e300;
    for (Index i = 0; i < p.rows(); ++i)
    {
        if (ok(i) && (p.row(i) - x).squaredNorm() < d)
        {
            d = (p.row(i) - x).squaredNorm();
            best = i;
        }
    }
    return best;
}

TEST(DynamicControlSet, AddsTheNearestNonMember)
{
    Fixture f;
    DynamicControlSet s = f.make();
    const Eigen::RowVector3d x(0.5, 0.5, 0.5);
    const Index expected = bruteNearest(f.cand, x, [&](Index i) { return !s.contains(i); });
    EXPECT_EQ(s.addNearest(x), expected);
    EXPECT_TRUE(s.contains(expected));
    EXPECT_EQ(s.size(), 41);
}

TEST(DynamicControlSet, RemovesTheNearestRemovableOldEnoughMember)
{
    Fixture f;
    for (Index i = 0; i < 300; i += 2) f.removable[i] = 0;  // even: static
    DynamicControlSet s = f.make({0, 1000, 2, 8});
    const Eigen::RowVector3d x(0.2, 0.7, 0.4);
    // a point added now is protected for 2 steps
    const Index added = s.addNearest(x);
    const auto ok = [&](Index i) { return s.contains(i) && f.removable[i] && i != added; };
    const Index expected = bruteNearest(f.cand, x, ok);
    const Index removed = s.removeNearest(x);
    EXPECT_EQ(removed, expected);
    EXPECT_NE(removed, added);
    EXPECT_EQ(removed % 2, 1);
    EXPECT_FALSE(s.contains(removed));
}

TEST(DynamicControlSet, NeverBelowMinPointsOrAboveMaxPoints)
{
    Fixture f;
    DynamicControlSet s = f.make({40, 41, 0, 8});
    EXPECT_EQ(s.removeNearest({0.5, 0.5, 0.5}), -1);
    EXPECT_GE(s.addNearest({0.5, 0.5, 0.5}), 0);
    EXPECT_EQ(s.addNearest({0.1, 0.5, 0.5}), -1);
    EXPECT_EQ(s.size(), 41);
}

TEST(DynamicControlSet, SwapsEqualAFreshSolve)
{
    Fixture f;
    DynamicControlSet s = f.make({0, 1000, 0, 8});
    const Values v = smoothField(f.cand);
    for (int k = 0; k < 12; ++k)
    {
        const Eigen::RowVector3d x = randomPoints(1, 3, 100 + k).row(0);
        ASSERT_GE(s.addNearest(x), 0);
        ASSERT_GE(s.removeNearest(f.cand.row((37*k) % 300)), 0);
        s.nextStep();
    }
    s.solve(v);

    Points c(s.size(), 3);
    Values vc(s.size(), 3);
    for (Index k = 0; k < s.size(); ++k)
    {
        c.row(k) = f.cand.row(s.indices()[k]);
        vc.row(k) = v.row(s.indices()[k]);
    }
    RbfInterpolant fresh(f.kernel, true, 3);
    fresh.fit(c, vc);
    const Points x = randomPoints(200, 3, 5);
    const Values a = s.evaluator().evaluate(x);
    const Values b = fresh.evaluate(x);
    EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-10*b.cwiseAbs().maxCoeff());
    // and exact at the control points
    EXPECT_LT((s.evaluator().evaluate(c) - vc).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(DynamicControlSet, Errors)
{
    Fixture f;
    EXPECT_THROW(DynamicControlSet(f.cand, std::vector<char>(3, 1), f.kernel, true, 3, {}), Error);
    EXPECT_THROW(DynamicControlSet(f.cand, f.removable, f.kernel, true, 3, {50, 10, 3, 8}), Error);
    DynamicControlSet s(f.cand, f.removable, f.kernel, true, 3, {});
    EXPECT_THROW(s.reset({0, 1, 400}), Error);
    EXPECT_THROW(s.reset({0, 1, 2}), Error);       // too few for the polynomial
    s.reset({0, 1, 2, 3, 4});
    EXPECT_THROW(s.solve(Values::Zero(5, 3)), Error);
}

} // namespace

namespace
{

TEST(DynamicControlSet, AddByIndexAndAges)
{
    Fixture f;
    DynamicControlSet s = f.make({0, 41, 3, 8});
    EXPECT_THROW(s.add(0), Error);          // already in (0 = 7*0)
    EXPECT_THROW(s.add(300), Error);        // out of range
    EXPECT_TRUE(s.add(1));
    EXPECT_FALSE(s.add(2));                 // maxPoints reached
    EXPECT_EQ(s.ages().back(), 0);
    s.nextStep();
    EXPECT_EQ(s.ages().back(), 1);
    std::vector<int> a(s.size(), 5);
    s.setAges(a);
    EXPECT_EQ(s.ages().front(), 5);
    EXPECT_THROW(s.setAges({1, 2}), Error);
}

} // namespace
