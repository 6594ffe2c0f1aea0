/*---------------------------------------------------------------------------*\
  dcpRBF tests: the quality region's check covers every cell whose points move
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "cellByCellQuality.H"
#include "testHelpers.H"
#include "dcpRBFQualityRegion.H"
#include "dcpRBFCellQuality.H"
#include "dcpRBFPlaneProjection.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace Foam;
using namespace Foam::dcpRBFTest;

// The check covers every cell whose points can move: on a mesh moved
// affinely (the polynomial alone) beyond the radius of the sources and
// randomly within it (a cell there folded), the summary's check has the
// minimum, the inverted count and the mean of every cell of the mesh,
// measured cell by cell; the region (centres within reach of the moving
// points) alone has not. In 2D and 3D, a radius that reaches some cells'
// points but no cell centre (the region empty: every cell checked all the
// same), and with the affine cells measured one for all or each on its own
// (affineBeyond false): the same figures
TEST(QualityRegion, CheckCoversEveryCellWhosePointsMove)
{
    for (const label dim : {2, 3})
    {
        for (const scalar radius : {0.25, 0.04})
        {
            testCase c(dim, 10, "movingPatches (bottom); staticPatches (top); supportRadius 1;");
            const polyMesh& mesh = c.mesh();
            const pointField p0(mesh.points());
            const dcpRBFPlaneProjection projection(mesh);
            const polyPatch& bottom =
                mesh.boundaryMesh()[mesh.boundaryMesh().findPatchID("bottom")];
            const dcprbf::Points moving
            (
                projection.toCore(pointField(bottom.localPoints()))
            );
            const auto metric = dcprbf::TetQuality::Metric::sizeShape;

            // within radius of the bottom: random, a point pushed through
            // its cell; beyond: x -> x + a + B x (in the plane in 2D)
            const tensor B(0.05, 0.3, 0, -0.1, 0.02, 0, 0, 0, dim == 3 ? 0.04 : 0);
            const vector a(0.1, -0.2, 0);
            std::mt19937 gen(3);
            std::uniform_real_distribution<scalar> u(-0.01, 0.01);
            pointField p(p0);
            label pushed = -1;
            forAll(p, i)
            {
                if (p0[i].y() <= radius + 1e-12)
                {
                    std::mt19937 g(unsigned(std::lround(1e4*p0[i].x()) + 7919*std::lround(1e4*p0[i].y())));
                    p[i] += vector(u(g), u(g), dim == 3 ? u(gen) : 0);
                    if (pushed < 0) pushed = i;
                }
                else
                {
                    p[i] += a + (B & p0[i]);
                }
            }
            ASSERT_GE(pushed, 0);
            forAll(p, i)
            {
                // the pushed point (2D: and its twin) up through its
                // cell (0.1 high)
                if (mag(p0[i].x() - p0[pushed].x()) + mag(p0[i].y() - p0[pushed].y()) < 1e-9)
                {
                    p[i].y() = p0[pushed].y() + 0.15;
                }
            }
            const scalarField all
            (
                cellByCellQuality(mesh, identity(mesh.nCells()), p0, p, metric)
            );
            label nInverted = 0;
            for (const scalar q : all) nInverted += (q <= 0);
            ASSERT_GT(nInverted, 0);

            for (const bool affineBeyond : {true, false})
            {
                const dcpRBFQualityRegion region
                (
                    mesh, projection, p0, moving, moving, radius, affineBeyond, metric
                );
                const dcpRBFQualityRegion::summary s(region.measure(p, 2));
                SCOPED_TRACE
                (
                    std::to_string(dim) + "D, radius " + std::to_string(radius)
                  + (affineBeyond ? ", one affine cell for all" : ", every cell")
                );
                EXPECT_EQ(s.nChecked, mesh.nCells());
                EXPECT_EQ(region.nChecked(), mesh.nCells());
                EXPECT_NEAR(s.checkedMin, min(all), 1e-12);
                EXPECT_EQ(s.checkedInverted, nInverted);
                EXPECT_NEAR(s.checkedMean, average(all), 1e-12);
                ASSERT_TRUE(s.hasLowest);
                EXPECT_NEAR(s.lowest[0], min(all), 1e-12);
                if (radius < 0.05)
                {
                    // no centre within reach: the region is empty
                    EXPECT_EQ(region.size(), 0);
                }
                else
                {
                    // the region alone sees fewer cells
                    EXPECT_LT(s.nCells, s.nChecked);
                }
            }
        }
    }
}


// ************************************************************************* //
