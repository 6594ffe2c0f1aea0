/*---------------------------------------------------------------------------*\
  dcpRBF tests
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    qualityScan lowest (the worst cells measured exactly, the others
    bounded) against qualityScan all on a 3D box of hexahedra whose bottom
    wall bulges: the same points at every step, bit for bit, and the same
    rows of dcpRBF.dat (control points, guard, minimum quality, inverted
    cells, boundary error, trials undone) but the mean quality, which is
    nan where cells were bounded (steps not written) and the same where
    every cell was measured.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "bumpRun.H"
#include "dcpRBFMotionSolver.H"
#include "dcpRBFQualityRegion.H"
#include "dcpRBFPlaneProjection.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

struct scanRun
{
    std::vector<pointField> points;
    std::vector<std::vector<double>> rows;
};

//- The bulge a sin(pi x) sin(pi z), a = 0.045 x step, on the bottom wall
//  of a 10^3 box (cells thinner at the bottom), writing every 4th step
scanRun bulge(const std::string& controlPoints, const std::string& scan, const label nSteps)
{
    testCase c
    (
        3, 10,
        "movingPatches (bottom); staticPatches (top left right front back);"
        " supportRadius 0.8; qualityScan " + scan + ";"
        " controlPoints { " + controlPoints + " }",
        "wall", "{ type fixedValue; value uniform (0 0 0); }", "(1 10 1)"
    );
    c.write
    (
        "system/controlDict", "dictionary",
        "application moveDynamicMesh; startFrom startTime; startTime 0;"
        " stopAt endTime; endTime 100; deltaT 1; writeControl timeStep;"
        " writeInterval 4; writeFormat ascii; writePrecision 17;"
        " timeFormat general; timePrecision 6; runTimeModifiable false;"
    );
    c.runTime().read();
    autoPtr<motionSolver> ms(select(c));
    scanRun r;
    for (label step = 1; step <= nSteps; ++step)
    {
        ++c.runTime();
        const scalar a = 0.045*step;
        prescribe(refCast<dcpRBFMotionSolver>(ms()).pointDisplacement(), "bottom", [a](const point& x)
        {
            const scalar pi = constant::mathematical::pi;
            return vector(0, a*std::sin(pi*x.x())*std::sin(pi*x.z()), 0);
        });
        const pointField p(ms->newPoints());
        c.mesh().movePoints(p);
        r.points.push_back(p);
    }
    r.rows = stepRows(c);
    return r;
}

} // namespace


TEST(QualityScan, LowestGivesAllsPointsAndLogButTheMean)
{
    const label nSteps = 9;
    for
    (
        const std::string cp :
        {
            "selection greedy; tolerance 1e-2;",
            "selection dynamic; tolerance 1e-2; nSwap 2;",
            "selection dynamic; tolerance 1e-2; swapRule nearest; nSwap 2;"
        }
    )
    {
        const scanRun all(bulge(cp, "all", nSteps)), lowest(bulge(cp, "lowest", nSteps));
        ASSERT_EQ(all.rows.size(), std::size_t(nSteps)) << cp;
        ASSERT_EQ(lowest.rows.size(), std::size_t(nSteps)) << cp;
        bool someInverted = false;
        label nBounded = 0;
        for (label s = 0; s < nSteps; ++s)
        {
            EXPECT_TRUE(all.points[s] == lowest.points[s]) << cp << " step " << s + 1;
            const auto& a = all.rows[s];
            const auto& l = lowest.rows[s];
            ASSERT_EQ(a.size(), l.size());
            for
            (
                const int col :
                {
                    int(cControl), int(cAdded), int(cRemoved), int(cGuard),
                    int(cCells), int(cMinQ), int(cError), int(cAtMax),
                    int(cUndone), 16
                }
            )
            {
                EXPECT_EQ(a[col], l[col]) << cp << " step " << s + 1 << " column " << col;
            }
            someInverted = someInverted || a[16] > 0;
            // the mean: the same where every cell was measured (the
            // written steps, every 4th; swapRule nearest), else nan
            const bool written = (s + 1) % 4 == 0;
            const bool nearest = cp.find("nearest") != std::string::npos;
            if (written || nearest || !std::isnan(l[cMeanQ]))
            {
                EXPECT_EQ(a[cMeanQ], l[cMeanQ]) << cp << " step " << s + 1;
            }
            nBounded += std::isnan(l[cMeanQ]);
        }
        // cells were bounded (not all measured) at some steps, but with
        // nearest
        if (cp.find("nearest") == std::string::npos)
        {
            EXPECT_GT(nBounded, 0) << cp;
        }
        // the bulge folds cells near the wall by the last steps
        EXPECT_TRUE(someInverted) << cp;
    }
}


TEST(QualityScan, RegionsLowestCellsAsTheFullMeasurement)
{
    // dcpRBFQualityRegion::measure with nLowest: its qualities' nLowest
    // lowest (positions and values), the n worst, the minima and the
    // inverted counts as the full measurement's
    testCase c
    (
        3, 12,
        "movingPatches (bottom); staticPatches (top left right front back);"
        " supportRadius 0.8;",
        "wall", "{ type fixedValue; value uniform (0 0 0); }", "(1 10 1)"
    );
    const polyMesh& mesh = c.mesh();
    const pointField& p0 = mesh.points();
    const dcpRBFPlaneProjection projection(mesh);
    const dcpRBFQualityRegion region
    (
        mesh, projection, p0, projection.toCore(p0), dcprbf::Points(0, 3),
        GREAT, false, dcprbf::TetQuality::Metric::sizeShape
    );
    for (const scalar a : {0.05, 0.3})
    {
        // a bulge of the bottom wall, fading upwards
        pointField p(p0);
        forAll(p, i)
        {
            const scalar pi = constant::mathematical::pi;
            p[i].y() += a*std::sin(pi*p0[i].x())*std::sin(pi*p0[i].z())*std::exp(-8*p0[i].y());
        }
        const dcpRBFQualityRegion::summary all(region.measure(p, 3));
        for (const label k : {1, 40, 300})
        {
            const dcpRBFQualityRegion::summary low(region.measure(p, 3, scalarField(), k));
            EXPECT_EQ(low.minQuality, all.minQuality);
            EXPECT_EQ(low.nInverted, all.nInverted);
            EXPECT_EQ(low.checkedMin, all.checkedMin);
            EXPECT_EQ(low.checkedInverted, all.checkedInverted);
            ASSERT_EQ(low.worst.size(), all.worst.size());
            forAll(all.worst, j)
            {
                EXPECT_TRUE(low.worst[j] == all.worst[j]) << "worst " << j;
            }
            EXPECT_TRUE(std::isnan(low.meanQuality));
            labelList byAll(identity(all.quality.size())), byLow(byAll);
            std::stable_sort(byAll.begin(), byAll.end(), [&](label i, label j) { return all.quality[i] < all.quality[j]; });
            std::stable_sort(byLow.begin(), byLow.end(), [&](label i, label j) { return low.quality[i] < low.quality[j]; });
            for (label j = 0; j < k; ++j)
            {
                EXPECT_EQ(byAll[j], byLow[j]) << "a " << a << " k " << k << " rank " << j;
                EXPECT_EQ(all.quality[byAll[j]], low.quality[byLow[j]]) << "rank " << j;
            }
        }
    }
}


// ************************************************************************* //
