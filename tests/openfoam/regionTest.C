/*---------------------------------------------------------------------------*\
  dcpRBF tests: a region (cellZone) and its frame
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    A box whose lower half is a cellZone, its bottom wall bulging: with the
    zone as dcpRBF's region (cellZone in dcpRBFCoeffs, or in the motion
    solver's dictionary as dynamicMultiMotionSolverFvMesh gives it) the
    points outside the zone and those on its border do not move at all, the
    zone's mesh is valid and only its cells are checked; the border makes
    the far field still without staticPatches. With a frame (a
    solid-body motion) the region's new points are the frame's transform of
    the points without it, the others stay. A moving patch outside the
    region, a zone that does not exist and two regions are refused, naming
    the keyword, and so is a 2D mesh's frame that would move points out of
    the plane.

\*---------------------------------------------------------------------------*/

#include "cellByCellQuality.H"
#include "testHelpers.H"
#include "bumpRun.H"
#include "dcpRBFCellQuality.H"
#include "cellZone.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

const std::string coeffs =
    "movingPatches (bottom); staticPatches (left right top);"
    " supportRadius 0.3;";

//- The cells whose centre is below y (or above it)
labelList cellsBelow(const fvMesh& mesh, const scalar y, const bool below = true)
{
    DynamicList<label> cells;
    forAll(mesh.cellCentres(), celli)
    {
        if ((mesh.cellCentres()[celli].y() < y) == below) cells.append(celli);
    }
    return labelList(std::move(cells));
}

//- A cellZone of the cells whose centre is below y (or above it)
void addZone(fvMesh& mesh, const word& name, const scalar y, const bool below = true)
{
    List<cellZone*> zones
    (
        1, new cellZone(name, cellsBelow(mesh, y, below), 0, mesh.cellZones())
    );
    mesh.addZones(List<pointZone*>(), List<faceZone*>(), zones);
}

//- The new points of one step of a bump of the bottom wall
pointField bumpStep(testCase& c, motionSolver& ms)
{
    auto& solver = refCast<dcpRBFMotionSolver>(ms);
    ++c.runTime();
    prescribe(solver.pointDisplacement(), "bottom", [](const point& x)
    {
        return vector(0, 0.05*Foam::sin(constant::mathematical::pi*x.x()), 0);
    });
    return pointField(ms.newPoints());
}

//- A point turned by angle about (0.5 0.25 0) and z: the frames' transform
//  (rotatingMotion's, about its origin)
point turnedByFrame(const point& p, const scalar angle)
{
    const vector r(p - vector(0.5, 0.25, 0));
    return
        vector(0.5, 0.25, 0)
      + vector
        (
            Foam::cos(angle)*r.x() - Foam::sin(angle)*r.y(),
            Foam::sin(angle)*r.x() + Foam::cos(angle)*r.y(),
            r.z()
        );
}

//- The points of the zone's cells, and those of the other cells
void zonePoints(const polyMesh& mesh, const word& zone, boolList& in, boolList& out)
{
    in.setSize(mesh.nPoints(), false);
    out.setSize(mesh.nPoints(), false);
    const labelList& cells = mesh.cellZones()[mesh.cellZones().findZoneID(zone)];
    boolList isIn(mesh.nCells(), false);
    UIndirectList<bool>(isIn, cells) = true;
    forAll(mesh.cellPoints(), celli)
    {
        for (const label pointi : mesh.cellPoints()[celli])
        {
            (isIn[celli] ? in : out)[pointi] = true;
        }
    }
}


TEST(Region, OutsideAndBorderStillZoneValidOnlyItsCellsChecked)
{
    testCase c(2, 20, coeffs + " cellZone lower;");
    addZone(c.mesh(), "lower", 0.5);
    autoPtr<motionSolver> ms(select(c));
    const pointField p0(c.mesh().points());
    const pointField p(bumpStep(c, ms()));
    boolList in, out;
    zonePoints(c.mesh(), "lower", in, out);
    label nOutside = 0;
    label nBorder = 0;
    scalar moved = 0;
    forAll(p, i)
    {
        if (out[i])
        {
            // outside or on the border: not moved at all
            EXPECT_TRUE(p[i] == p0[i]) << "point " << i << " at " << p0[i].y();
            nOutside += !in[i];
            nBorder += in[i];
        }
        else
        {
            moved = max(moved, mag(p[i] - p0[i]));
        }
    }
    EXPECT_GT(nOutside, 0);
    EXPECT_GT(nBorder, 0);
    // dcpRBF's displacement outside the region and on its border: none
    // (the border's points are static: the interpolant is zero on them, not
    // cut off after it)
    const vectorField& d =
        refCast<dcpRBFMotionSolver>(ms()).pointDisplacement().primitiveField();
    scalar outsideDisplacement = 0;
    scalar borderDisplacement = 0;
    forAll(d, i)
    {
        if (!in[i]) outsideDisplacement = max(outsideDisplacement, mag(d[i]));
        else if (out[i]) borderDisplacement = max(borderDisplacement, mag(d[i]));
    }
    EXPECT_EQ(outsideDisplacement, 0);
    EXPECT_EQ(borderDisplacement, 0);
    EXPECT_GT(moved, 1e-2);
    const labelList cells(identity(c.mesh().nCells()));
    EXPECT_GT(gMin(cellByCellQuality(c.mesh(), cells, p0, p)), 0.5);
    // the check: the zone's cells alone
    const std::vector<std::vector<double>> rows(stepRows(c));
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(label(rows[0][cCells]), c.mesh().cellZones()[0].size());
}


TEST(Region, TheSolverDictionarysCellZoneAsDynamicMultiGivesIt)
{
    // the zone named where dynamicMultiMotionSolverFvMesh puts it: the same
    // points as cellZone in dcpRBFCoeffs, bit for bit
    testCase a(2, 20, coeffs + " cellZone lower;");
    addZone(a.mesh(), "lower", 0.5);
    autoPtr<motionSolver> msA(select(a));
    const pointField pa(bumpStep(a, msA()));

    testCase b(2, 20, coeffs);
    b.write
    (
        "constant/dynamicMeshDict", "dictionary",
        "dynamicFvMesh dynamicMotionSolverFvMesh;\nmotionSolver dcpRBF;\n"
        "cellZone lower;\ndcpRBFCoeffs\n{\n" + coeffs + "\n}\n"
    );
    addZone(b.mesh(), "lower", 0.5);
    autoPtr<motionSolver> msB(select(b));
    const pointField pb(bumpStep(b, msB()));
    ASSERT_EQ(pa.size(), pb.size());
    forAll(pa, i)
    {
        EXPECT_TRUE(pa[i] == pb[i]) << "point " << i;
    }
}


TEST(Region, FrameTransformsTheRegion)
{
    // the same step with a rotating frame: the points are the frame's
    // transform of those without it (a region that shares no point with
    // cells outside: here the whole box)
    const std::string frame =
        " frame { solidBodyMotionFunction rotatingMotion; rotatingMotionCoeffs"
        " { origin (0.5 0.25 0); axis (0 0 1); omega 0.3; } }";
    testCase still(2, 20, coeffs);
    autoPtr<motionSolver> msStill(select(still));
    const pointField p(bumpStep(still, msStill()));

    testCase turned(2, 20, coeffs + frame);
    autoPtr<motionSolver> msTurned(select(turned));
    const pointField q(bumpStep(turned, msTurned()));

    const scalar angle = 0.3*turned.runTime().value();
    ASSERT_GT(angle, 0);
    scalar err = 0;
    label nTurned = 0;
    forAll(q, i)
    {
        err = max(err, mag(q[i] - turnedByFrame(p[i], angle)));
        nTurned += mag(q[i] - p[i]) > 1e-6;
    }
    EXPECT_LT(err, 1e-12);
    EXPECT_GT(nTurned, 0);
}


// A solid-body frame alone (every patch fixedValue: no moving patch, given
// as movingPatches () or inferred): the points are the frame's transform of
// the reference points, the RBF's part zero
TEST(Region, FrameAloneNeedsNoMovingPatch)
{
    const std::string frame =
        " frame { solidBodyMotionFunction rotatingMotion; rotatingMotionCoeffs"
        " { origin (0.5 0.25 0); axis (0 0 1); omega 0.3; } }";
    for (const std::string lists : {"", "movingPatches (); staticPatches (top bottom left right);"})
    {
        SCOPED_TRACE(lists.empty() ? "inferred" : lists);
        testCase c(2, 20, lists + frame);
        autoPtr<motionSolver> ms(select(c));
        const pointField p0(refCast<dcpRBFMotionSolver>(ms()).points0());
        ++c.runTime();
        const pointField q(ms->newPoints());
        const scalar angle = 0.3*c.runTime().value();
        ASSERT_GT(angle, 0);
        scalar err = 0;
        forAll(q, i)
        {
            err = max(err, mag(q[i] - turnedByFrame(p0[i], angle)));
        }
        EXPECT_LT(err, 1e-12);
    }
}


TEST(Region, OutsideStaysWhereTheMeshHasIt)
{
    // another zone's solver moved the points outside the region (as under
    // dynamicMultiMotionSolverFvMesh): they stay where the mesh has them
    testCase c(2, 20, coeffs + " cellZone lower;");
    addZone(c.mesh(), "lower", 0.5);
    autoPtr<motionSolver> ms(select(c));
    boolList in, out;
    zonePoints(c.mesh(), "lower", in, out);
    // (the border points cells outside share too: dynamicMotionSolverList-
    // FvMesh sums the solvers' moves, each solver's where it does not act
    // must be none)
    pointField moved(c.mesh().points());
    forAll(moved, i)
    {
        if (out[i]) moved[i] += vector(0.01, 0, 0);
    }
    c.mesh().movePoints(moved);
    const pointField p(bumpStep(c, ms()));
    label nShared = 0;
    forAll(p, i)
    {
        if (out[i])
        {
            EXPECT_TRUE(p[i] == moved[i]) << "outside or shared point " << i;
            nShared += in[i];
        }
    }
    EXPECT_GT(nShared, 0);
}


TEST(Region, BorderMakesTheFarFieldStill)
{
    // no staticPatches: the region's border is static, so the far field is
    // still by default (nothing beyond twice supportRadius from the moving
    // wall moves); without the weight the interpolant's polynomial would
    // move the zone's middle (the bump's lift against the still border)
    const scalar R = 0.1;
    testCase c
    (
        2, 20,
        "movingPatches (bottom); staticPatches (); supportRadius "
      + std::to_string(R) + "; cellZone lower;"
    );
    addZone(c.mesh(), "lower", 0.5);
    autoPtr<motionSolver> ms(select(c));
    const pointField p0(c.mesh().points());
    const pointField p(bumpStep(c, ms()));
    scalar far = 0;
    scalar near = 0;
    label nFar = 0;
    forAll(p, i)
    {
        const point& x = p0[i];
        if (x.x() < 1e-9 || x.x() > 1 - 1e-9) continue;
        if (x.y() > 2*R + 1e-9 && x.y() < 0.5 - 1e-9)
        {
            far = max(far, mag(p[i] - x));
            ++nFar;
        }
        else if (x.y() > 1e-9 && x.y() < R)
        {
            near = max(near, mag(p[i] - x));
        }
    }
    EXPECT_GT(nFar, 0);
    EXPECT_LE(far, 1e-4*0.05) << "the zone's far field moved";
    EXPECT_GT(near, 1e-3);
}


TEST(Region, RefusalsNameTheKeyword)
{
    const auto message = [](testCase& c)
    {
        try
        {
            autoPtr<motionSolver> ms(select(c));
        }
        catch (const Foam::error& e)
        {
            return std::string(e.message());
        }
        return std::string("no error");
    };
    {
        // the moving wall outside the zone (the upper half)
        testCase c(2, 8, coeffs + " cellZone upper;");
        addZone(c.mesh(), "upper", 0.5, false);
        const std::string m(message(c));
        EXPECT_NE(m.find("outside the region"), std::string::npos) << m;
    }
    {
        testCase c(2, 8, coeffs + " cellZone lower;");
        c.write
        (
            "constant/dynamicMeshDict", "dictionary",
            "dynamicFvMesh dynamicMotionSolverFvMesh;\nmotionSolver dcpRBF;\n"
            "cellZone upper;\ndcpRBFCoeffs\n{\n" + coeffs + " cellZone lower;\n}\n"
        );
        List<cellZone*> zones(2);
        zones[0] = new cellZone("lower", cellsBelow(c.mesh(), 0.5), 0, c.mesh().cellZones());
        zones[1] = new cellZone("upper", cellsBelow(c.mesh(), 0.5, false), 1, c.mesh().cellZones());
        c.mesh().addZones(List<pointZone*>(), List<faceZone*>(), zones);
        const std::string m(message(c));
        EXPECT_NE(m.find("Keyword cellZone"), std::string::npos) << m;
    }
    {
        testCase c(2, 8, coeffs + " frame rotatingMotion;");
        const std::string m(message(c));
        EXPECT_NE(m.find("Keyword frame"), std::string::npos) << m;
    }
    {
        // a 2D mesh's frame turning about an axis in its plane (at the
        // first step: the refusal needs the motion)
        testCase c
        (
            2, 8,
            coeffs + " frame { solidBodyMotionFunction rotatingMotion;"
            " rotatingMotionCoeffs { origin (0 0 0); axis (1 0 0); omega 1; } }"
        );
        std::string m("no error");
        try
        {
            autoPtr<motionSolver> ms(select(c));
            bumpStep(c, ms());
        }
        catch (const Foam::error& e)
        {
            m = e.message();
        }
        EXPECT_NE(m.find("Keyword frame: at time"), std::string::npos) << m;
        EXPECT_NE(m.find("across its plane"), std::string::npos) << m;
    }
    {
        // a solid body tearing its region from the cells around
        testCase c
        (
            2, 8,
            coeffs + " cellZone lower; frame { solidBodyMotionFunction"
            " rotatingMotion; rotatingMotionCoeffs { origin (0 0 0);"
            " axis (0 0 1); omega 1; } }"
        );
        addZone(c.mesh(), "lower", 0.5);
        const std::string m(message(c));
        EXPECT_NE(m.find("Keyword frame: the region (cellZone lower) shares"), std::string::npos) << m;
    }
    {
        // a moving patch crossing the region's border
        testCase c
        (
            2, 8,
            "movingPatches (left); staticPatches (right top bottom);"
            " supportRadius 0.3; cellZone lower;"
        );
        addZone(c.mesh(), "lower", 0.5);
        const std::string m(message(c));
        EXPECT_NE(m.find("patch left crosses the border"), std::string::npos) << m;
    }
}

} // namespace

// ************************************************************************* //
