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

// The top wall's condition, in neither list: slip removes the displacement
// along the wall's normal (y), fixedNormalSlip along its own n (here x, not
// the wall's normal): each keeps its own meaning
TEST(Slip, SlipAndFixedNormalSlipRemoveTheirOwnNormal)
{
    struct variant { const char* condition; direction removed; };
    for (const variant v : {variant{"slip", vector::Y}, variant{"fixedNormalSlip; n (1 0 0)", vector::X}})
    {
        testCase c(2, 8, "movingPatches (bottom); staticPatches (left right); supportRadius 2;");
        c.write
        (
            "0/pointDisplacement", "pointVectorField",
            std::string("dimensions [0 1 0 0 0 0 0];\ninternalField uniform (0 0 0);\n"
            "boundaryField\n{\n"
            "    \"(left|right)\" { type fixedValue; value uniform (0 0 0); }\n"
            "    bottom { type fixedValue; value uniform (0 0 0); }\n"
            "    top { type ") + v.condition + "; }\n"
            "    \"(front|back)\" { type empty; }\n}\n"
        );
        autoPtr<motionSolver> ms(select(c));
        auto& solver = refCast<dcpRBFMotionSolver>(ms());
        prescribe
        (
            solver.pointDisplacement(), "bottom",
            [](const point& x)
            {
                const scalar s = std::sin(constant::mathematical::pi*x.x());
                return vector(0.05*s, 0.1*s, 0);
            }
        );
        const pointField p0(solver.points0());
        const pointField p(ms->newPoints());
        const polyBoundaryMesh& bm = c.mesh().boundaryMesh();
        scalar removed = 0, kept = 0;
        for (const label i : bm[bm.findPatchID("top")].meshPoints())
        {
            const vector d(p[i] - p0[i]);
            removed = max(removed, mag(d[v.removed]));
            kept = max(kept, mag(d[v.removed == vector::X ? vector::Y : vector::X]));
        }
        EXPECT_LT(removed, 1e-14) << v.condition;
        EXPECT_GT(kept, 1e-4) << v.condition << ": nothing moved along the other direction";
    }
}

} // namespace

// ************************************************************************* //
