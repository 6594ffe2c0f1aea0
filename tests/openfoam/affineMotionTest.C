/*---------------------------------------------------------------------------*\
  dcpRBF tests: affine boundary motion is reproduced everywhere
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    Every boundary patch moves by the same affine map x -> M x + b (rotation,
    stretch, translation). With all boundary points as control points and the
    linear polynomial, the RBF reproduces that map at every interior point.

\*---------------------------------------------------------------------------*/

#include "testHelpers.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

struct affineMap
{
    tensor M;
    vector b;
    vector operator()(const point& x) const { return (M & x) + b - x; }
};

affineMap makeMap(label dim)
{
    const scalar a = 0.3;  // rotation angle [rad]
    if (dim == 2)
    {
        const tensor R(Foam::cos(a), -Foam::sin(a), 0, Foam::sin(a), Foam::cos(a), 0, 0, 0, 1);
        const tensor S(1.2, 0, 0, 0, 0.85, 0, 0, 0, 1);
        return {R & S, vector(0.15, -0.05, 0)};
    }
    // rotation about (1 1 1)/sqrt(3)
    const vector n(vector(1, 1, 1)/Foam::sqrt(3.0));
    const tensor K(0, -n.z(), n.y(), n.z(), 0, -n.x(), -n.y(), n.x(), 0);
    const tensor R(I + Foam::sin(a)*K + (1 - Foam::cos(a))*(K & K));
    const tensor S(1.2, 0, 0, 0, 0.85, 0, 0, 0, 1.1);
    return {R & S, vector(0.15, -0.05, 0.2)};
}

class AffineMotion : public ::testing::TestWithParam<std::tuple<label, std::string>>
{};

TEST_P(AffineMotion, ReproducedAtEveryPoint)
{
    const label dim = std::get<0>(GetParam());
    const std::string function = std::get<1>(GetParam());
    const word patches(dim == 2 ? "(left right bottom top)" : "(\".*\")");
    testCase c
    (
        dim, 5,
        "movingPatches " + patches + "; staticPatches (); function "
      + function + "; supportRadius 0.7; polynomial true;"
    );
    autoPtr<motionSolver> ms(select(c));
    auto& solver = refCast<dcpRBFMotionSolver>(ms());
    const affineMap f(makeMap(dim));
    for (const polyPatch& pp : c.mesh().boundaryMesh())
    {
        if (pp.type() != "empty") prescribe(solver.pointDisplacement(), pp.name(), f);
    }

    const pointField p0(solver.points0());
    const pointField p(ms->newPoints());
    scalar err = 0;
    forAll(p, i)
    {
        vector expected(p0[i] + f(p0[i]));
        if (dim == 2) expected.z() = p0[i].z();
        err = max(err, mag(p[i] - expected));
    }
    // relative to the domain size (1)
    EXPECT_LT(err, 1e-10) << dim << "D " << function;
}

INSTANTIATE_TEST_SUITE_P
(
    DimAndKernel,
    AffineMotion,
    ::testing::Combine
    (
        ::testing::Values(label(2), label(3)),
        ::testing::Values("WendlandC2", "WendlandC4", "TPS")
    ),
    [](const auto& info)
    {
        return std::to_string(std::get<0>(info.param)) + "D_"
            + std::get<1>(info.param);
    }
);

} // namespace

// ************************************************************************* //
