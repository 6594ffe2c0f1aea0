/*---------------------------------------------------------------------------*\
  dcpRBF tests: run-time selection and a first motion
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "pointMesh.H"
#include "mapPolyMesh.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

const char* bumpCoeffs =
    "movingPatches (bottom); staticPatches (top left right);"
    " supportRadius 0.8;";

//- A smooth bump on the bottom wall, zero at its ends
vector bump(const point& p)
{
    return vector(0, 0.08*std::sin(constant::mathematical::pi*p.x()), 0);
}

TEST(Selection, DcpRBFIsSelectedFromDynamicMeshDictAndMovesThePoints)
{
    for (const label dim : {2, 3})
    {
        testCase c(dim, 6, string(bumpCoeffs) + (dim == 3 ? " staticPatches (top left right front back);" : ""));
        autoPtr<motionSolver> ms(select(c));
        EXPECT_EQ(ms->type(), "dcpRBF");
        ASSERT_TRUE(isA<dcpRBFMotionSolver>(ms()));
        auto& solver = refCast<dcpRBFMotionSolver>(ms());

        prescribe(solver.pointDisplacement(), "bottom", bump);
        const pointField p0(solver.points0());
        const pointField p(ms->newPoints());

        // points off the non-empty patches moved
        const polyBoundaryMesh& bm = c.mesh().boundaryMesh();
        const label bottom = bm.findPatchID("bottom");
        scalar maxInterior = 0;
        boolList onPatch(p.size(), false), onOther(p.size(), false);
        for (const polyPatch& pp : bm)
        {
            if (pp.type() == "empty") continue;
            for (const label i : pp.meshPoints())
            {
                onPatch[i] = true;
                if (pp.index() != bottom) onOther[i] = true;
            }
        }
        forAll(p, i)
        {
            if (!onPatch[i]) maxInterior = max(maxInterior, mag(p[i] - p0[i]));
        }
        EXPECT_GT(maxInterior, 1e-3) << dim << "D";

        // moving points exactly where prescribed (points shared with other
        // patches follow the boundary conditions' evaluation order), static
        // points put
        for (const label i : bm[bottom].meshPoints())
        {
            if (onOther[i]) continue;
            EXPECT_LT(mag(p[i] - (p0[i] + bump(p0[i]))), 1e-14) << dim << "D";
        }
        for (const label i : bm[bm.findPatchID("top")].meshPoints())
        {
            EXPECT_EQ(p[i], p0[i]);
        }
        if (dim == 2)
        {
            // no motion out of the plane
            forAll(p, i) EXPECT_EQ(p[i].z(), p0[i].z());
        }
    }
}

TEST(Selection, DcpRBFIsInTheDisplacementMotionSolverTable)
{
    testCase c(2, 4, bumpCoeffs);
    const pointMesh& pMesh = pointMesh::New(c.mesh());
    pointVectorField pd
    (
        IOobject("pointDisplacement", "0", c.mesh(), IOobject::MUST_READ),
        pMesh
    );
    pointIOField points0(points0MotionSolver::points0IO(c.mesh()));
    autoPtr<displacementMotionSolver> ms
    (
        displacementMotionSolver::New
        (
            "dcpRBF", c.mesh(), c.dynamicMeshDict(), pd, points0
        )
    );
    EXPECT_EQ(ms->type(), "dcpRBF");
    prescribe(ms->pointDisplacement(), "bottom", bump);
    ms->solve();
    const pointField& p0 = ms->points0();
    const vectorField& d = ms->pointDisplacement().primitiveField();
    EXPECT_GT(max(mag(d)), 0.079);
    // the volume moves: interior points near the wall follow the bump
    label nInterior = 0;
    forAll(p0, i)
    {
        const point& x = p0[i];
        if (x.x() > 0.2 && x.x() < 0.8 && x.y() > 0 && x.y() < 0.3)
        {
            EXPECT_GT(d[i].y(), 1e-3) << x.x() << " " << x.y();
            ++nInterior;
        }
    }
    EXPECT_GT(nInterior, 0);
}

TEST(Selection, TopologyChangeIsRefused)
{
    testCase c(2, 4, bumpCoeffs);
    autoPtr<motionSolver> ms(select(c));
    const mapPolyMesh map(c.mesh());   // an identity map is a topology update too
    EXPECT_THROW(ms->updateMesh(map), Foam::error);
}

} // namespace

// ************************************************************************* //
