// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of TrialSwaps, one step's error-guided trial swaps: a proposal
// swaps exactly one point in and one out (the join and leave choices of
// DynamicControlSet, after skip leaving points), undo() and abandon() put
// the set back bit for bit, end() counts the kept ones, and no candidate
// means no proposal and the set unchanged.
#include "TrialSwaps.hpp"
#include "SwapsTestSet.hpp"

#include <algorithm>
#include <iterator>
#include <vector>

using namespace dcprbf;

namespace
{

using Index = Eigen::Index;

//- The set's indices sorted
std::vector<Index> sorted(const DynamicControlSet& s)
{
    std::vector<Index> i(s.indices());
    std::sort(i.begin(), i.end());
    return i;
}

struct TrialSwapsFixture : test::SwapsTestSet
{
    const Eigen::RowVector3d worst{0.5, 0.4, 0.6};

    std::pair<Values, Eigen::MatrixX3d> coefficients() const
    {
        return SwapsTestSet::coefficients(set.state());
    }

    //- The set's indices, ages, coefficients and solved interpolant
    struct Snapshot
    {
        std::vector<Index> idx;
        std::vector<int> ages;
        std::pair<Values, Eigen::MatrixX3d> coef;
        Values values;
    };

    Snapshot snapshot() const
    {
        return {set.indices(), set.ages(), coefficients(), set.evaluator().evaluate(cand)};
    }

    //- The set as in the snapshot, bit for bit?
    void expectAsBefore(const Snapshot& b)
    {
        EXPECT_EQ(set.indices(), b.idx);
        EXPECT_EQ(set.ages(), b.ages);
        const auto c = coefficients();
        EXPECT_TRUE(c.first == b.coef.first) << "alpha bit for bit";
        EXPECT_TRUE(c.second == b.coef.second) << "beta bit for bit";
        set.solve(v);
        EXPECT_TRUE(set.evaluator().evaluate(cand) == b.values);
    }
};

TEST_F(TrialSwapsFixture, ProposeSwapsOneInAndOneOut)
{
    const std::vector<Index> before = sorted(set);
    // what the proposal should choose, from a copy of the set
    const Index in = set.mostInaccurateNear(worst, v, TrialSwaps::joinNeighbours, 1e-9*v.rowwise().norm().maxCoeff());
    ASSERT_GE(in, 0);
    const std::vector<Index> order = set.removalOrder(set.leaveOneOutErrors(v));
    ASSERT_FALSE(order.empty());

    TrialSwaps t(set);
    EXPECT_FALSE(t.started());
    ASSERT_TRUE(t.propose(worst, v, 0));
    EXPECT_TRUE(t.started());
    EXPECT_EQ(set.size(), Index(before.size()));
    const std::vector<Index> after = sorted(set);
    std::vector<Index> joined, left;
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(joined));
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(left));
    EXPECT_EQ(joined, std::vector<Index>{in});
    EXPECT_EQ(left, std::vector<Index>{order[0]});
    // the leaving point and its reach: the nearest remaining control point
    EXPECT_TRUE(t.leaving() == cand.row(order[0]));
    double reach = 1e300;
    for (const Index j : set.indices()) reach = std::min(reach, (cand.row(j) - t.leaving()).norm());
    EXPECT_EQ(t.leavingReach(), reach);
    EXPECT_GT(reach, 0.0);
    EXPECT_EQ(t.stepStart().indices.size(), before.size());
}

TEST_F(TrialSwapsFixture, SkipSkipsLeavingPoints)
{
    const std::vector<Index> order = set.removalOrder(set.leaveOneOutErrors(v));
    ASSERT_GT(order.size(), 3u);
    for (const int skip : {1, 3})
    {
        TrialSwaps t(set);
        ASSERT_TRUE(t.propose(worst, v, skip));
        EXPECT_FALSE(set.contains(order[skip])) << "skip " << skip;
        for (int r = 0; r < skip; ++r)
        {
            EXPECT_TRUE(set.contains(order[r])) << "skip " << skip << ": " << r << " skipped";
        }
        EXPECT_TRUE(t.leaving() == cand.row(order[skip]));
        t.undo();
        t.end();
    }
    // skipping every leaving point: none proposed, the set unchanged
    const std::vector<Index> idx = set.indices();
    TrialSwaps t(set);
    EXPECT_FALSE(t.propose(worst, v, int(order.size())));
    EXPECT_EQ(set.indices(), idx);
    EXPECT_FALSE(t.started());
}

TEST_F(TrialSwapsFixture, UndoRestoresTheExactState)
{
    const Snapshot before = snapshot();
    const std::vector<Index> idx = before.idx;
    TrialSwaps t(set);
    ASSERT_TRUE(t.propose(worst, v, 0));
    ASSERT_NE(set.indices(), idx);
    set.solve(v);   // the caller solves the proposal
    t.undo();
    expectAsBefore(before);
    EXPECT_TRUE(t.started()) << "undone, still this step's trials";
    EXPECT_EQ(t.end(), 0);
    EXPECT_FALSE(t.started()) << "none kept: the trials are over";
    EXPECT_EQ(set.indices(), idx);
}

TEST_F(TrialSwapsFixture, AbandonRestoresTheStepStartAcrossKeptTrials)
{
    const Snapshot before = snapshot();
    const std::vector<Index> idx = before.idx;
    TrialSwaps t(set);
    std::vector<Index> kept;
    for (int i = 0; i < 3; ++i)
    {
        ASSERT_TRUE(t.propose(worst + Eigen::RowVector3d(0.1*i, 0, 0), v, 0)) << i;
        set.solve(v);
        t.keep();
        kept = set.indices();
    }
    ASSERT_TRUE(t.propose(worst, v, 0));
    set.solve(v);
    t.undo();
    EXPECT_EQ(set.indices(), kept) << "undo: back to the last kept trial";
    EXPECT_EQ(t.end(), 3);
    ASSERT_TRUE(t.started());
    EXPECT_EQ(t.stepStart().indices, idx);
    t.abandon();
    EXPECT_FALSE(t.started());
    expectAsBefore(before);
}

TEST_F(TrialSwapsFixture, EndCountsTheKeptAndConfirmKeepsThem)
{
    TrialSwaps t(set);
    EXPECT_EQ(t.end(), 0) << "no trial";
    EXPECT_FALSE(t.started());
    ASSERT_TRUE(t.propose(worst, v, 0));
    set.solve(v);
    t.keep();
    ASSERT_TRUE(t.propose(worst, v, 0));
    set.solve(v);
    t.undo();
    ASSERT_TRUE(t.propose(worst, v, 1));
    set.solve(v);
    t.keep();
    const std::vector<Index> swapped = set.indices();
    EXPECT_EQ(t.end(), 2);
    EXPECT_TRUE(t.started());
    t.confirm();
    EXPECT_FALSE(t.started());
    EXPECT_EQ(set.indices(), swapped);
    // the next step counts afresh
    ASSERT_TRUE(t.propose(worst, v, 0));
    set.solve(v);
    t.keep();
    EXPECT_EQ(t.end(), 1);
}

TEST_F(TrialSwapsFixture, NoCandidateNoProposalTheSetUnchanged)
{
    const Snapshot before = snapshot();
    const std::vector<Index> idx = before.idx;
    TrialSwaps t(set);
    // no joining point: no error above the floor (values the set reproduces)
    set.solve(Values::Zero(cand.rows(), 3));
    EXPECT_FALSE(t.propose(worst, Values::Zero(cand.rows(), 3), 0));
    EXPECT_FALSE(t.started());
    expectAsBefore(before);
    // no leaving point: none removable
    DynamicControlSet fixed(cand, std::vector<char>(cand.rows(), 0), k, true, 3, DynamicControlSet::Options());
    fixed.reset(idx);
    fixed.solve(v);
    TrialSwaps tf(fixed);
    EXPECT_FALSE(tf.propose(worst, v, 0));
    EXPECT_FALSE(tf.started());
    EXPECT_EQ(fixed.indices(), idx);
    // no joining point: every candidate a control point
    std::vector<Index> all(cand.rows());
    for (Index i = 0; i < cand.rows(); ++i) all[i] = i;
    DynamicControlSet full(cand, std::vector<char>(cand.rows(), 1), k, true, 3, DynamicControlSet::Options());
    full.reset(all);
    full.solve(v);
    TrialSwaps ta(full);
    EXPECT_FALSE(ta.propose(worst, v, 0));
    EXPECT_EQ(full.indices(), all);
}

} // namespace
