/*---------------------------------------------------------------------------*\
  dcpRBF tests: dcpRBFTrialState, the errorGuided trials' schedule and blend
  in the restart state (the schedule and the blend themselves:
  tests/core/swaps)
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFTrialState.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace Foam;

namespace
{

TEST(TrialState, ScheduleRoundTrip)
{
    dcprbf::TrialSchedule s(4, 16, 0.05);
    s.backOff();
    s.endStep(0.7);
    dictionary state;
    dcpRBFTrialState::write(s, state);
    EXPECT_EQ(state.get<label>("trialWait"), 3);
    EXPECT_EQ(state.get<label>("trialBackoff"), 8);
    EXPECT_EQ(state.get<scalar>("trialQuality"), 0.7);
    dcprbf::TrialSchedule r(4, 16, 0.05);
    dcpRBFTrialState::read(state, r);
    EXPECT_EQ(r.wait(), s.wait());
    EXPECT_EQ(r.backoff(), s.backoff());
    EXPECT_EQ(r.quality(), s.quality());
    EXPECT_TRUE(r.endWaitIfWorse(0.6));
    dcprbf::TrialSchedule fresh(4, 16, 0.05);
    dcpRBFTrialState::read(dictionary(), fresh);
    EXPECT_FALSE(fresh.waiting());
    EXPECT_EQ(fresh.backoff(), 4);
    EXPECT_EQ(fresh.quality(), 1);
}


TEST(TrialState, BlendRoundTripAndRemoval)
{
    // 40 points on a line in the plane: a set of every other one
    dcprbf::Points cand(40, 3);
    for (label i = 0; i < cand.rows(); ++i)
    {
        cand.row(i) << 0.025*i, 0.3*std::sin(0.2*i), 0;
    }
    dcprbf::DynamicControlSet set
    (
        cand, std::vector<char>(cand.rows(), 1),
        dcprbf::RadialKernel::fromName("WendlandC2", 0.5), true, 2,
        dcprbf::DynamicControlSet::Options()
    );
    std::vector<Eigen::Index> idx;
    for (label i = 0; i < cand.rows(); i += 2) idx.push_back(i);
    set.reset(idx);

    dcprbf::SwapBlend b(4);
    b.start(set.state());
    b.advance();
    dictionary state;
    dcpRBFTrialState::write(b, state);
    EXPECT_EQ(state.get<label>("blendStep"), 2);
    EXPECT_EQ(state.get<labelList>("blendFromIndices").size(), label(idx.size()));

    dcprbf::SwapBlend r(4);
    dcpRBFTrialState::read(state, set, r);
    ASSERT_TRUE(r.active());
    EXPECT_EQ(r.step(), 2);
    EXPECT_EQ(r.from().indices, idx);
    EXPECT_EQ(r.from().ages, set.ages());

    // no blend: the entries removed, none read back
    b.stop();
    dcpRBFTrialState::write(b, state);
    EXPECT_FALSE(state.found("blendStep"));
    EXPECT_FALSE(state.found("blendFromIndices"));
    EXPECT_FALSE(state.found("blendFromAges"));
    dcprbf::SwapBlend none(4);
    dcpRBFTrialState::read(state, set, none);
    EXPECT_FALSE(none.active());
}

} // End anonymous namespace


// ************************************************************************* //
