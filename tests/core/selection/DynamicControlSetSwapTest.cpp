// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the error-guided swap pieces of DynamicControlSet: Rippa's
// leave-one-out errors equal brute-force removal, a constant-size swap equals
// a fresh set, the join and leave choices, undo, and the blended interpolant.
#include "DynamicControlSet.hpp"
#include "KernelCases.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <cmath>

using namespace dcprbf;
using test::randomPoints;
using test::smoothField;

namespace
{

using Index = Eigen::Index;

DynamicControlSet makeSet(const Points& cand, const RadialKernel& k, bool poly, int dim,
    DynamicControlSet::Options o = {})
{
    return DynamicControlSet(cand, std::vector<char>(cand.rows(), 1), k, poly, dim, o);
}

std::vector<Index> everyThird(Index n)
{
    std::vector<Index> idx;
    for (Index i = 0; i < n; i += 3) idx.push_back(i);
    return idx;
}

Values fieldFor(const Points& x, int dim)
{
    Values v = smoothField(x);
    if (dim == 2) v.col(2).setZero();
    return v;
}

class LeaveOneOut : public ::testing::TestWithParam<test::KernelCase> {};

// e_j = d_j - s_{-j}(x_j), with s_{-j} the interpolant without centre j
TEST_P(LeaveOneOut, EqualsBruteForceRemoval)
{
    const auto [name, poly, dim] = GetParam();
    if (RadialKernel::fromName(name, 1.0).needsPolynomial() && !poly)
    {
        GTEST_SKIP() << name << " needs the polynomial";
    }
    const RadialKernel k = RadialKernel::fromName(name, test::testRadius(name, 0.7));
    const Points cand = randomPoints(90, dim, 3);
    const Values v = fieldFor(cand, dim);
    DynamicControlSet s = makeSet(cand, k, poly, dim);
    s.reset(everyThird(cand.rows()));
    const Values loo = s.leaveOneOutErrors(v);
    ASSERT_EQ(loo.rows(), s.size());
    const double scale = v.cwiseAbs().maxCoeff();
    for (Index j = 0; j < s.size(); j += 4)
    {
        std::vector<Index> rest(s.indices());
        const Index left = rest[j];
        rest.erase(rest.begin() + j);
        DynamicControlSet without = makeSet(cand, k, poly, dim);
        without.reset(rest);
        without.solve(v);
        const Values sj = without.evaluator().evaluate(cand.row(left));
        const Eigen::RowVector3d brute = v.row(left) - sj.row(0);
        EXPECT_LT((loo.row(j) - brute).norm(), 1e-7*scale + 1e-6*brute.norm())
            << name << " poly " << poly << " " << dim << "D centre " << j;
    }
}

// The leave-one-out errors after the set changed (a swap, a state restored,
// a swap kept) are those of a set made afresh: the inverse diagonal kept
// between calls is never that of another set; bit for bit on the same one
TEST(LeaveOneOut, AfterChangesEqualsAFreshSet)
{
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.6);
    const Points cand = randomPoints(200, 3, 7);
    const Values v = fieldFor(cand, 3);
    DynamicControlSet s = makeSet(cand, k, true, 3);
    s.reset(everyThird(cand.rows()));
    const auto fresh = [&]()
    {
        DynamicControlSet f = makeSet(cand, k, true, 3);
        f.reset(s.indices());
        return f.leaveOneOutErrors(v);
    };
    const Values first = s.leaveOneOutErrors(v);
    EXPECT_TRUE(s.leaveOneOutErrors(v) == first);
    const DynamicControlSet::State before(s.state());
    ASSERT_TRUE(s.swap(1, s.indices()[5]));
    const Values swapped = s.leaveOneOutErrors(v);
    EXPECT_LT((swapped - fresh()).cwiseAbs().maxCoeff(), 1e-9*v.cwiseAbs().maxCoeff());
    EXPECT_GT((swapped.topRows(5) - first.topRows(5)).cwiseAbs().maxCoeff(), 0.0);
    s.restore(before);
    EXPECT_TRUE(s.leaveOneOutErrors(v) == first);
    ASSERT_TRUE(s.swap(2, s.indices()[10]));
    EXPECT_LT((s.leaveOneOutErrors(v) - fresh()).cwiseAbs().maxCoeff(), 1e-9*v.cwiseAbs().maxCoeff());
}

// The same over 100 centres: the inverse factor's diagonal is computed in
// blocks of 32 columns (the centres at and around the blocks' edges)
TEST(LeaveOneOut, OverSeveralBlocksEqualsBruteForceRemoval)
{
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.6);
    const Points cand = randomPoints(300, 3, 5);
    const Values v = fieldFor(cand, 3);
    DynamicControlSet s = makeSet(cand, k, true, 3);
    s.reset(everyThird(cand.rows()));
    ASSERT_EQ(s.size(), 100);
    const Values loo = s.leaveOneOutErrors(v);
    const double scale = v.cwiseAbs().maxCoeff();
    for (const Index j : {0, 1, 31, 32, 33, 63, 64, 95, 96, 99})
    {
        std::vector<Index> rest(s.indices());
        const Index left = rest[j];
        rest.erase(rest.begin() + j);
        DynamicControlSet without = makeSet(cand, k, true, 3);
        without.reset(rest);
        without.solve(v);
        const Values sj = without.evaluator().evaluate(cand.row(left));
        const Eigen::RowVector3d brute = v.row(left) - sj.row(0);
        EXPECT_LT((loo.row(j) - brute).norm(), 1e-7*scale + 1e-6*brute.norm()) << "centre " << j;
    }
}

INSTANTIATE_TEST_SUITE_P(KernelsPolyDim, LeaveOneOut, ::testing::ValuesIn(test::kernelCases()),
    test::kernelCaseName);

struct SwapFixture : ::testing::Test
{
    Points cand = randomPoints(200, 3, 9);
    Values v = smoothField(cand);
    RadialKernel k = RadialKernel::fromName("WendlandC2", 0.6);
};

TEST_F(SwapFixture, ConstantSizeSwapEqualsAFreshSet)
{
    DynamicControlSet::Options o;
    o.maxPoints = 67;   // at maxPoints: a swap still happens
    o.protectSteps = 0;
    DynamicControlSet s = makeSet(cand, k, true, 3, o);
    s.reset(everyThird(cand.rows()));
    ASSERT_EQ(s.size(), 67);
    ASSERT_TRUE(s.swap(4, 9));
    EXPECT_EQ(s.size(), 67);
    EXPECT_TRUE(s.contains(4));
    EXPECT_FALSE(s.contains(9));
    EXPECT_EQ(s.indices().back(), 4);
    DynamicControlSet fresh = makeSet(cand, k, true, 3);
    fresh.reset(s.indices());
    s.solve(v);
    fresh.solve(v);
    EXPECT_LT((s.evaluator().evaluate(cand) - fresh.evaluator().evaluate(cand)).cwiseAbs().maxCoeff(),
        1e-10*v.cwiseAbs().maxCoeff());
    EXPECT_THROW(s.swap(4, 9), Error);   // 4 is a member, 9 is not
}

TEST_F(SwapFixture, JoinsTheWorstOfTheNearestAndLeavesTheCheapest)
{
    DynamicControlSet::Options o;
    o.protectSteps = 0;
    DynamicControlSet s = makeSet(cand, k, true, 3, o);
    s.reset(everyThird(cand.rows()));
    s.solve(v);
    const Values error = v - s.evaluator().evaluate(cand);
    const Eigen::RowVector3d x(0.4, 0.5, 0.6);
    const int kNear = 6;
    // brute force: the kNear nearest non-members, the largest error among them
    std::vector<std::pair<double, Index>> byDistance;
    for (Index i = 0; i < cand.rows(); ++i)
    {
        if (!s.contains(i)) byDistance.emplace_back((cand.row(i) - x).squaredNorm(), i);
    }
    std::sort(byDistance.begin(), byDistance.end());
    Index expected = -1;
    double best = 0, largest = 0;
    for (int r = 0; r < kNear; ++r)
    {
        const double e = error.row(byDistance[r].second).norm();
        const double score = e/std::sqrt(byDistance[r].first);
        if (score > best) { best = score; expected = byDistance[r].second; }
        largest = std::max(largest, e);
    }
    EXPECT_EQ(s.mostInaccurateNear(x, v, kNear, 0.0), expected);
    // nothing above the floor (the errors as above to a few ulps)
    EXPECT_EQ(s.mostInaccurateNear(x, v, kNear, largest*(1 + 1e-9)), -1);
    EXPECT_THROW(s.mostInaccurateNear(x, v.topRows(3), kNear, 0.0), Error);
    // k 0: none; k beyond the non-members: the best of the maxTries
    // nearest (the search's cap)
    EXPECT_EQ(s.mostInaccurateNear(x, v, 0, 0.0), -1);
    Index bestOfAll = -1;
    double bestAll = 0;
    for (std::size_t r = 0; r < byDistance.size() && r < std::size_t(o.maxTries); ++r)
    {
        const auto& di = byDistance[r];
        const double score = error.row(di.second).norm()/std::sqrt(di.first);
        if (score > bestAll) { bestAll = score; bestOfAll = di.second; }
    }
    EXPECT_EQ(s.mostInaccurateNear(x, v, int(cand.rows()) + 5, 0.0), bestOfAll);

    const Values loo = s.leaveOneOutErrors(v);
    const std::vector<Index> order = s.removalOrder(loo);
    ASSERT_EQ(Index(order.size()), s.size());
    for (std::size_t r = 1; r < order.size(); ++r)
    {
        const auto pos = [&](Index c)
        {
            return std::find(s.indices().begin(), s.indices().end(), c) - s.indices().begin();
        };
        EXPECT_LE(loo.row(pos(order[r - 1])).norm(), loo.row(pos(order[r])).norm());
    }
}

TEST_F(SwapFixture, RemovalOrderSkipsProtectedAndFixedPoints)
{
    std::vector<char> removable(cand.rows(), 1);
    removable[0] = 0;
    DynamicControlSet::Options o;
    o.protectSteps = 2;
    DynamicControlSet s(cand, removable, k, true, 3, o);
    s.reset(everyThird(cand.rows()));   // ages = protectSteps: removable
    ASSERT_TRUE(s.swap(1, 3));          // 1 joins with age 0: protected
    const std::vector<Index> order = s.removalOrder(s.leaveOneOutErrors(v));
    EXPECT_EQ(std::count(order.begin(), order.end(), 0), 0);
    EXPECT_EQ(std::count(order.begin(), order.end(), 1), 0);
    EXPECT_EQ(Index(order.size()), s.size() - 2);
}

// dim+1 centres (the fewest the linear polynomial takes: a legal maxPoints)
// each needed by the polynomial: B_jj = 0. Their leave-one-out errors are
// infinite without dividing by zero (traps on, as OpenFOAM's FOAM_SIGFPE
// sets them: a division by zero would end the test with SIGFPE), none is a
// leaving candidate; with one centre more, every centre is (finite errors)
TEST(LeaveOneOut, CentresThePolynomialNeedsCannotLeave)
{
    for (const int dim : {2, 3})
    {
        const Points cand = randomPoints(40, dim, 5);
        const Values v = fieldFor(cand, dim);
        const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.8);
        DynamicControlSet::Options o;
        o.protectSteps = 0;
        for (const Index n : {Index(dim + 1), Index(dim + 2)})
        {
            DynamicControlSet s = makeSet(cand, k, true, dim, o);
            std::vector<Index> idx;
            for (Index i = 0; i < n; ++i) idx.push_back(4*i);
            s.reset(idx);
            s.solve(v);
            #ifdef FE_DIVBYZERO
            const int traps = FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW;
            std::feclearexcept(FE_ALL_EXCEPT);
            const int before = fegetexcept();
            feenableexcept(traps);
            #endif
            const Values loo = s.leaveOneOutErrors(v);
            const std::vector<Index> order = s.removalOrder(loo);
            #ifdef FE_DIVBYZERO
            fedisableexcept(traps & ~before);
            #endif
            ASSERT_EQ(loo.rows(), n);
            if (n == dim + 1)
            {
                for (Index j = 0; j < n; ++j)
                {
                    EXPECT_TRUE(std::isinf(loo(j, 0))) << dim << "D, centre " << j;
                }
                EXPECT_TRUE(order.empty()) << dim << "D: " << order.size() << " could leave";
            }
            else
            {
                EXPECT_TRUE(loo.allFinite()) << dim << "D";
                EXPECT_EQ(Index(order.size()), n) << dim << "D";
            }
        }
    }
}

TEST_F(SwapFixture, RestoreUndoesATrialSwap)
{
    DynamicControlSet s = makeSet(cand, k, true, 3);
    s.reset(everyThird(cand.rows()));
    s.solve(v);
    const Values before = s.evaluator().evaluate(cand);
    const DynamicControlSet::State st = s.state();
    ASSERT_TRUE(s.swap(5, 6));
    s.restore(st);
    EXPECT_TRUE(s.contains(6));
    EXPECT_FALSE(s.contains(5));
    s.solve(v);
    EXPECT_EQ((s.evaluator().evaluate(cand) - before).cwiseAbs().maxCoeff(), 0.0);
}

TEST_F(SwapFixture, BlendIsTheConvexCombinationOfBothInterpolants)
{
    DynamicControlSet s = makeSet(cand, k, true, 3);
    s.reset(everyThird(cand.rows()));
    s.solve(v);
    const Values before = s.evaluator().evaluate(cand);
    const DynamicControlSet::State from = s.state();
    ASSERT_TRUE(s.swap(5, 6));
    ASSERT_TRUE(s.swap(8, 12));
    s.solve(v);
    const Values after = s.evaluator().evaluate(cand);
    const double tol = 1e-12*v.cwiseAbs().maxCoeff();
    for (const double w : {0.0, 0.25, 1.0})
    {
        s.solveBlended(v, from, w);
        const Values blend = s.evaluator().evaluate(cand);
        EXPECT_LT((blend - ((1 - w)*before + w*after)).cwiseAbs().maxCoeff(), tol) << "w " << w;
    }
}

} // namespace

namespace
{

// The paper's rule at a fixed size (minPoints = maxPoints): the nearest
// non-member to the worst place joins and the nearest member to the best
// place leaves, in one update
TEST(SwapNearest, WorksAtFixedSize)
{
    const Points cand = randomPoints(150, 3, 12);
    DynamicControlSet::Options o;
    o.minPoints = 50;
    o.maxPoints = 50;
    DynamicControlSet s = makeSet(cand, RadialKernel::fromName("WendlandC2", 0.6), true, 3, o);
    s.reset(everyThird(cand.rows()));
    ASSERT_EQ(s.size(), 50);
    const Eigen::RowVector3d worst(0.2, 0.3, 0.4), best(0.8, 0.7, 0.6);
    Index in = -1, out = -1;
    double dIn = 1e300, dOut = 1e300;
    for (Index i = 0; i < cand.rows(); ++i)
    {
        const double dw = (cand.row(i) - worst).squaredNorm();
        const double db = (cand.row(i) - best).squaredNorm();
        if (!s.contains(i) && dw < dIn) { dIn = dw; in = i; }
        if (s.contains(i) && db < dOut) { dOut = db; out = i; }
    }
    EXPECT_EQ(s.addNearest(worst), -1);        // at maxPoints: no addition
    EXPECT_EQ(s.removeNearest(best), -1);      // at minPoints: no removal
    ASSERT_TRUE(s.swapNearest(worst, best));
    EXPECT_EQ(s.size(), 50);
    EXPECT_TRUE(s.contains(in));
    EXPECT_FALSE(s.contains(out));
}

} // namespace
