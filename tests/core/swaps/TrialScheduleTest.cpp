// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of TrialSchedule, the errorGuided trials' back-off, wait and
// rescue: the back-off doubling up to the longest wait, a kept swap starting
// it over, a wait ended only by a fall beyond the drop, the step's end
// counting down and taking the reference quality only where it backed off,
// save/restore, the restart state put back.
#include "TrialSchedule.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace dcprbf;

namespace
{

//- Steps waited after a back-off, given a minimum quality that never falls
int stepsWaited(TrialSchedule& s)
{
    int n = 0;
    while (s.waiting())
    {
        s.endStep(0.5);
        ++n;
    }
    return n;
}

TEST(TrialSchedule, BackOffDoublesUpToTheLongestWait)
{
    TrialSchedule s(4, 16, 0.05);
    EXPECT_FALSE(s.waiting());
    std::vector<int> waits;
    for (int i = 0; i < 5; ++i)
    {
        s.backOff();
        // the step that backed off ends as well
        s.endStep(0.5);
        waits.push_back(1 + stepsWaited(s));
    }
    EXPECT_EQ(waits, (std::vector<int>{4, 8, 16, 16, 16}));
    // a longest wait that is no power of two times the first: capped at it
    TrialSchedule t(3, 10, 0.05);
    std::vector<int> next;
    for (int i = 0; i < 4; ++i)
    {
        t.backOff();
        next.push_back(t.wait());
        t.endStep(0.5);
        stepsWaited(t);
    }
    EXPECT_EQ(next, (std::vector<int>{3, 6, 10, 10}));
}

TEST(TrialSchedule, AKeptSwapStartsTheBackOffOver)
{
    TrialSchedule s(2, 16, 0.05);
    s.backOff();
    s.endStep(0.5);
    stepsWaited(s);
    s.backOff();
    EXPECT_EQ(s.wait(), 4);
    EXPECT_EQ(s.backoff(), 8);
    s.endStep(0.5);
    stepsWaited(s);
    s.kept();
    EXPECT_EQ(s.backoff(), 2);
    EXPECT_FALSE(s.waiting()) << "kept() changes the back-off, not the wait";
    s.endStep(0.5);
    s.backOff();
    EXPECT_EQ(s.wait(), 2);
}

TEST(TrialSchedule, AWaitEndsOnlyWhenTheMeshGetsWorseByMoreThanTheDrop)
{
    TrialSchedule s(8, 16, 0.05);
    EXPECT_FALSE(s.endWaitIfWorse(0.0)) << "no wait to end";
    s.backOff();
    s.endStep(0.6);      // the reference quality: the step that backed off
    EXPECT_TRUE(s.waiting());
    EXPECT_FALSE(s.endWaitIfWorse(0.6)) << "no fall";
    EXPECT_FALSE(s.endWaitIfWorse(0.7)) << "better";
    EXPECT_FALSE(s.endWaitIfWorse(0.56)) << "a fall of 0.04: still waiting";
    EXPECT_EQ(s.wait(), 7);
    EXPECT_TRUE(s.endWaitIfWorse(0.54)) << "a fall of 0.06 ends the wait";
    EXPECT_FALSE(s.waiting());
    EXPECT_EQ(s.wait(), 0);
    EXPECT_FALSE(s.endWaitIfWorse(0.1)) << "no wait to end";
}

TEST(TrialSchedule, EndStepCountsDownAndTakesTheQualityOnlyWhereItBackedOff)
{
    TrialSchedule s(4, 16, 0.05);
    EXPECT_EQ(s.quality(), 1.0);
    s.endStep(0.3);      // no back-off this step: the reference stays
    EXPECT_EQ(s.quality(), 1.0);
    EXPECT_EQ(s.wait(), 0) << "never below zero";
    s.backOff();
    EXPECT_EQ(s.wait(), 4);
    s.endStep(0.8);      // the step that backed off
    EXPECT_EQ(s.quality(), 0.8);
    EXPECT_EQ(s.wait(), 3);
    s.endStep(0.2);      // a step waited: not a reference
    EXPECT_EQ(s.quality(), 0.8);
    EXPECT_EQ(s.wait(), 2);
}

TEST(TrialSchedule, RestoreForgetsTheStepsBackOff)
{
    TrialSchedule s(4, 16, 0.05);
    s.backOff();
    s.endStep(0.9);
    const TrialSchedule::Saved before(s.save());
    EXPECT_EQ(before.wait, 3);
    EXPECT_EQ(before.backoff, 8);
    s.backOff();
    EXPECT_EQ(s.wait(), 8);
    s.restore(before);
    EXPECT_EQ(s.wait(), 3);
    EXPECT_EQ(s.backoff(), 8);
    // the step's back-off forgotten: its end is no reference quality
    s.endStep(0.2);
    EXPECT_EQ(s.quality(), 0.9);
    EXPECT_TRUE(s.endWaitIfWorse(0.84));
}

TEST(TrialSchedule, RestartPutsTheStateBack)
{
    TrialSchedule s(4, 16, 0.05);
    EXPECT_EQ(s.firstBackoff(), 4);
    s.restart(5, 16, 0.7);
    EXPECT_EQ(s.wait(), 5);
    EXPECT_EQ(s.backoff(), 16);
    EXPECT_EQ(s.quality(), 0.7);
    EXPECT_FALSE(s.endWaitIfWorse(0.66));
    EXPECT_TRUE(s.endWaitIfWorse(0.64));
    EXPECT_EQ(s.firstBackoff(), 4);
}

TEST(TrialSchedule, RescueTrialsAndSkips)
{
    EXPECT_EQ(TrialSchedule::nTrials(false, 3), 3);
    EXPECT_EQ(TrialSchedule::nTrials(true, 3), 3*TrialSchedule::rescueSwapFactor);
    int skip = 0;
    EXPECT_FALSE(TrialSchedule::tryNextLeaving(false, skip));
    EXPECT_EQ(skip, 0);
    int n = 0;
    while (TrialSchedule::tryNextLeaving(true, skip)) ++n;
    EXPECT_EQ(n, TrialSchedule::rescueSkips - 1);
}

} // namespace
