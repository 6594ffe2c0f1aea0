/*---------------------------------------------------------------------------*\
  dcpRBF tests: one evaluation of the conditions per step, refused
  conditions, maxPoints marked, dynamic swaps over several steps
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF, GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "countingDisplacement.H"
#include "dcpRBFCellQuality.H"
#include "addToRunTimeSelectionTable.H"
#include "IFstream.H"

#include <gtest/gtest.h>
#include <set>
#include <sstream>

namespace Foam
{
namespace dcpRBFTest
{
    label countingDisplacement::nEvaluations = 0;
    defineTypeNameAndDebug(countingDisplacement, 0);
    addToRunTimeSelectionTable
    (
        pointPatchVectorField, countingDisplacement, dictionary
    );
}
}

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

const std::string patches =
    "movingPatches (bottom); staticPatches (top left right); supportRadius 0.8;";

//- The rows of postProcessing/dcpRBF/0/dcpRBF.dat, as numbers
std::vector<std::vector<double>> stepRows(const testCase& c)
{
    std::vector<std::vector<double>> rows;
    std::ifstream is(c.dir()/"postProcessing"/"dcpRBF"/"0"/"dcpRBF.dat");
    std::string line;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        std::vector<double> row;
        double x;
        while (ls >> x) row.push_back(x);
        rows.push_back(row);
    }
    return rows;
}

// Columns of dcpRBF.dat (dcpRBFStepLog)
enum column { cTime, cControl, cAdded, cRemoved, cGuard, cCells, cMinQ, cMeanQ,
    cError, cAtMax, cSwapTime, cSelectTime, cInterpolateTime, cGuardTime, cUndone };


class OneEvaluation : public ::testing::TestWithParam<std::tuple<int, std::string>> {};

// A condition that moves its patch by `increment` per evaluation: after n
// steps the patch is n increments away, as with OpenFOAM's own solvers
TEST_P(OneEvaluation, ConditionsAreEvaluatedOncePerStep)
{
    const label dim = std::get<0>(GetParam());
    testCase c
    (
        dim, 6, patches + " controlPoints { " + std::get<1>(GetParam()) + " }",
        "wall",
        "{ type countingDisplacement; increment (0 0.01 0); value uniform (0 0 0); }"
    );
    autoPtr<motionSolver> ms(select(c));
    const pointField p0(refCast<dcpRBFMotionSolver>(ms()).points0());
    countingDisplacement::nEvaluations = 0;
    const label nSteps = 3;
    pointField p;
    for (label step = 1; step <= nSteps; ++step)
    {
        ++c.runTime();
        p = ms->newPoints();
    }
    EXPECT_EQ(countingDisplacement::nEvaluations, nSteps);
    label nBottom = 0, nInterior = 0;
    const scalar eps = 1e-9;
    forAll(p0, i)
    {
        const point& x = p0[i];
        // away from the side walls (and, in 3D, the front and back walls)
        const bool between =
            x.x() > eps && x.x() < 1 - eps
         && (dim == 2 || (x.z() > eps && x.z() < 1 - eps));
        if (!between) continue;
        if (x.y() < eps)
        {
            EXPECT_LT(mag(p[i] - x - vector(0, 0.01*nSteps, 0)), 1e-12)
                << x.x() << " " << x.y() << " " << x.z();
            ++nBottom;
        }
        else if (x.y() < 0.5)
        {
            // the volume near the wall moves too, less than the wall
            EXPECT_GT(p[i].y() - x.y(), 1e-6) << x.x() << " " << x.y() << " " << x.z();
            EXPECT_LT(p[i].y() - x.y(), 0.01*nSteps + 1e-12) << x.x() << " " << x.y();
            ++nInterior;
        }
    }
    EXPECT_GT(nBottom, 0);
    EXPECT_GT(nInterior, 0);
}

INSTANTIATE_TEST_SUITE_P
(
    DimsAndModes, OneEvaluation,
    ::testing::Combine
    (
        ::testing::Values(2, 3),
        ::testing::Values
        (
            "selection all;",
            "selection greedy;",
            "selection dynamic;"
        )
    )
);


class UnprescribedMovingPatch : public ::testing::TestWithParam<std::string> {};

// A moving patch whose condition does not fix the value would not move
TEST_P(UnprescribedMovingPatch, IsRefusedNamingPatchAndType)
{
    const std::string type = GetParam();
    testCase c(2, 3, patches, "wall", "{ type " + type + "; value uniform (0 0 0); }");
    try
    {
        autoPtr<motionSolver> ms(select(c));
        FAIL() << "no error for a moving patch of type " << type;
    }
    catch (const Foam::IOerror& e)
    {
        const std::string m(e.message());
        EXPECT_NE(m.find("movingPatches"), std::string::npos) << m;
        EXPECT_NE(m.find("bottom"), std::string::npos) << m;
        EXPECT_NE(m.find(type), std::string::npos) << m;
        // where a sliding patch goes (not under staticPatches: frozen)
        EXPECT_NE(m.find("slip, fixedNormalSlip) goes in neither list"), std::string::npos) << m;
    }
}

INSTANTIATE_TEST_SUITE_P
(
    Types, UnprescribedMovingPatch, ::testing::Values("calculated", "zeroGradient", "slip")
);


vector bump(const point& p, scalar a)
{
    return vector(0, a*std::sin(constant::mathematical::pi*p.x()), 0);
}

// maxPoints reached with the boundary error above reselectTolerance: the
// step is marked in dcpRBF.dat; with room to spare it is not
TEST(MaxPoints, ReachedWithErrorAboveToleranceIsMarked)
{
    for (const label maxPoints : {5, 2000})
    {
        testCase c
        (
            2, 12, patches + " controlPoints { selection greedy; tolerance 1e-6;"
            " reselectTolerance 1e-5; maxPoints " + std::to_string(maxPoints) + "; }"
        );
        autoPtr<motionSolver> ms(select(c));
        auto& solver = refCast<dcpRBFMotionSolver>(ms());
        ++c.runTime();
        prescribe(solver.pointDisplacement(), "bottom", [](const point& x) { return bump(x, 0.1); });
        ms->newPoints();
        const auto rows = stepRows(c);
        ASSERT_EQ(rows.size(), 1u);
        ASSERT_GT(rows[0].size(), std::size_t(cAtMax));
        EXPECT_EQ(rows[0][cAtMax], maxPoints == 5 ? 1 : 0) << "maxPoints " << maxPoints;
        EXPECT_LE(solver.controlPoints().size(), maxPoints);
        if (maxPoints == 5)
        {
            EXPECT_GT(rows[0][cError], 1e-5);
        }
    }
}

// Dynamic control points over several steps of a growing bump: points swap,
// the set's size follows the additions and removals, the wall is exact at
// every step and the mesh stays valid
TEST(DynamicSwaps, HappenOverStepsAndKeepTheWallExact)
{
    testCase c(2, 12, patches + " controlPoints { selection dynamic; swapRule nearest; tolerance 1e-2; protectSteps 1; }");
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    const pointField p0(solver.points0());
    std::set<Eigen::Index> first;
    const label nSteps = 6;
    for (label step = 1; step <= nSteps; ++step)
    {
        ++c.runTime();
        const scalar a = 0.05*step;
        prescribe(solver.pointDisplacement(), "bottom", [a](const point& x) { return bump(x, a); });
        const pointField p(ms->newPoints());
        c.mesh().movePoints(p);
        if (step == 1)
        {
            const auto& idx = solver.controlPoints().set().indices();
            first.insert(idx.begin(), idx.end());
        }
        forAll(p0, i)
        {
            if (p0[i].y() == 0 && p0[i].x() > 0 && p0[i].x() < 1)
            {
                EXPECT_LT(mag(p[i] - p0[i] - bump(p0[i], a)), 1e-12) << "step " << step;
            }
        }
        EXPECT_FALSE(c.mesh().checkMesh(false)) << "mesh errors at step " << step;  // true: errors
    }
    const auto rows = stepRows(c);
    ASSERT_EQ(label(rows.size()), nSteps);
    double added = 0, removed = 0;
    for (label s = 1; s < nSteps; ++s)
    {
        added += rows[s][cAdded];
        removed += rows[s][cRemoved];
        // the set's size follows the step's additions and removals
        EXPECT_EQ(rows[s][cControl], rows[s - 1][cControl] + rows[s][cAdded] + rows[s][cGuard]
            - rows[s][cRemoved]) << "step " << s + 1;
    }
    EXPECT_GT(added, 0);
    EXPECT_GT(removed, 0);
    const auto& idx = solver.controlPoints().set().indices();
    const std::set<Eigen::Index> last(idx.begin(), idx.end());
    EXPECT_NE(first, last) << "the control set never changed";
}

//- A growing bump on the bottom wall of a boundary-layer box: the points
//  and the rows of dcpRBF.dat after each step
struct bumpRun
{
    std::vector<pointField> points;
    std::vector<std::vector<double>> rows;
    //- Each step's minimum quality of the points written, over every cell
    std::vector<double> minQuality;
    //- The motion solver's whole-region quality measurements
    label nMeasurements = 0;
};

bumpRun runBump(const std::string& controlPoints, label nSteps, label n = 16,
    scalar perStep = 0.04, const std::vector<scalar>& amplitudes = {})
{
    // a boundary layer: cells 30 times thinner at the bottom wall than at
    // the top, where a reduced set's boundary error folds them first
    testCase c(2, n, patches + " boundaryCorrection false; guardIterations 0;"
        " controlPoints { " + controlPoints + " }", "wall",
        "{ type fixedValue; value uniform (0 0 0); }", "(1 30 1)");
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    bumpRun b;
    const pointField p0(c.mesh().points());
    const labelList cells(identity(c.mesh().nCells()));
    for (label step = 1; step <= nSteps; ++step)
    {
        ++c.runTime();
        const scalar a = amplitudes.empty() ? perStep*step : amplitudes[step - 1];
        prescribe(solver.pointDisplacement(), "bottom", [a](const point& x)
        {
            return vector(0, a*std::sin(2*constant::mathematical::pi*x.x()), 0);
        });
        const pointField p(ms->newPoints());
        // the new points (the measured ones, reused when the displacement
        // is the one they were made from) are those of the displacement
        // the step leaves, bitwise, after trials, rescues and blends too
        const pointField fresh(ms->curPoints());
        scalar d = 0;
        forAll(p, i) d = max(d, mag(p[i] - fresh[i]));
        EXPECT_EQ(d, 0) << "step " << step << ": newPoints() != curPoints()";
        // the logged minimum is the written mesh's (its worst cells are at
        // the moving wall, in reach), after trials made before or after the
        // measurement, rescues and blends alike
        b.minQuality.push_back(gMin(dcpRBFCellQuality(c.mesh()).compute(cells, p0, p)));
        c.mesh().movePoints(p);
        b.points.push_back(p);
    }
    // no constraint repeated off its axis here: every step's new points
    // are the measured ones (not made a second time)
    EXPECT_EQ(solver.nReusedPoints(), nSteps);
    b.nMeasurements = solver.nMeasurements();
    b.rows = stepRows(c);
    EXPECT_EQ(label(b.rows.size()), nSteps);
    for (std::size_t s = 0; s < b.rows.size() && s < b.minQuality.size(); ++s)
    {
        EXPECT_NEAR(b.rows[s][cMinQ], b.minQuality[s], 1e-12) << "step " << s + 1;
    }
    return b;
}

// A patch in neither list moves with the interpolated displacement, then
// its own condition applies (here fixedValue zero): the step's new points
// are not the ones the quality was measured on, and newPoints() must make
// them anew from the displacement it leaves
TEST(NewPoints, AreThoseOfTheFinalDisplacementWhenAConditionOverridesIt)
{
    testCase c(2, 12, "movingPatches (bottom); staticPatches (left right); supportRadius 0.8;"
        " controlPoints { selection greedy; }");
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    const label top = c.mesh().boundaryMesh().findPatchID("top");
    for (label step = 1; step <= 2; ++step)
    {
        ++c.runTime();
        const scalar a = 0.1*step;
        prescribe(solver.pointDisplacement(), "bottom", [a](const point&) { return vector(0, a, 0); });
        const pointField p(ms->newPoints());
        const pointField fresh(ms->curPoints());
        scalar d = 0;
        forAll(p, i) d = max(d, mag(p[i] - fresh[i]));
        EXPECT_EQ(d, 0) << "step " << step;
        scalar topMoved = 0;
        for (const label pointi : c.mesh().boundaryMesh()[top].meshPoints())
        {
            topMoved = max(topMoved, mag(p[pointi] - solver.points0()[pointi]));
        }
        EXPECT_LT(topMoved, 1e-15) << "step " << step << ": the top's fixedValue zero";
        // the interpolation moves the row of points below the top: at the
        // top it would too, so the measured points differ from these
        scalar belowTop = 0;
        forAll(p, i)
        {
            const scalar y = solver.points0()[i].y();
            if (y > 1 - 1.5/12 && y < 1 - 1e-9)
            {
                belowTop = max(belowTop, mag(p[i] - solver.points0()[i]));
            }
        }
        EXPECT_GT(belowTop, 1e-3) << "step " << step;
        c.mesh().movePoints(p);
    }
}

//- Minimum quality per step of the bump run
std::vector<double> minQualityPerStep(const std::string& controlPoints, label nSteps,
    std::vector<std::vector<double>>* rowsOut = nullptr, label n = 16, scalar perStep = 0.04)
{
    const bumpRun b(runBump(controlPoints, nSteps, n, perStep));
    if (rowsOut) *rowsOut = b.rows;
    std::vector<double> q;
    for (const auto& row : b.rows) q.push_back(row[cMinQ]);
    return q;
}

//- Largest change of point velocity between steps, max |x(n+1) - 2x(n) + x(n-1)|
scalar largestJerk(const bumpRun& b)
{
    scalar j = 0;
    for (std::size_t s = 1; s + 1 < b.points.size(); ++s)
    {
        forAll(b.points[s], i)
        {
            j = max(j, mag(b.points[s + 1][i] - 2*b.points[s][i] + b.points[s - 1][i]));
        }
    }
    return j;
}

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
    EXPECT_LE(run.nMeasurements, nSteps + 1)
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


// The trials' back-off: after an undone trial the next waits trialBackoff
// steps, doubling per further undone one (up to 16), back to trialBackoff
// after a kept swap (at once: swapBlendSteps 1). Every step's trials
// (columns nAdded, nUndone) follow that schedule; no rescue on this bump
class TrialBackoff : public ::testing::TestWithParam<label> {};

TEST_P(TrialBackoff, TrialsWaitAsScheduled)
{
    const label backoff = GetParam();
    const label nSteps = 24;
    const std::string controlPoints =
        "selection dynamic; nSwap 1; swapBlendSteps 1; protectSteps 0;"
        " tolerance 1e-12; minPoints 12; maxPoints 12; reselectTolerance 1e9;"
        " trialBackoff " + std::to_string(backoff) + ";";
    const bumpRun b(runBump(controlPoints, nSteps, 16, 0.01));
    ASSERT_EQ(label(b.rows.size()), nSteps);
    label wait = 0, next = backoff, nUndoneSteps = 0, nTrialSteps = 0, nWaited = 0;
    for (label s = 0; s < nSteps; ++s)
    {
        const auto& row = b.rows[s];
        ASSERT_GT(row[cMinQ], 0) << "step " << s + 1 << ": a rescue would not wait";
        const bool kept = row[cAdded] > 0, undone = row[cUndone] > 0;
        if (wait > 0)
        {
            EXPECT_FALSE(kept || undone) << "step " << s + 1 << ": a trial while waiting "
                << wait << " more step(s)";
            ++nWaited;
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
            next = std::min<label>(2*next, 16);
        }
        if (wait > 0) --wait;
    }
    EXPECT_GT(nUndoneSteps, 1) << "no back-off to check";
    EXPECT_GT(nWaited, 0);
    // the trials go on after the first wait: the schedule, not a stop
    EXPECT_GT(nTrialSteps, nUndoneSteps > 0 ? 2 : 0);
}

INSTANTIATE_TEST_SUITE_P(Steps, TrialBackoff, ::testing::Values(1, 2, 4),
    [](const ::testing::TestParamInfo<label>& i)
    {
        return "trialBackoff" + std::to_string(i.param);
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

// Stored kernel matrices (evaluationMemoryMB, default: the product written
// straight to the points, in 2D to both twins) and evaluation on the fly
// (0) move the mesh the same, over steps where the set changes (patched
// matrices), in 2D and 3D
TEST(StoredEvaluation, MovesTheMeshAsEvaluationOnTheFly)
{
    for (const label dim : {2, 3})
    {
        std::vector<pointField> p[2];
        for (const int stored : {0, 1})
        {
            testCase c(dim, 6, patches + " controlPoints { selection dynamic; tolerance 1e-2; }"
                + (stored ? "" : " evaluationMemoryMB 0;"));
            autoPtr<motionSolver> ms(select(c));
            auto& solver = refCast<dcpRBFMotionSolver>(ms());
            for (label step = 1; step <= 4; ++step)
            {
                ++c.runTime();
                const scalar a = 0.05*step;
                prescribe(solver.pointDisplacement(), "bottom", [a](const point& x) { return bump(x, a); });
                const pointField pts(ms->newPoints());
                c.mesh().movePoints(pts);
                p[stored].push_back(pts);
            }
        }
        for (std::size_t s = 0; s < p[0].size(); ++s)
        {
            scalar d = 0;
            forAll(p[0][s], i) d = max(d, mag(p[0][s][i] - p[1][s][i]));
            EXPECT_LT(d, 1e-12) << dim << "D, step " << s + 1;
        }
    }
}

// The re-selection's boundary error from stored matrices (the moving
// candidates' rows of the product at every candidate) picks the same points
// as on the fly; the moving patch is not the first, so its candidates are
// not the first rows
TEST(StoredEvaluation, ReselectionAsOnTheFly)
{
    std::vector<std::vector<Eigen::Index>> sets[2];
    for (const int stored : {0, 1})
    {
        testCase c(2, 12, "movingPatches (top); staticPatches (bottom left right); supportRadius 0.8;"
            " controlPoints { selection greedy; tolerance 1e-2; reselectTolerance 2e-2; }"
            + std::string(stored ? "" : " evaluationMemoryMB 0;"));
        autoPtr<motionSolver> ms(select(c));
        auto& solver = refCast<dcpRBFMotionSolver>(ms());
        const dcpRBFControlPoints& cp = solver.controlPoints();
        for (label step = 1; step <= 4; ++step)
        {
            ++c.runTime();
            // the shape changes from step to step: the set must grow
            prescribe(solver.pointDisplacement(), "top", [step](const point& x)
            {
                return vector(0, -0.05*std::sin(constant::mathematical::pi*x.x())*pow(x.x(), 2*step), 0);
            });
            c.mesh().movePoints(ms->newPoints());
            sets[stored].push_back(cp.set().indices());
        }
    }
    EXPECT_GT(sets[1].back().size(), sets[1].front().size()) << "no re-selection happened";
    for (std::size_t s = 0; s < sets[0].size(); ++s)
    {
        EXPECT_EQ(sets[0][s], sets[1][s]) << "step " << s + 1;
    }
}

// The interpolant at the candidates (boundary error of the selection and
// the correction) from stored matrices equals the evaluator's, as the set
// changes over steps (swaps: patched matrices; additions). swapRule
// nearest swaps every step (errorGuided's trials are kept or undone by
// the window's minimum: which ones are kept varies with round-off)
TEST(StoredEvaluation, BoundaryValuesEqualTheEvaluator)
{
    testCase c(3, 6, patches + " controlPoints { selection dynamic; swapRule nearest; tolerance 1e-3; }");
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    const dcpRBFControlPoints& cp = solver.controlPoints();
    std::set<std::vector<Eigen::Index>> sets;
    for (label step = 1; step <= 4; ++step)
    {
        ++c.runTime();
        const scalar a = 0.05*step;
        prescribe(solver.pointDisplacement(), "bottom", [a](const point& x) { return bump(x, a); });
        c.mesh().movePoints(ms->newPoints());
        sets.insert(cp.set().indices());
        const dcprbf::Values stored(cp.boundaryValues());
        const dcprbf::Values direct(cp.evaluator().evaluate(cp.candidates()));
        ASSERT_EQ(stored.rows(), direct.rows());
        EXPECT_LT((stored - direct).cwiseAbs().maxCoeff(), 1e-13) << "step " << step;
    }
    EXPECT_GT(sets.size(), 1u) << "the set never changed";
}

} // namespace

// ************************************************************************* //
