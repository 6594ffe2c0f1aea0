/*---------------------------------------------------------------------------*\
  dcpRBF tests: the defaults that depend on the case (supportRadius, selection)
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "dcpRBFSelectionSettings.H"
#include "IStringStream.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

const char* lists =
    "movingPatches (bottom); staticPatches (top left right);";

} // End anonymous namespace


// Without supportRadius: the reference mesh's bounding-box diagonal, in the
// plane of a 2D mesh (not its thickness), in full in 3D
TEST(Defaults, RadiusIsTheReferenceMeshsExtentInItsPlane)
{
    for (const label dim : {2, 3})
    {
        testCase c(dim, 4, string(lists) + (dim == 3 ? " staticPatches (top left right front back);" : ""));
        autoPtr<motionSolver> ms(select(c));
        const auto& solver = refCast<dcpRBFMotionSolver>(ms());
        const boundBox bb(solver.points0(), true);
        vector span(bb.span());
        if (dim == 2) span.z() = 0;
        EXPECT_GT(bb.span().z(), 0) << dim << "D: the box has a thickness";
        EXPECT_EQ(solver.settings().kernel().radius(), mag(span)) << dim << "D";
        EXPECT_TRUE(solver.settings().radiusDefault()) << dim << "D";
    }
}


// Without selection: all while every candidate fits in maxPoints (2000),
// dynamic beyond; a given selection is kept
TEST(Defaults, SelectionAllUpToMaxPointsThenDynamic)
{
    const string walls(" supportRadius 0.5; staticPatches (top left right front back);");
    for (const label n : {6, 20})
    {
        for (const word& given : {word::null, word("all")})
        {
            testCase c
            (
                3, n, "movingPatches (bottom);" + walls
              + (given.empty() ? "" : " controlPoints { selection " + given + "; }")
            );
            autoPtr<motionSolver> ms(select(c));
            const auto& solver = refCast<dcpRBFMotionSolver>(ms());
            // the boundary points of the n^3 box: 218 (n 6), 2402 (n 20)
            const bool above = (n + 1)*(n + 1)*(n + 1) - (n - 1)*(n - 1)*(n - 1) > 2000;
            SCOPED_TRACE("n " + Foam::name(n) + " selection " + (given.empty() ? "(none)" : given));
            EXPECT_EQ
            (
                solver.settings().selection().selectionName(),
                word(above && given.empty() ? "dynamic" : "all")
            );
        }
    }
}


// Without maxPoints: 2000, at most the greedy basis's budget (1.25e8
// numbers) over the candidates, not below 100, at least minPoints; a given
// maxPoints is kept
TEST(Defaults, MaxPointsBoundedByTheBasisBudget)
{
    const auto chosen = [](const char* text, const label nCandidates)
    {
        dcpRBFSelectionSettings s{dictionary(IStringStream(text)())};
        s.chooseDefault(nCandidates);
        return s;
    };
    EXPECT_EQ(chosen("", 1000).maxPoints, 2000);
    EXPECT_EQ(chosen("", 1000).selectionName(), word("all"));
    EXPECT_EQ(chosen("", 50000).maxPoints, 2000);
    EXPECT_EQ(chosen("", 129002).maxPoints, 968);
    EXPECT_EQ(chosen("", 129002).selectionName(), word("dynamic"));
    EXPECT_EQ(chosen("", 100000000).maxPoints, 100);
    EXPECT_EQ(chosen("selection greedy; maxPoints 1500;", 129002).maxPoints, 1500);
    EXPECT_EQ(chosen("selection greedy; minPoints 1200;", 129002).maxPoints, 1200);
}


// ************************************************************************* //
