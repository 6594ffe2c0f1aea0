/*---------------------------------------------------------------------------*\
  dcpRBF tests: one evaluation of the conditions per step, refused
  conditions, maxPoints marked, dynamic swaps over several steps
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF, GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "bumpRun.H"
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
        const dcprbf::Values stored(cp.blockValues());
        const dcprbf::Values direct(cp.evaluator().evaluate(cp.block().points()));
        ASSERT_EQ(stored.rows(), direct.rows());
        EXPECT_LT((stored - direct).cwiseAbs().maxCoeff(), 1e-13) << "step " << step;
    }
    EXPECT_GT(sets.size(), 1u) << "the set never changed";
}

} // namespace

// ************************************************************************* //
