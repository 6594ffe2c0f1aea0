/*---------------------------------------------------------------------------*\
  dcpRBF tests: greedy and dynamic control points inside OpenFOAM
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

//- A bump on the bottom wall of the unit box
vector bump(const point& p)
{
    return vector(0, 0.1*std::sin(constant::mathematical::pi*p.x()), 0);
}

struct moved
{
    pointField p0, p;
    label nControl;
};

moved run(label dim, const std::string& controlPoints, const std::string& extra = "")
{
    testCase c
    (
        dim, 10,
        "movingPatches (bottom); staticPatches (top left right); supportRadius 0.8;"
        " controlPoints { " + controlPoints + " }" + extra
    );
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    prescribe(solver.pointDisplacement(), "bottom", bump);
    moved m{solver.points0(), ms->newPoints(), solver.controlPoints().size()};
    return m;
}

TEST(Modes, GreedyUsesFewerPointsAndKeepsTheBoundaryExact)
{
    for (const label dim : {2, 3})
    {
        const moved all(run(dim, "selection all;"));
        const moved greedy(run(dim, "selection greedy; tolerance 1e-2;"));
        EXPECT_LE(greedy.nControl, 0.6*all.nControl) << dim << "D";
        EXPECT_GE(greedy.nControl, dim + 1);

        // every bottom point where prescribed, despite not all being control points
        forAll(greedy.p0, i)
        {
            const point& x = greedy.p0[i];
            if (x.y() == 0 && x.x() > 0 && x.x() < 1 && (dim == 2 || (x.z() > 0 && x.z() < 1)))
            {
                EXPECT_LT(mag(greedy.p[i] - (x + bump(x))), 1e-12) << dim << "D";
            }
        }
        // and the volume close to the full RBF
        EXPECT_LT(max(mag(greedy.p - all.p)), 0.02) << dim << "D";
    }
}

TEST(Modes, GreedyToleranceControlsTheSetSize)
{
    const moved coarse(run(2, "selection greedy; tolerance 5e-2;"));
    const moved fine(run(2, "selection greedy; tolerance 1e-4;"));
    EXPECT_LT(coarse.nControl, fine.nControl);
    const moved capped(run(2, "selection greedy; tolerance 1e-6; maxPoints 8;"));
    EXPECT_EQ(capped.nControl, 8);
}

TEST(Modes, AffineMotionExactInEveryMode)
{
    // with the polynomial, any set reproduces an affine motion exactly
    for (const char* sel : {"selection greedy;", "selection dynamic;"})
    {
        testCase c
        (
            2, 6,
            std::string("movingPatches (left right bottom top); staticPatches ();"
            " supportRadius 0.7; controlPoints { ") + sel + " }"
        );
        autoPtr<motionSolver> ms(select(c));
        auto& solver = refCast<dcpRBFMotionSolver>(ms());
        const auto f = [](const point& x) { return vector(0.2*x.y() + 0.1, -0.15*x.x(), 0); };
        for (const word n : {"left", "right", "bottom", "top"}) prescribe(solver.pointDisplacement(), n, f);
        const pointField p0(solver.points0());
        const pointField p(ms->newPoints());
        EXPECT_LT(solver.controlPoints().size(), 20);
        scalar err = 0;
        forAll(p, i) err = max(err, mag(p[i] - p0[i] - f(p0[i])));
        EXPECT_LT(err, 1e-10) << sel;
    }
}

TEST(Modes, SelectOnUnitSelectsBeforeAnyMotion)
{
    testCase c
    (
        2, 10,
        "movingPatches (bottom); staticPatches (top left right); supportRadius 0.8;"
        " controlPoints { selection greedy; selectOn unit; tolerance 1e-2; }"
    );
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    EXPECT_FALSE(solver.controlPoints().ready());
    const pointField p(ms->newPoints());   // zero displacement
    EXPECT_TRUE(solver.controlPoints().ready());
    EXPECT_LT(solver.controlPoints().size(), 40);
    EXPECT_LT(max(mag(p - solver.points0())), 1e-12);
}

TEST(Modes, BoundaryCorrectionBlendsTheErrorIntoTheVolume)
{
    // a coarse set (large boundary error) so the correction radius
    // 10 max|e| spans interior points
    const std::string greedy("selection greedy; tolerance 0.3; reselectTolerance 0.5;");
    const moved with(run(2, greedy));
    const moved without(run(2, greedy, " boundaryCorrection false;"));
    const moved all(run(2, "selection all;"));
    EXPECT_EQ(with.nControl, without.nControl);
    // the correction changes points near the boundary, towards full RBF
    scalar changed = 0, errWith = 0, errWithout = 0;
    forAll(with.p, i)
    {
        changed = max(changed, mag(with.p[i] - without.p[i]));
        errWith += mag(with.p[i] - all.p[i]);
        errWithout += mag(without.p[i] - all.p[i]);
    }
    EXPECT_GT(changed, 1e-6);
    EXPECT_LT(errWith, errWithout);
}

TEST(Modes, SupportRadiusRelativeToTheMovingExtent)
{
    testCase c
    (
        2, 4,
        "movingPatches (bottom); staticPatches (top left right);"
        " supportRadius 2 movingExtent;"
    );
    autoPtr<motionSolver> ms(select(c));
    const auto& solver = refCast<dcpRBFMotionSolver>(ms());
    // bottom patch: x in [0, 1], y = 0, z in [0, 0.1]; a 2D mesh (z
    // empty): the extent in its plane, not the extrusion's thickness
    ASSERT_EQ(c.mesh().nGeometricD(), 2);
    EXPECT_NEAR(solver.settings().kernel().radius(), 2.0, 1e-12);
}

// evaluationMemoryMB unset: no matrix is stored until the control set has
// settled (the first step's set, or one that changes by more than a patch
// from a step to the next, is evaluated on the fly: OpenFOAM's
// SnakeRiverCanyon grows its set at every step); set: stored at once
TEST(Modes, StoredMatricesOnlyOnceTheSetSettles)
{
    const std::size_t MB = std::size_t(1) << 20;
    for (const std::string memory : {"", "evaluationMemoryMB 512;"})
    {
        testCase c
        (
            3, 10,
            "movingPatches (bottom); staticPatches (top left right front back); supportRadius 0.8;"
            " controlPoints { selection greedy; tolerance 1e-2; reselectTolerance 2e-2; } " + memory
        );
        autoPtr<motionSolver> ms(select(c));
        auto& solver = refCast<dcpRBFMotionSolver>(ms());
        const dcpRBFControlPoints& cp = solver.controlPoints();
        const bool automatic = memory.empty();
        // (a third of bump(): no cell squashed flat at the static walls)
        prescribe
        (
            solver.pointDisplacement(), "bottom",
            [](const point& p) { return bump(p)/3; }
        );
        ms->newPoints();
        EXPECT_EQ(cp.storageBudget(), automatic ? 0 : 512*MB) << "after the first step";
        ms->newPoints();
        EXPECT_EQ(cp.storageBudget(), automatic ? 1024*MB : 512*MB) << "the set unchanged";
        // a wavier bump: the set grows by more than a patch
        const label before = cp.size();
        prescribe
        (
            solver.pointDisplacement(), "bottom",
            [](const point& p)
            {
                const scalar pi = constant::mathematical::pi;
                return vector(0, 0.03*std::sin(5*pi*p.x())*std::sin(5*pi*p.z()), 0);
            }
        );
        ms->newPoints();
        ASSERT_GT(cp.size(), before + 2*dcprbf::StoredEvaluation::maxPatchColumns)
            << "the test needs a set that grows by more than a patch";
        EXPECT_EQ(cp.storageBudget(), automatic ? 0 : 512*MB) << "the set grown";
    }
}

// The mesh measured is the mesh written: every boundary point (static ones
// too, where the reduced interpolant is off without boundaryCorrection) is
// in place before the measurement, on the stored matrix's path (written
// straight to the points) as on the fly; the measured points are reused as
// the new points at every step, the static ones exactly in place
TEST(Modes, MeasuredMeshIsTheWrittenOne)
{
    for (const std::string memory : {"evaluationMemoryMB 64;", "evaluationMemoryMB 0;"})
    {
        testCase c
        (
            2, 10,
            "movingPatches (bottom); staticPatches (top left right); supportRadius 0.8;"
            " boundaryCorrection false; guardIterations 0; " + memory +
            " controlPoints { selection greedy; tolerance 0.2; }"
        );
        autoPtr<motionSolver> ms(select(c));
        auto& solver = refCast<dcpRBFMotionSolver>(ms());
        const pointField p0(c.mesh().points());
        const label nSteps = 3;
        for (label step = 1; step <= nSteps; ++step)
        {
            ++c.runTime();
            const scalar a = 0.02*step;
            prescribe(solver.pointDisplacement(), "bottom", [a](const point& x)
            {
                return vector(a, a*std::sin(constant::mathematical::pi*x.x()), 0);
            });
            const pointField p(ms->newPoints());
            for (const word name : {"top", "left", "right"})
            {
                const polyPatch& pp = c.mesh().boundaryMesh()[c.mesh().boundaryMesh().findPatchID(name)];
                for (const label pointi : pp.meshPoints())
                {
                    if (p0[pointi].y() > 1e-12)   // (the bottom's corners move)
                    {
                        EXPECT_EQ(p[pointi], p0[pointi]) << memory << " step " << step << " " << name;
                    }
                }
            }
            c.mesh().movePoints(p);
        }
        EXPECT_LT(solver.controlPoints().size(), 20) << "the set must leave static points out";
        EXPECT_EQ(solver.nReusedPoints(), nSteps) << memory;
    }
}

} // namespace

// ************************************************************************* //
