/*---------------------------------------------------------------------------*\
  dcpRBF tests: the far field stays still (farField still)
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    A bump of the bottom wall of a box whose other walls are static: the
    bump's mean lift is an affine part of the boundary's motion, which the
    interpolant's linear polynomial carries to every point. By default
    (farField still) no point farther than twice supportRadius from the
    moving wall moves by more than 1e-4 of the bump, in every selection
    mode; within supportRadius the displacement is the interpolant's, bit
    for bit (farField interpolated gives the same there); with farField
    interpolated the far field does move (what the default prevents).
    The cells between supportRadius and twice it are checked with the others:
    where the bottom wall lifts as a whole, the worst cells are there, and
    the logged minimum is the whole mesh's.

\*---------------------------------------------------------------------------*/

#include "cellByCellQuality.H"
#include "testHelpers.H"
#include "bumpRun.H"
#include "dcpRBFCellQuality.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

//- One step of a bump of the bottom wall (height 0.05) in a box with static
//  walls, supportRadius 0.2; the displacement of every point
vectorField bumpStep(const std::string& controlPoints, const std::string& farField)
{
    testCase c
    (
        2, 40,
        "movingPatches (bottom); staticPatches (top left right);"
        " supportRadius 0.2; " + farField + " controlPoints { "
      + controlPoints + " }"
    );
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    ++c.runTime();
    prescribe(solver.pointDisplacement(), "bottom", [](const point& x)
    {
        return vector(0, 0.05*Foam::sin(constant::mathematical::pi*x.x()), 0);
    });
    const pointField p(ms->newPoints());
    return p - solver.points0();
}

class FarField : public ::testing::TestWithParam<std::string>
{};

TEST_P(FarField, StillBeyondTwiceTheRadiusWhatTheInterpolantGivesWithin)
{
    const std::string controlPoints = GetParam();
    const vectorField still(bumpStep(controlPoints, ""));
    const vectorField free(bumpStep(controlPoints, "farField interpolated;"));
    testCase ref(2, 40, "movingPatches (bottom); staticPatches (); supportRadius 0.2;");
    const pointField& p0 = ref.mesh().points();
    const scalar radius = 0.2;
    const scalar bump = 0.05;
    scalar farStill = 0;
    scalar farFree = 0;
    label nWithin = 0;
    forAll(p0, i)
    {
        // the distance to the moving wall (the whole bottom, y = 0)
        const scalar r = p0[i].y();
        if (r > 2*radius)
        {
            farStill = max(farStill, mag(still[i]));
            farFree = max(farFree, mag(free[i]));
        }
        else if (r <= radius)
        {
            ++nWithin;
            EXPECT_TRUE(still[i] == free[i]) << "point " << i << " at y " << p0[i].y();
        }
    }
    ASSERT_GT(nWithin, 0);
    std::cout
        << controlPoints << " beyond 2 supportRadius, largest motion over the"
        << " bump's: farField still " << farStill/bump << ", interpolated "
        << farFree/bump << std::endl;
    EXPECT_LE(farStill, 1e-4*bump) << controlPoints;
    // the case's premise: the interpolant's own far field moves
    EXPECT_GT(farFree, 1e-3*bump) << controlPoints;
}

INSTANTIATE_TEST_SUITE_P
(
    Selections,
    FarField,
    ::testing::Values
    (
        "selection all;",
        "selection greedy; tolerance 1e-3;",
        "selection dynamic; tolerance 1e-3;",
        "selection dynamic; swapRule nearest; tolerance 1e-3;"
    ),
    [](const auto& info)
    {
        const std::string& s = info.param;
        return
            s.find("nearest") != std::string::npos ? std::string("dynamicNearest")
          : s.find("dynamic") != std::string::npos ? std::string("dynamic")
          : s.find("greedy") != std::string::npos ? std::string("greedy")
          : std::string("all");
    }
);


TEST(FarField, CellsOfTheBlendAreChecked)
{
    // the bottom wall lifted by half the radius: the blend between R and 2R
    // takes the lift; its cells (beyond R of every boundary point in the
    // box's middle) are checked one by one, not as one affine cell for all
    testCase c
    (
        2, 40,
        "movingPatches (bottom); staticPatches (top left right);"
        " supportRadius 0.2;"
    );
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    ++c.runTime();
    prescribe(solver.pointDisplacement(), "bottom", [](const point&)
    {
        return vector(0, 0.1, 0);
    });
    const pointField p0(solver.points0());
    const pointField p(ms->newPoints());
    const scalarField q
    (
        cellByCellQuality(c.mesh(), identity(c.mesh().nCells()), p0, p)
    );
    // the premise: cells of the blend in the box's middle are deformed
    scalar bandLeast = 1;
    forAll(q, celli)
    {
        const point& x = c.mesh().cellCentres()[celli];
        if (x.y() > 0.25 && x.y() < 0.35 && x.x() > 0.3 && x.x() < 0.7)
        {
            bandLeast = min(bandLeast, q[celli]);
        }
    }
    EXPECT_LT(bandLeast, 0.95);
    // the logged check is the whole mesh's, cell by cell
    const std::vector<std::vector<double>> rows(stepRows(c));
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_NEAR(rows[0][cMinQ], gMin(q), 1e-12);
    EXPECT_NEAR(rows[0][cMeanQ], gAverage(q), 1e-12);
}


TEST(FarField, WeightIsTheQuinticSmoothstepBetweenTheRadii)
{
    EXPECT_EQ(dcpRBFFarField::weight(0.5, 1, 2), 1);
    EXPECT_EQ(dcpRBFFarField::weight(1, 1, 2), 1);
    EXPECT_EQ(dcpRBFFarField::weight(2, 1, 2), 0);
    EXPECT_EQ(dcpRBFFarField::weight(3, 1, 2), 0);
    EXPECT_NEAR(dcpRBFFarField::weight(1.5, 1, 2), 0.5, 1e-15);
    // 1 - (10 t^3 - 15 t^4 + 6 t^5) at t = 0.25
    EXPECT_NEAR(dcpRBFFarField::weight(1.25, 1, 2), 1 - 0.103515625, 1e-15);
    // flat at both ends (no kink in the displacement)
    const scalar h = 1e-4;
    EXPECT_LT((1 - dcpRBFFarField::weight(1 + h, 1, 2))/h, 1e-6);
    EXPECT_LT(dcpRBFFarField::weight(2 - h, 1, 2)/h, 1e-6);
}


} // namespace

// ************************************************************************* //
