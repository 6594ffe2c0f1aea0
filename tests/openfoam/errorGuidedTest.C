/*---------------------------------------------------------------------------*\
  dcpRBF tests: swapRule errorGuided: trials kept only where they help, the
  rescue, the trials' schedule, the blend
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "bumpRun.H"
#include "dcpRBFErrorGuidedSwaps.H"

#include <gtest/gtest.h>
#include <cmath>
#include <sstream>
#include <string>
#include <tuple>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

//- The trials' schedule read back from the rows of a run: after an undone
//  trial the next waits trialBackoff steps, doubling per further undone one
//  (up to 16), back to trialBackoff after a kept swap; a wait ends early
//  where the mesh without swaps is worse by more than trialQualityDrop than
//  at the last undone trial. Checks every step against it (no rescue)
struct trialSchedule
{
    label nTrialSteps = 0, nUndoneSteps = 0, nWaited = 0;
    //- Trial steps that ended a wait, and those of them that kept swaps
    label nEarly = 0, nEarlyKept = 0;
    //- Steps due for a trial (not waiting, or the wait ended by the fall)
    //  that made none
    label nMissed = 0;

    trialSchedule(const std::vector<std::vector<double>>& rows, const label backoff,
        const scalar drop)
    {
        label wait = 0, next = backoff;
        scalar trialQuality = 1;
        for (std::size_t s = 0; s < rows.size(); ++s)
        {
            const auto& row = rows[s];
            EXPECT_GT(row[cMinQ], 0) << "step " << s + 1 << ": a rescue does not wait";
            const bool kept = row[cAdded] > 0, undone = row[cUndone] > 0;
            // the logged minimum is the mesh without swaps unless kept
            const bool fallen = trialQuality - row[cMinQ] > drop;
            if (wait > 0 && (kept || undone))
            {
                ++nEarly;
                nEarlyKept += kept;
                EXPECT_TRUE(kept || fallen) << "step " << s + 1 << ": a trial while waiting "
                    << wait << " more step(s), the mesh " << trialQuality - row[cMinQ]
                    << " worse than at the last trial";
                wait = 0;
            }
            else if (wait > 0 && !fallen)
            {
                ++nWaited;
            }
            else if (!(kept || undone))
            {
                // due (the wait over or ended by the fall), no trial
                ++nMissed;
                wait = 0;
            }
            nTrialSteps += kept || undone;
            if (kept)
            {
                next = backoff;
            }
            else if (undone)
            {
                ++nUndoneSteps;
                wait = next;
                next = std::min<label>(2*next, dcpRBFErrorGuidedSettings::maxTrialWait());
                trialQuality = row[cMinQ];
            }
            if (wait > 0) --wait;
        }
    }
};

// The error-guided rule at fixed N (the paper's setting: no correction, no
// re-selection) keeps a swap only if it raises the step's minimum quality:
// swaps happen, and the mesh is never worse than with the static set. On
// the 16 x 16 box the trials see every cell; on the 48 x 48 box (2304
// cells) they see the worst 256 only and the written mesh is checked in full
class ErrorGuidedSwaps : public ::testing::TestWithParam<label> {};

TEST_P(ErrorGuidedSwaps, NeverWorseThanTheStaticSetAtFixedN)
{
    const label n = GetParam();
    const std::string fixedN =
        "tolerance 1e-12; minPoints 12; maxPoints 12; reselectTolerance 1e9;";
    const label nSteps = 8;
    const std::vector<double> greedy
    (
        minQualityPerStep("selection greedy; " + fixedN, nSteps, nullptr, n)
    );
    const bumpRun run
    (
        runBump
        (
            "selection dynamic; swapRule errorGuided; swapBlendSteps 1; protectSteps 0; " + fixedN,
            nSteps, n
        )
    );
    const std::vector<std::vector<double>>& rows = run.rows;
    std::vector<double> dynamic;
    for (const auto& row : rows) dynamic.push_back(row[cMinQ]);
    ASSERT_EQ(label(greedy.size()), nSteps);
    ASSERT_EQ(label(dynamic.size()), nSteps);
    if (n > 16)
    {
        EXPECT_GT(rows[0][cCells], 2*256) << "the trials see a part of the cells";
    }
    double kept = 0;
    for (label s = 0; s < nSteps; ++s)
    {
        EXPECT_GE(dynamic[s], greedy[s] - 1e-12) << "step " << s + 1;
        EXPECT_EQ(rows[s][cControl], 12) << "constant N";
        kept += rows[s][cAdded];
    }
    // most of the way from the static set's quality to full RBF's (on the
    // finer box from the third step), valid where full RBF is
    const std::vector<double> all(minQualityPerStep("selection all;", nSteps, nullptr, n));
    EXPECT_GT(kept, 0) << "no swap was kept";
    // after the first step the trials pick their window from the last
    // step's measurement: a step that keeps swaps measures its mesh once
    // (the mesh without swaps, of a window's minimum at most the written
    // one's, is not measured in full)
    label keptLater = 0;
    for (label s = 1; s < nSteps; ++s) keptLater += rows[s][cAdded] > 0;
    EXPECT_GT(keptLater, 0) << "no swap kept after the first step";
    // (except where a wait ended because the mesh got worse: the mesh
    // without swaps was measured first, to see that)
    const dcpRBFErrorGuidedSettings defaults(dictionary::null);
    const trialSchedule t(rows, defaults.trialBackoff, defaults.trialQualityDrop);
    EXPECT_LE(run.nMeasurements, nSteps + 1 + t.nEarlyKept)
        << keptLater << " steps after the first kept swaps";
    EXPECT_GT(dynamic.back(), greedy.back()) << "the swaps did not pay off";
    for (label s = 0; s < nSteps; ++s)
    {
        EXPECT_TRUE(all[s] <= 0 || dynamic[s] > 0) << "step " << s + 1;
    }
    for (label s = (n > 16 ? 2 : 1); s < nSteps; ++s)
    {
        EXPECT_GT(dynamic[s], greedy[s] + 0.5*(all[s] - greedy[s])) << "step " << s + 1;
    }
}

INSTANTIATE_TEST_SUITE_P(Box, ErrorGuidedSwaps, ::testing::Values(16, 48),
    [](const ::testing::TestParamInfo<label>& i)
    {
        return "cells" + std::to_string(i.param) + "x" + std::to_string(i.param);
    });

// Rescue: where the mesh without swaps has inverted cells, the trials go
// on (other leaving points after an undone one, more than nSwap) and apply
// at once, even with the blend on (swapBlendSteps 4, nSwap 1). A bump that
// inverts the static set's cells at the first step: the step is made valid,
// with more kept swaps than nSwap (without the rescue: at most one)
TEST(ErrorGuidedRescue, MakesTheFirstStepValidWhereTheStaticSetInverts)
{
    const std::string fixedN =
        "tolerance 1e-12; minPoints 12; maxPoints 12; reselectTolerance 1e9;";
    const label nSteps = 2, n = 48;
    const scalar perStep = 0.14;
    const std::vector<double> greedy
    (
        minQualityPerStep("selection greedy; " + fixedN, nSteps, nullptr, n, perStep)
    );
    const std::vector<double> all
    (
        minQualityPerStep("selection all;", nSteps, nullptr, n, perStep)
    );
    std::vector<std::vector<double>> rows;
    const std::vector<double> dynamic
    (
        minQualityPerStep
        (
            "selection dynamic; nSwap 1; swapBlendSteps 4; " + fixedN,
            nSteps, &rows, n, perStep
        )
    );
    ASSERT_LE(greedy[0], 0) << "the static set should invert cells at step 1";
    ASSERT_GT(all[0], 0) << "full RBF should not";
    EXPECT_GT(dynamic[0], 0) << "the rescue did not make step 1 valid";
    EXPECT_GT(rows[0][cAdded], 1) << "more swaps than nSwap in the rescue";
    for (label s = 0; s < nSteps; ++s)
    {
        EXPECT_EQ(rows[s][cControl], 12) << "constant N";
    }
}


// The trials of a step after the first come before its full measurement,
// their window picked from the last step's; where the mesh without swaps
// turns out inverted (here from the second step on: the static set folds
// the bump's cells then) the rescue still follows in the same step, with
// more kept swaps than nSwap, and the step is valid
TEST(ErrorGuidedRescue, FollowsTheTrialsMadeBeforeTheMeasurement)
{
    const std::string fixedN =
        "tolerance 1e-12; minPoints 12; maxPoints 12; reselectTolerance 1e9;";
    const label n = 48;
    const std::vector<scalar> amplitudes({0.01, 0.16, 0.2});
    const label nSteps = amplitudes.size();
    const auto minQ = [&](const std::string& controlPoints, bumpRun& b)
    {
        b = runBump(controlPoints, nSteps, n, 0, amplitudes);
        std::vector<double> q;
        for (const auto& row : b.rows) q.push_back(row[cMinQ]);
        return q;
    };
    bumpRun bg, ba, bd;
    const std::vector<double> greedy(minQ("selection greedy; " + fixedN, bg));
    const std::vector<double> all(minQ("selection all;", ba));
    const std::vector<double> dynamic
    (
        minQ("selection dynamic; nSwap 1; swapBlendSteps 1; protectSteps 0; " + fixedN, bd)
    );
    ASSERT_GT(greedy[0], 0) << "the static set should be valid at step 1";
    ASSERT_LE(greedy[1], 0) << "the static set should invert cells at step 2";
    ASSERT_GT(all[1], 0) << "full RBF should not";
    EXPECT_GT(dynamic[1], 0) << "the rescue did not make step 2 valid";
    EXPECT_GT(bd.rows[1][cAdded], 1) << "more swaps than nSwap in the rescue";
}


// The trials follow the schedule: with trialQualityDrop 1 (a wait never
// ends early) no trial while waiting; with a smaller one, on the growing
// bump, waits end early where the mesh got worse, and only there
class TrialBackoff : public ::testing::TestWithParam<std::tuple<label, scalar>> {};

TEST_P(TrialBackoff, TrialsWaitAsScheduled)
{
    const label backoff = std::get<0>(GetParam());
    const scalar drop = std::get<1>(GetParam());
    const label nSteps = 24;
    std::ostringstream controlPoints;
    controlPoints<< "selection dynamic; nSwap 1; swapBlendSteps 1; protectSteps 0;"
        " tolerance 1e-12; minPoints 12; maxPoints 12; reselectTolerance 1e9;"
        " trialBackoff " << backoff << "; trialQualityDrop " << drop << ";";
    ::testing::internal::CaptureStdout();
    const bumpRun b(runBump(controlPoints.str(), nSteps, 16, 0.01));
    const std::string log(::testing::internal::GetCapturedStdout());
    ASSERT_EQ(label(b.rows.size()), nSteps);
    const trialSchedule t(b.rows, backoff, drop);
    // the log says so where a wait ended early (a trial at each, here)
    label nSaid = 0;
    for (auto i = log.find(", wait ended"); i != std::string::npos;
        i = log.find(", wait ended", i + 1))
    {
        ++nSaid;
    }
    EXPECT_EQ(nSaid, t.nEarly) << "log lines ', wait ended'";
    EXPECT_GT(t.nUndoneSteps, 1) << "no back-off to check";
    // every step due for a trial made one (a swap to propose on this bump)
    EXPECT_EQ(t.nMissed, 0);
    EXPECT_GT(t.nWaited, 0) << "no wait held";
    if (drop >= 1)
    {
        EXPECT_EQ(t.nEarly, 0);
        // the trials go on after the first wait: the schedule, not a stop
        EXPECT_GT(t.nTrialSteps, 2);
    }
    else
    {
        EXPECT_GT(t.nEarly, 0) << "no wait ended where the mesh got worse";
    }
}

INSTANTIATE_TEST_SUITE_P(Steps, TrialBackoff,
    ::testing::Values(std::make_tuple(1, 1.0), std::make_tuple(2, 1.0),
        std::make_tuple(4, 1.0), std::make_tuple(4, 0.05), std::make_tuple(16, 0.03)),
    [](const ::testing::TestParamInfo<std::tuple<label, scalar>>& i)
    {
        return "trialBackoff" + std::to_string(std::get<0>(i.param)) + "Drop"
            + std::to_string(int(std::round(1000*std::get<1>(i.param)))) + "permille";
    });


// A kept swap changes the interpolant; phased in over swapBlendSteps the
// mesh velocity changes by a fraction of that jump per step. The bump grows
// linearly: with a fixed set the points move at constant velocity, so the
// velocity changes only through the swaps
TEST(ErrorGuidedBlend, PhasedInSwapsKeepTheMeshVelocitySmooth)
{
    const std::string fixedN =
        "selection dynamic; tolerance 1e-12; minPoints 12; maxPoints 12;"
        " reselectTolerance 1e9; protectSteps 0; nSwap 1;";
    const label nSteps = 8;
    const bumpRun atOnce(runBump(fixedN + " swapBlendSteps 1;", nSteps));
    const bumpRun phased(runBump(fixedN + " swapBlendSteps 4;", nSteps));
    double keptAtOnce = 0, keptPhased = 0;
    for (const auto& row : atOnce.rows) keptAtOnce += row[cAdded];
    for (const auto& row : phased.rows) keptPhased += row[cAdded];
    ASSERT_GT(keptAtOnce, 0);
    ASSERT_GT(keptPhased, 0);
    const bumpRun greedy(runBump("selection greedy; tolerance 1e-12; minPoints 12;"
        " maxPoints 12; reselectTolerance 1e9;", nSteps));
    EXPECT_LT(largestJerk(greedy), 1e-12) << "the motion itself is smooth";
    EXPECT_GT(largestJerk(atOnce), 1e-4) << "a swap at once makes the velocity jump";
    EXPECT_LT(largestJerk(phased), 0.5*largestJerk(atOnce));
}

//- Two bumps (x = 1/4 and 3/4), the first 3 % higher
scalar twoBumps(const scalar x)
{
    return (x < 0.5 ? 1.03 : 1.0)*std::abs(std::sin(2*constant::mathematical::pi*x));
}

// Kept trials are abandoned where the step's whole mesh is no better than
// without them: a swap never makes the mesh worse than not swapping. Two
// bumps of about the same height on a boundary-layer box, 20 control points:
// a trial judged on the worst cells (at one bump) helps there, but its
// joining point's kernel reaches the other bump's cells, outside the window
// (here at step 6: two trials kept, then abandoned: no point added, the
// kept ones counted with the undone one, the mesh far from inverted, so no
// rescue). Without the whole-mesh comparison the step would add them
TEST(ErrorGuidedSwaps, KeptTrialsAbandonedWhereTheWholeMeshIsNoBetter)
{
    const std::string fixedN =
        "tolerance 1e-12; minPoints 20; maxPoints 20; reselectTolerance 1e9;";
    const bumpRun d
    (
        runBump
        (
            "selection dynamic; nSwap 4; swapBlendSteps 1; trialBackoff 1;"
            " trialQualityDrop 1; " + fixedN,
            12, 48, 0.012, {}, "", twoBumps
        )
    );
    label abandoned = 0;
    for (const auto& row : d.rows)
    {
        if (row[cMinQ] > 0.3 && row[cAdded] == 0 && row[cUndone] >= 2) ++abandoned;
    }
    EXPECT_GT(abandoned, 0) << "no step whose kept trials were abandoned";
}

} // namespace

// ************************************************************************* //
