/*---------------------------------------------------------------------------*\
  dcpRBF tests: rotationInterpolation
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    rotationInterpolation: a rigid motion of every patch together (no static
    patch) moves every point rigidly, in every selection mode, past half a
    turn; a rotating body turns the points within its circle rigidly and
    leaves the points beyond the blend in place, in one step of 150 degrees;
    a pivot axis moves the centre level with the body's centroid.

\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "unitConversion.H"

#include <gtest/gtest.h>

#include <vector>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

//- x -> c + R(x - c) + t, R a rotation by angle about axis
struct rigidMap
{
    tensor R;
    point c;
    vector t;
    vector operator()(const point& x) const { return c + (R & (x - c)) + t - x; }
};

rigidMap makeMap(const vector& axis, const scalar deg, const point& c, const vector& t)
{
    const vector n(axis/mag(axis));
    const scalar a = degToRad(deg);
    const tensor K(0, -n.z(), n.y(), n.z(), 0, -n.x(), -n.y(), n.x(), 0);
    return {I + Foam::sin(a)*K + (1 - Foam::cos(a))*(K & K), c, t};
}

class RigidEverything
:
    public ::testing::TestWithParam<std::tuple<label, std::string>>
{};

TEST_P(RigidEverything, EveryPointMovesRigidlyPastHalfATurn)
{
    const label dim = std::get<0>(GetParam());
    const std::string selection = std::get<1>(GetParam());
    const word patches(dim == 2 ? "(left right bottom top)" : "(\".*\")");
    testCase c
    (
        dim, 5,
        "movingPatches " + patches + "; staticPatches (); function WendlandC2;"
        " supportRadius 0.7; polynomial true; rotationInterpolation true;"
        " controlPoints { selection " + selection + "; }"
    );
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    const vector axis(dim == 2 ? vector(0, 0, 1) : vector(1, 2, -0.5));
    const pointField p0(solver.points0());

    // three steps, the last past half a turn
    for (const scalar deg : {60.0, 120.0, 200.0})
    {
        c.runTime()++;
        const rigidMap f(makeMap(axis, deg, point(0.3, 0.6, 0), vector(0.2, -0.1, 0)));
        for (const polyPatch& pp : c.mesh().boundaryMesh())
        {
            if (pp.type() != "empty") prescribe(solver.pointDisplacement(), pp.name(), f);
        }
        const pointField p(ms->newPoints());
        scalar err = 0;
        forAll(p, i)
        {
            vector expected(p0[i] + f(p0[i]));
            if (dim == 2) expected.z() = p0[i].z();
            err = max(err, mag(p[i] - expected));
        }
        EXPECT_LT(err, 1e-10) << dim << "D " << selection << " at " << deg << " deg";
    }
}

INSTANTIATE_TEST_SUITE_P
(
    DimAndSelection,
    RigidEverything,
    ::testing::Combine
    (
        ::testing::Values(label(2), label(3)),
        ::testing::Values("all", "greedy", "dynamic")
    ),
    [](const auto& info)
    {
        return std::to_string(std::get<0>(info.param)) + "D_"
            + std::get<1>(info.param);
    }
);


TEST(RotatingBody, RadialRingInnerCircleTurnsRigidlyOuterPointsStay)
{
    // bottom (y = 0, x in [0, 1]) turns 150 deg about its middle; the
    // radial ring (blendProfile log): the body's circle has radius 0.5, the
    // nearest static point (left/right, first cell up) is at
    // sqrt(0.25 + 0.1^2): the blend ends there
    testCase c
    (
        2, 10,
        "movingPatches (bottom); staticPatches (left right top);"
        " function WendlandC2; supportRadius 2; polynomial true;"
        " controlPoints { selection greedy; } rotationInterpolation true;"
        " rotation { centre (0.5 0 0); blendProfile log; }"
    );
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    const point centre(0.5, 0, 0);
    const rigidMap f(makeMap(vector(0, 0, 1), 150, centre, Zero));
    c.runTime()++;
    prescribe(solver.pointDisplacement(), "bottom", f);
    const pointField p0(solver.points0());
    const pointField p(ms->newPoints());

    const scalar outer = Foam::sqrt(0.25 + 0.01);
    label nInside = 0, nOutside = 0;
    forAll(p, i)
    {
        vector r0(p0[i] - centre);
        r0.z() = 0;
        if (mag(r0) < 0.5 - 1e-9)
        {
            vector expected(p0[i] + f(p0[i]));
            expected.z() = p0[i].z();
            EXPECT_LT(mag(p[i] - expected), 1e-12) << "point " << i;
            ++nInside;
        }
        else if (mag(r0) > outer + 1e-9)
        {
            EXPECT_LT(mag(p[i] - p0[i]), 1e-12) << "point " << i;
            ++nOutside;
        }
    }
    EXPECT_GT(nInside, 50);
    EXPECT_GT(nOutside, 100);
}


//- A 3D box (n cells a side) whose bottom (y = 0, x and z in [0, 1]) turns
//  about the z axis through (0.5 0 0), to each of the angles in turn, under
//  rotationInterpolation with the given entries of rotation: the points
//  after the last step, and what the solver wrote meanwhile
struct turnedBottom
{
    pointField points;
    std::string log;
};

turnedBottom turnBottom3D
(
    const label n,
    const std::string& rotation,
    const std::vector<scalar>& degrees
)
{
    testCase c
    (
        3, n,
        "movingPatches (bottom); staticPatches (top);"
        " function WendlandC2; supportRadius 2; polynomial true;"
        " controlPoints { selection greedy; } rotationInterpolation true;"
        " rotation { " + rotation + " }"
    );
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    turnedBottom result;
    result.log = captured([&]()
    {
        for (const scalar deg : degrees)
        {
            c.runTime()++;
            prescribe
            (
                solver.pointDisplacement(), "bottom",
                makeMap(vector(0, 0, 1), deg, point(0.5, 0, 0), Zero)
            );
            result.points = ms->newPoints();
        }
    });
    return result;
}

//- How often text occurs in log
label occurrences(const std::string& log, const std::string& text)
{
    label n = 0;
    for (auto at = log.find(text); at != std::string::npos; at = log.find(text, at + 1))
    {
        ++n;
    }
    return n;
}


TEST(RotatingBody, AxisCentresTheBlendLevelWithTheCentroid)
{
    // pitched 30 deg. With axis, the centre (0.5 0 0) moves along it to the
    // point level with the bottom's centroid, (0.5 0 0.5): the mesh is the
    // one that centre gives, and not the one (0.5 0 0) gives; the same in a
    // bodies entry
    const auto points = [](const std::string& rotation)
    {
        return turnBottom3D(6, rotation, {30}).points;
    };
    const pointField onAxis(points("centre (0.5 0 0); axis (0 0 2);"));
    const pointField level(points("centre (0.5 0 0.5);"));
    const pointField root(points("centre (0.5 0 0);"));
    const pointField body
    (
        points("bodies { b { patches (bottom); centre (0.5 0 0); axis (0 0 1); } }")
    );
    EXPECT_LT(max(mag(onAxis - level)), 1e-12);
    EXPECT_LT(max(mag(body - level)), 1e-12) << "axis in a bodies entry";
    EXPECT_GT(max(mag(root - level)), 1e-3) << "the centre does not change the mesh";
}


TEST(RotatingBody, TurningOffTheAxisIsWarnedAboutOnce)
{
    // 15 then 30 deg; axis (1 0 0) is the wrong pivot axis: a warning names
    // axis, once in the two steps; axis (0 0 1): none
    const auto warnings = [](const std::string& axis)
    {
        const std::string log
        (
            turnBottom3D(4, "centre (0.5 0 0); axis " + axis + ";", {15, 30}).log
        );
        return occurrences(log, "off its keyword axis");
    };
    EXPECT_EQ(warnings("(1 0 0)"), 1);
    EXPECT_EQ(warnings("(0 0 1)"), 0);
}


TEST(RotatingBody, AxisHintedWhereItHelps)
{
    // no axis, 15 deg: with the centre (0.5 0 0), axis (0 0 1) would move it
    // to (0.5 0 0.5), the farthest point 0.71 instead of 1.12 away: a hint
    // naming axis; with the centre (0.5 0 0.5), on the same axis and already
    // level: none
    const auto hints = [](const std::string& centre)
    {
        const std::string log(turnBottom3D(4, "centre " + centre + ";", {15}).log);
        return occurrences(log, "Hint: axis (0 0 1)");
    };
    EXPECT_EQ(hints("(0.5 0 0)"), 1);
    EXPECT_EQ(hints("(0.5 0 0.5)"), 0);
}

} // namespace
