/*---------------------------------------------------------------------------*\
  dcpRBF tests: dcpRBFSlipPatches gives OpenFOAM's slip
  condition where the wall is at its reference position
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "dcpRBFSlipPatches.H"
#include "pointFields.H"
#include "Random.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

TEST(SlipPatches, SameValuesAsOpenFOAMsConditionOnTheReferenceWall)
{
    // (symmetry needs a symmetry patch: the same evaluation, see
    // dcpRBFSlipPatches.C)
    for (const word condition : {"slip"})
    {
        SCOPED_TRACE(condition);
        testCase c
        (
            3, 6, "movingPatches (top); staticPatches (left right);", "wall",
            "{ type " + condition + "; }"
        );
        // a curved bottom wall (its normals differ from point to point),
        // which is also the reference: OpenFOAM's condition uses the
        // current normals, dcpRBFSlipPatches the reference ones
        pointField curved(c.mesh().points());
        for (point& x : curved)
        {
            x.y() += 0.05*(1 - x.y())*Foam::sin(3*x.x())*Foam::cos(2*x.z());
        }
        c.mesh().movePoints(curved);

        pointVectorField stock
        (
            IOobject
            (
                "pointDisplacement", c.runTime().timeName(), c.mesh(),
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            ),
            pointMesh::New(c.mesh())
        );
        Random rnd(5);
        for (vector& v : stock.primitiveFieldRef())
        {
            v = rnd.sample01<vector>() - vector::uniform(0.5);
        }
        pointVectorField ours(stock);

        const label bottom = c.mesh().boundaryMesh().findPatchID("bottom");
        ASSERT_GE(bottom, 0);
        const dcpRBFSlipPatches slip(ours, c.mesh().points());
        ASSERT_TRUE(slip.handles(bottom));
        EXPECT_FALSE(slip.handles(c.mesh().boundaryMesh().findPatchID("top")));

        stock.boundaryFieldRef()[bottom].evaluate();
        slip.evaluate(ours, bottom);

        // the same values on the wall's points, the others untouched; the
        // normal part removed (not zero before)
        const labelList& meshPoints = c.mesh().boundaryMesh()[bottom].meshPoints();
        const pointPatch& pp = stock.boundaryField()[bottom].patch();
        const vectorField n(pp.pointNormals());
        scalar normalBefore = 0;
        forAll(meshPoints, i)
        {
            const label pointi = meshPoints[i];
            EXPECT_LT(mag(ours[pointi] - stock[pointi]), 1e-12) << pointi;
            EXPECT_LT(mag(ours[pointi] & n[i]), 1e-12) << pointi;
        }
        forAll(ours, pointi)
        {
            normalBefore = max(normalBefore, mag(ours[pointi] - stock[pointi]));
        }
        EXPECT_LT(normalBefore, 1e-12);
    }
}

} // End anonymous namespace
