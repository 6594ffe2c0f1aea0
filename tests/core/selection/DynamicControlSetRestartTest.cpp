// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of DynamicControlSet's fresh starts: taking over a greedy's
// factorization equals factorizing the same set, and refactorize() after
// updates gives bit for bit the state a restart (reset on the indices) gives.
#include "DynamicControlSet.hpp"
#include "GreedySelector.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

using namespace dcprbf;
using test::randomPoints;
using test::smoothField;

namespace
{

using Index = Eigen::Index;

const RadialKernel kernel = RadialKernel::fromName("WendlandC2", 0.6);

DynamicControlSet makeSet(const Points& cand)
{
    return DynamicControlSet(cand, std::vector<char>(cand.rows(), 1), kernel, true, 3, {});
}

//- The evaluator's values at the candidates after solving for v
Values solved(DynamicControlSet& s, const Values& v)
{
    s.solve(v);
    return s.evaluator().evaluate(s.candidates());
}

TEST(DynamicControlSetRestart, GreedyFactorizationTakenOverEqualsAFreshOne)
{
    const Points cand = randomPoints(300, 3, 5);
    const Values v = smoothField(cand);
    GreedyOptions o;
    o.tolerance = 1e-2;
    GreedyResult r = GreedySelector(kernel, true, 3, o).select(cand, v);
    ASSERT_TRUE(r.factorization);

    DynamicControlSet taken = makeSet(cand);
    taken.reset(r.selected, std::move(*r.factorization));
    DynamicControlSet fresh = makeSet(cand);
    fresh.reset(r.selected);
    EXPECT_EQ(taken.indices(), fresh.indices());
    const Values a = solved(taken, v), b = solved(fresh, v);
    EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-10*v.cwiseAbs().maxCoeff());
}

TEST(DynamicControlSetRestart, FactorizationOfTheWrongSizeIsRefused)
{
    const Points cand = randomPoints(100, 3, 6);
    GreedyOptions o;
    o.tolerance = 1e-2;
    GreedyResult r = GreedySelector(kernel, true, 3, o).select(cand, smoothField(cand));
    std::vector<Index> fewer(r.selected.begin(), r.selected.end() - 1);
    DynamicControlSet s = makeSet(cand);
    EXPECT_THROW(s.reset(fewer, std::move(*r.factorization)), Error);
}

TEST(DynamicControlSetRestart, RefactorizeAfterUpdatesEqualsARestartBitForBit)
{
    const Points cand = randomPoints(300, 3, 7);
    const Values v = smoothField(cand);
    std::vector<Index> first;
    for (Index i = 0; i < 40; ++i) first.push_back(7*i);

    DynamicControlSet running = makeSet(cand);
    running.reset(first);
    for (int step = 0; step < 5; ++step)
    {
        running.nextStep();
        ASSERT_GE(running.addNearest(cand.row(11*step + 3)), 0);
        ASSERT_GE(running.removeNearest(cand.row(13*step + 1)), 0);
    }
    const Values updated = solved(running, v);
    const std::vector<int> ages = running.ages();
    running.refactorize();
    EXPECT_EQ(running.ages(), ages);

    // what a restart does: a new set from the written indices and ages
    DynamicControlSet restarted = makeSet(cand);
    restarted.reset(running.indices());
    restarted.setAges(ages);

    const Values a = solved(running, v), b = solved(restarted, v);
    EXPECT_EQ((a - b).cwiseAbs().maxCoeff(), 0.0);
    // and the same interpolant as the updated factorization, to round-off
    EXPECT_LT((a - updated).cwiseAbs().maxCoeff(), 1e-10*v.cwiseAbs().maxCoeff());
}

} // namespace
