/*---------------------------------------------------------------------------*\
  dcpRBF tests: the quality region's flat scan against dcpRBFCellQuality
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "dcpRBFQualityRegion.H"
#include "dcpRBFCellQuality.H"
#include "cellByCellQuality.H"
#include "dcpRBFPlaneProjection.H"
#include "dcpRBFPlanarCells.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

//- The region within radius of the bottom patch, measured by its flat scan
//  and cell by cell by dcpRBFCellQuality, on a randomly deformed mesh with
//  one cell folded
void compareScans(const label dim, const scalar radius)
{
    testCase c(dim, 10, "movingPatches (bottom); staticPatches (top); supportRadius 1;");
    const polyMesh& mesh = c.mesh();
    const pointField p0(mesh.points());
    const dcpRBFPlaneProjection projection(mesh);
    const polyPatch& bottom = mesh.boundaryMesh()[mesh.boundaryMesh().findPatchID("bottom")];
    const dcprbf::Points moving(projection.toCore(pointField(bottom.localPoints())));

    for (const auto metric :
        {dcprbf::TetQuality::Metric::sizeShape, dcprbf::TetQuality::Metric::shape})
    {
        const dcpRBFQualityRegion region
        (
            mesh, projection, p0, moving, moving, radius, true, metric
        );
        ASSERT_GT(region.cells().size(), 0);
        // subsets (a trial window's parts) copied from the region's scans:
        // the flat one (3D), the polygons' (2D); the cells' points listed
        // only for the flat scan (a polygon reads one cap's)
        ASSERT_TRUE(region.cellQuality().subsettable());
        EXPECT_EQ(region.cellQuality().pointIds() != nullptr, dim == 3);
        // (constructed without cells: no subsets, an error)
        EXPECT_THROW
        (
            dcpRBFCellQuality(dcpRBFCellQuality(mesh, metric), labelList({0}), p0),
            Foam::error
        );
        if (radius < 1)
        {
            ASSERT_LT(region.cells().size(), mesh.nCells());
        }

        // random displacement of 0.2 cell sizes in the plane (2D: the same
        // for front and back points), then a point pushed through its cell
        std::mt19937 gen(5);
        std::uniform_real_distribution<scalar> u(-0.02, 0.02);
        pointField p(p0);
        forAll(p, i)
        {
            // (seeded by the rounded position: front and back twins differ
            // in the last digits)
            std::mt19937 g
            (
                unsigned(std::lround(1e4*p0[i].x()) + 7919*std::lround(1e4*p0[i].y()))
            );
            const scalar dz = dim == 3 ? u(gen) : 0;
            p[i] += vector(u(g), u(g), dz);
        }
        const label victim = mesh.cellPoints()[region.cells()[0]][0];
        const point inside(mesh.cellCentres()[region.cells()[0]]);
        forAll(p, i)
        {
            // every point at the victim's position (2D: its front/back twin)
            if (mag(p0[i].x() - p0[victim].x()) + mag(p0[i].y() - p0[victim].y()) < 1e-9)
            {
                p[i].x() = 2*inside.x() - p0[victim].x();
                p[i].y() = 2*inside.y() - p0[victim].y();
            }
        }

        const scalarField q(region.quality(p));
        const scalarField ref
        (
            cellByCellQuality(mesh, region.cells(), p0, p, metric)
        );
        ASSERT_EQ(q.size(), ref.size());
        label nInverted = 0;
        forAll(q, i)
        {
            EXPECT_NEAR(q[i], ref[i], 1e-10) << i;
            nInverted += (ref[i] <= 0);
        }
        EXPECT_GT(nInverted, 0);
        EXPECT_NEAR(min(q), min(ref), 1e-10);

        // every 7th cell, the list reversed, and every 3rd after it (the
        // scans' scratch numbering reset between subsets): bit for bit
        for (const label stride : {7, 3})
        {
            labelList positions;
            for (label i = region.cells().size() - 1; i >= 0; i -= stride)
            {
                positions.append(i);
            }
            const dcpRBFCellQuality sub(region.cellQuality(), positions, p0);
            const scalarField qs(sub.compute(p));
            ASSERT_EQ(qs.size(), positions.size());
            forAll(qs, k)
            {
                EXPECT_EQ(qs[k], q[positions[k]]) << dim << "D, position " << positions[k];
            }
        }

        const dcpRBFQualityRegion::summary s(region.measure(p, 2));
        EXPECT_EQ(s.nCells, region.cells().size());
        EXPECT_EQ(s.minQuality, min(q));
        EXPECT_EQ(s.nInverted, nInverted);
        EXPECT_EQ(s.worst[0][0], min(q));
        ASSERT_EQ(s.best.size(), 2);
        EXPECT_EQ(s.best[0][0], max(q));

        // without the best cells (no swap rule reads them): the same
        // figures and worst cells, no best ones
        const dcpRBFQualityRegion::summary w(region.measure(p, 2, scalarField(), -1, false));
        EXPECT_EQ(w.minQuality, s.minQuality);
        EXPECT_EQ(w.meanQuality, s.meanQuality);
        EXPECT_EQ(w.checkedMean, s.checkedMean);
        EXPECT_EQ(w.nInverted, s.nInverted);
        EXPECT_EQ(w.worst, s.worst);
        EXPECT_EQ(w.best.size(), 0);
    }
}

TEST(QualityRegion, FlatScanEqualsCellQuality3D)
{
    compareScans(3, 2);
    compareScans(3, 0.35);
}

TEST(QualityRegion, FlatScanEqualsCellQuality2D)
{
    // the 2D mesh's cells are measured from their polygons (the comparisons
    // below check them against the 3D decomposition)
    testCase c(2, 10, "movingPatches (bottom); staticPatches (top); supportRadius 1;");
    const dcpRBFPlanarCells planar(c.mesh(), identity(c.mesh().nCells()), c.mesh().points());
    EXPECT_EQ(planar.planar().size(), c.mesh().nCells());
    EXPECT_EQ(planar.others().size(), 0);
    testCase c3(3, 4, "movingPatches (bottom); staticPatches (top); supportRadius 1;");
    EXPECT_EQ
    (
        dcpRBFPlanarCells(c3.mesh(), identity(c3.mesh().nCells()), c3.mesh().points())
            .planar().size(),
        0
    );

    compareScans(2, 2);
    compareScans(2, 0.35);
}

TEST(QualityRegion, TwistedPrismIsNoPlanarCell)
{
    // a cell whose front points sit at the in-plane positions of the back
    // points' neighbours: every back point has a twin, but the side faces
    // do not join an edge to its twins, so the polygon is not the cell
    testCase c(2, 4, "movingPatches (bottom); staticPatches (top); supportRadius 1;");
    const polyMesh& mesh = c.mesh();
    const label celli = 5;
    const dcpRBFPlanarCells straight(mesh, labelList(1, celli), mesh.points());
    ASSERT_EQ(straight.planar().size(), 1);

    pointField p0(mesh.points());
    const cell& cl = mesh.cells()[celli];
    face back, front;
    for (const label facei : cl)
    {
        const face& f = mesh.faces()[facei];
        if (f.size() == 4 && mag(f.areaNormal(p0).z()) > 0.99*mag(f.areaNormal(p0)))
        {
            (p0[f[0]].z() < 0.05 ? back : front) = f;
        }
    }
    ASSERT_EQ(back.size(), 4);
    ASSERT_EQ(front.size(), 4);
    forAll(back, i)
    {
        // the front twin of back[i] moved to back[i+1]'s position
        for (const label pf : front)
        {
            const point& x = mesh.points()[pf];
            const point& y = mesh.points()[back[i]];
            if (mag(x.x() - y.x()) + mag(x.y() - y.y()) < 1e-9)
            {
                p0[pf].x() = mesh.points()[back.nextLabel(i)].x();
                p0[pf].y() = mesh.points()[back.nextLabel(i)].y();
            }
        }
    }
    const dcpRBFPlanarCells twisted(mesh, labelList(1, celli), p0);
    EXPECT_EQ(twisted.planar().size(), 0);
    EXPECT_EQ(twisted.others().size(), 1);
}

TEST(QualityRegion, MixedPolygonAndDecomposedCellsEqualCellQuality2D)
{
    // reference points with a few back-plane points shifted in the plane:
    // the cells using them are no prisms (measured by the decomposition),
    // the others are (from their polygons); every value in its place
    testCase c(2, 10, "movingPatches (bottom); staticPatches (top); supportRadius 1;");
    const polyMesh& mesh = c.mesh();
    pointField p0(mesh.points());
    label nShifted = 0;
    forAll(p0, i)
    {
        if (p0[i].z() < 0.05 && (i % 7) == 3)
        {
            p0[i].x() += 0.01;
            ++nShifted;
        }
    }
    ASSERT_GT(nShifted, 0);
    const labelList cells(identity(mesh.nCells()));
    const dcpRBFPlanarCells sorted(mesh, cells, p0);
    ASSERT_GT(sorted.planar().size(), 0);
    ASSERT_GT(sorted.others().size(), 0);

    // an in-plane motion, the same for twins (by their unshifted position)
    pointField p(p0);
    forAll(p, i)
    {
        const point& x = mesh.points()[i];
        p[i] += vector(0.02*std::sin(7*x.y()), 0.03*std::cos(5*x.x()), 0);
    }
    const dcpRBFCellQuality quality(mesh, cells, p0, dcprbf::TetQuality::Metric::sizeShape);
    const scalarField q(quality.compute(p));
    const scalarField ref(cellByCellQuality(mesh, cells, p0, p, dcprbf::TetQuality::Metric::sizeShape));
    ASSERT_EQ(q.size(), ref.size());
    forAll(q, i)
    {
        EXPECT_NEAR(q[i], ref[i], 1e-10) << i;
    }
    EXPECT_LT(min(ref), 1 - 1e-3);

    // subsets (a trial window's parts) of both kinds of cells, interleaved,
    // the list reversed, two in a row: each value as the whole's, bit for
    // bit; a position out of range refused
    for (const label stride : {3, 2})
    {
        labelList positions;
        for (label i = cells.size() - 1; i >= 0; i -= stride) positions.append(i);
        const dcpRBFCellQuality sub(quality, positions, p0);
        const scalarField qs(sub.compute(p));
        ASSERT_EQ(qs.size(), positions.size());
        forAll(qs, k)
        {
            EXPECT_EQ(qs[k], q[positions[k]]) << "position " << positions[k];
        }
    }
    EXPECT_THROW
    (
        dcpRBFCellQuality(quality, labelList({0, cells.size()}), p0),
        Foam::error
    );
    // reference points not the mesh's: refused
    EXPECT_THROW
    (
        dcpRBFCellQuality(quality, labelList({0}), pointField(p0.size() - 1, Zero)),
        Foam::error
    );
}


// within(x, r): the region's positions whose reference centre is strictly
// within r of x, ascending, as a brute-force search finds them; and a few of
// the region's cells measured on their own (a trial window's part: built from
// the mesh, or copied from the region's scan) have the region's values, bit
// for bit
TEST(QualityRegion, WithinAndAFewCellsOnTheirOwn)
{
    testCase c(3, 10, "movingPatches (bottom); staticPatches (top); supportRadius 1;");
    const polyMesh& mesh = c.mesh();
    const pointField p0(mesh.points());
    const dcpRBFPlaneProjection projection(mesh);
    const polyPatch& bottom = mesh.boundaryMesh()[mesh.boundaryMesh().findPatchID("bottom")];
    const dcprbf::Points moving(projection.toCore(pointField(bottom.localPoints())));
    const dcpRBFQualityRegion region
    (
        mesh, projection, p0, moving, moving, 2, true,
        dcprbf::TetQuality::Metric::sizeShape
    );
    const List<FixedList<scalar, 3>>& centres = region.centres();
    ASSERT_EQ(centres.size(), mesh.nCells());

    std::mt19937 gen(11);
    std::uniform_real_distribution<scalar> u(-0.1, 1.1);
    for (int k = 0; k < 20; ++k)
    {
        const Eigen::RowVector3d x(u(gen), u(gen), u(gen));
        for (const scalar r : {0.0, 0.05, 0.2, 0.6})
        {
            labelList expected;
            forAll(centres, i)
            {
                const scalar d0 = centres[i][0] - x(0);
                const scalar d1 = centres[i][1] - x(1);
                const scalar d2 = centres[i][2] - x(2);
                if (d0*d0 + d1*d1 + d2*d2 < r*r) expected.append(i);
            }
            EXPECT_EQ(region.within(x, r), expected) << "r " << r;
        }
    }

    // 12 of the region's cells (positions 7, 90, ...) on their own, and
    // 12 neighbours (positions 40-51: Morton order, faces shared)
    pointField p(p0);
    forAll(p, i)
    {
        p[i] += vector(0.03*std::sin(9*p0[i].y()), 0.02*std::cos(7*p0[i].z()), 0.02*p0[i].x());
    }
    const scalarField all(region.quality(p));
    for (const label step : {83, 1})
    {
        labelList positions, cells;
        for (label i = step == 1 ? 40 : 7; positions.size() < 12; i += step)
        {
            positions.append(i);
            cells.append(region.cells()[i]);
        }
        const dcpRBFCellQuality few(mesh, cells, p0, dcprbf::TetQuality::Metric::sizeShape);
        const scalarField q(few.compute(p));
        ASSERT_EQ(q.size(), positions.size());
        forAll(q, k)
        {
            EXPECT_EQ(q[k], all[positions[k]]) << "cell " << cells[k];
        }
        // and copied from the region's scan (a trial window's part in 3D)
        ASSERT_TRUE(region.cellQuality().subsettable());
        const dcpRBFCellQuality copied(region.cellQuality(), positions, p0);
        EXPECT_EQ(copied.compute(p), q);
    }
}

} // namespace


// ************************************************************************* //
