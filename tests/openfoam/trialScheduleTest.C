/*---------------------------------------------------------------------------*\
  dcpRBF tests: dcpRBFTrialSchedule, the errorGuided trials' back-off, wait
  and rescue, without a mesh
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFTrialSchedule.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- Steps waited after a back-off, given a minimum quality that never falls
label stepsWaited(dcpRBFTrialSchedule& s)
{
    label n = 0;
    while (s.waiting())
    {
        s.endStep(0.5);
        ++n;
    }
    return n;
}


TEST(TrialSchedule, BackOffDoublesUpToTheLongestWait)
{
    dcpRBFTrialSchedule s(4, 16, 0.05);
    EXPECT_FALSE(s.waiting());
    std::vector<label> waits;
    for (label i = 0; i < 5; ++i)
    {
        s.backOff();
        // the step that backed off ends as well
        s.endStep(0.5);
        waits.push_back(1 + stepsWaited(s));
    }
    EXPECT_EQ(waits, (std::vector<label>{4, 8, 16, 16, 16}));
}


TEST(TrialSchedule, AKeptSwapStartsTheBackOffOver)
{
    dcpRBFTrialSchedule s(2, 16, 0.05);
    s.backOff();
    s.endStep(0.5);
    stepsWaited(s);
    s.backOff();
    EXPECT_EQ(s.wait(), 4);
    s.endStep(0.5);
    stepsWaited(s);
    s.kept();
    s.endStep(0.5);
    s.backOff();
    EXPECT_EQ(s.wait(), 2);
}


TEST(TrialSchedule, AWaitEndsWhenTheMeshGetsWorseByMoreThanTheDrop)
{
    dcpRBFTrialSchedule s(8, 16, 0.05);
    s.backOff();
    s.endStep(0.6);      // the reference quality: the step that backed off
    EXPECT_TRUE(s.waiting());
    EXPECT_FALSE(s.endWaitIfWorse(0.56)) << "a fall of 0.04: still waiting";
    EXPECT_TRUE(s.waiting());
    EXPECT_TRUE(s.endWaitIfWorse(0.54)) << "a fall of 0.06 ends the wait";
    EXPECT_FALSE(s.waiting());
    EXPECT_FALSE(s.endWaitIfWorse(0.1)) << "no wait to end";
}


TEST(TrialSchedule, RestoreForgetsTheStepsBackOff)
{
    dcpRBFTrialSchedule s(4, 16, 0.05);
    s.backOff();
    s.endStep(0.9);
    const FixedList<label, 2> before(s.save());
    s.backOff();
    s.restore(before);
    EXPECT_EQ(s.wait(), 3);
    EXPECT_EQ(s.backoff(), 8);
    // the reference quality stays the one of the step that backed off
    s.endStep(0.2);
    EXPECT_TRUE(s.endWaitIfWorse(0.84));
}


TEST(TrialSchedule, RescueTrialsAndSkips)
{
    EXPECT_EQ(dcpRBFTrialSchedule::nTrials(false, 3), 3);
    EXPECT_EQ(dcpRBFTrialSchedule::nTrials(true, 3), 3*dcpRBFTrialSchedule::rescueSwapFactor);
    label skip = 0;
    EXPECT_FALSE(dcpRBFTrialSchedule::tryNextLeaving(false, skip));
    EXPECT_EQ(skip, 0);
    label n = 0;
    while (dcpRBFTrialSchedule::tryNextLeaving(true, skip)) ++n;
    EXPECT_EQ(n, dcpRBFTrialSchedule::rescueSkips - 1);
}


TEST(TrialSchedule, RestartStateRoundTrip)
{
    dcpRBFTrialSchedule s(4, 16, 0.05);
    s.backOff();
    s.endStep(0.7);
    dictionary state;
    s.write(state);
    dcpRBFTrialSchedule r(4, 16, 0.05);
    r.read(state);
    EXPECT_EQ(r.wait(), s.wait());
    EXPECT_EQ(r.backoff(), s.backoff());
    EXPECT_TRUE(r.endWaitIfWorse(0.6));
    dcpRBFTrialSchedule fresh(4, 16, 0.05);
    fresh.read(dictionary());
    EXPECT_FALSE(fresh.waiting());
    EXPECT_EQ(fresh.backoff(), 4);
}

} // End anonymous namespace


// ************************************************************************* //
