/*---------------------------------------------------------------------------*\
  dcpRBF tests: points of symmetryPlane patches slide in their plane
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

TEST(Symmetry, SymmetryPlanePointsStayInTheirPlane)
{
    for (const char* sel : {"all", "greedy", "dynamic"})
    {
        // front (z = 0) and back (z = 1) are symmetry planes, unlisted
        testCase c
        (
            3, 6,
            std::string("movingPatches (bottom); staticPatches (top left right);"
            " supportRadius 0.8; controlPoints { selection ") + sel + "; }",
            "symmetryPlane"
        );
        autoPtr<motionSolver> ms(select(c));
        auto& solver = refCast<dcpRBFMotionSolver>(ms());
        // a displacement with an out-of-plane component inside the domain
        prescribe
        (
            solver.pointDisplacement(), "bottom",
            [](const point& x)
            {
                const scalar s = std::sin(constant::mathematical::pi*x.x());
                return vector(0, 0.1*s, 0.05*s*std::sin(constant::mathematical::pi*x.z()));
            }
        );
        const pointField p0(solver.points0());
        const pointField p(ms->newPoints());

        const polyBoundaryMesh& bm = c.mesh().boundaryMesh();
        label nSliding = 0;
        for (const word patch : {"front", "back"})
        {
            for (const label i : bm[bm.findPatchID(patch)].meshPoints())
            {
                EXPECT_LT(mag(p[i].z() - p0[i].z()), 1e-14) << sel;
                nSliding += mag(p[i].y() - p0[i].y()) > 1e-4;
            }
        }
        EXPECT_GT(nSliding, 0) << sel << ": nothing slid along the plane";
    }
}

} // namespace

// ************************************************************************* //
