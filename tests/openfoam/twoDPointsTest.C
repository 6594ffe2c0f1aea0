/*---------------------------------------------------------------------------*\
  dcpRBF tests: dcpRBFTwoDPoints gives OpenFOAM's 2D correction of the points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "dcpRBFTwoDPoints.H"
#include "twoDPointCorrector.H"
#include "Random.H"

#include <gtest/gtest.h>

#include <cstring>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

//- The mesh's points moved by random amounts in every direction (the
//  front and back twins apart, off their planes), scale s
pointField perturbed(const polyMesh& mesh, const scalar s, const label seed)
{
    Random rnd(seed);
    pointField p(mesh.points());
    for (point& x : p)
    {
        x += s*(rnd.sample01<vector>() - vector::uniform(0.5));
    }
    return p;
}


TEST(TwoDPoints, SameValuesAsOpenFOAMsCorrection)
{
    for (const label dim : {2, 3})
    {
        testCase c(dim, 7, "movingPatches (bottom); staticPatches (top left right);");
        const dcpRBFTwoDPoints ours(c.mesh());
        EXPECT_EQ(ours.required(), dim == 2);
        for (const label seed : {1, 2, 3})
        {
            // the mesh moved in the plane first (polyMesh then recomputes
            // its directions and bounds; ours are those of the start)
            pointField moved(c.mesh().points());
            Random rnd(10 + seed);
            for (point& x : moved)
            {
                x.x() += 0.002*(rnd.sample01<scalar>() - 0.5);
            }
            c.mesh().movePoints(moved);
            const pointField p0(perturbed(c.mesh(), 0.05, seed));
            pointField a(p0), b(p0);
            ours.correct(a);
            twoDPointCorrector::New(c.mesh()).correctPoints(b);
            ASSERT_EQ(a.size(), b.size());
            EXPECT_EQ(std::memcmp(a.cdata(), b.cdata(), a.size()*sizeof(point)), 0)
                << "dim " << dim << " seed " << seed;
            // in 2D the correction did something (not a comparison of no-ops)
            label nChanged = 0;
            forAll(a, i)
            {
                nChanged += mag(a[i] - p0[i]) > 1e-6;
            }
            if (dim == 2)
            {
                EXPECT_EQ(nChanged, a.size());
                // twins share their in-plane position, and the planes are
                // the mesh's
                const scalar zMid = 0.5*(c.mesh().bounds().min().z() + c.mesh().bounds().max().z());
                forAll(a, i)
                {
                    EXPECT_NEAR(mag(a[i].z() - zMid), 0.5*c.mesh().bounds().span().z(), 0.05);
                }
            }
            else
            {
                EXPECT_EQ(nChanged, 0);
            }
        }
    }
}

// A 2D mesh whose empty direction is x (the box's coordinates turned
// (x y z) -> (z x y), a rotation): the same values as OpenFOAM's too
TEST(TwoDPoints, SameValuesWhenTheEmptyDirectionIsX)
{
    testCase c(2, 7, "movingPatches (bottom); staticPatches (top left right);");
    pointField turned(c.mesh().points());
    for (point& x : turned)
    {
        x = point(x.z(), x.x(), x.y());
    }
    c.mesh().movePoints(turned);
    ASSERT_EQ(c.mesh().geometricD().x(), -1);
    const dcpRBFTwoDPoints ours(c.mesh());
    ASSERT_TRUE(ours.required());
    const pointField p0(perturbed(c.mesh(), 0.05, 4));
    pointField a(p0), b(p0);
    ours.correct(a);
    twoDPointCorrector::New(c.mesh()).correctPoints(b);
    EXPECT_EQ(std::memcmp(a.cdata(), b.cdata(), a.size()*sizeof(point)), 0);
    // twins share their in-plane (y, z) position
    label nChanged = 0;
    forAll(a, i)
    {
        nChanged += mag(a[i] - p0[i]) > 1e-6;
    }
    EXPECT_EQ(nChanged, a.size());
}

} // namespace
