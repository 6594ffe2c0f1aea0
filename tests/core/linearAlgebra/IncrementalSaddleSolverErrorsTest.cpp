// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Guards of IncrementalSaddleSolver: every refused change throws Error and
// leaves the control set (and its coefficients) unchanged.
#include "IncrementalSaddleSolver.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

using namespace dcprbf;
using test::randomPoints;
using test::relDiff;

namespace
{

IncrementalSaddleSolver make(bool poly, int dim, const std::string& name = "WendlandC2")
{
    return IncrementalSaddleSolver
    (
        RadialKernel::fromName(name, test::testRadius(name, 0.8)),
        LinearPolynomial(poly, dim, Eigen::RowVector3d::Constant(0.5), 2.0)
    );
}

//- Solution for the smooth field on the current centres
Values weights(const IncrementalSaddleSolver& s)
{
    Values a;
    Eigen::MatrixX3d b;
    s.solve(test::smoothField(s.centres()), a, b);
    return a;
}

void expectMessage(const std::function<void()>& f, const std::string& part)
{
    try
    {
        f();
        ADD_FAILURE() << "no Error, expected one mentioning '" << part << "'";
    }
    catch (const Error& e)
    {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

TEST(IncrementalSaddleSolverErrors, DuplicateAddIsRefused)
{
    IncrementalSaddleSolver s = make(true, 3);
    const Points c = randomPoints(20, 3, 51);
    s.reset(c);
    const Values before = weights(s);
    expectMessage([&] { s.add(c.row(7)); }, "duplicates control point 7");
    expectMessage
    (
        [&] { s.add(c.row(3) + Eigen::RowVector3d(1e-13, 0, 0)); },
        "duplicates control point 3"
    );
    EXPECT_EQ(s.size(), 20);
    EXPECT_EQ(relDiff(weights(s), before), 0.0);
}

TEST(IncrementalSaddleSolverErrors, RemovalBelowMinimumIsRefused)
{
    IncrementalSaddleSolver s = make(true, 3);
    s.reset(randomPoints(5, 3, 52));
    EXPECT_EQ(s.minimumSize(), 4);
    s.remove(2);
    expectMessage([&] { s.remove(0); }, "at least 4 are needed");
    EXPECT_EQ(s.size(), 4);

    IncrementalSaddleSolver noPoly = make(false, 2);
    noPoly.reset(randomPoints(2, 2, 53));
    noPoly.remove(1);
    expectMessage([&] { noPoly.remove(0); }, "at least 1 are needed");
}

TEST(IncrementalSaddleSolverErrors, CoplanarAfterRemovalIsRefused3D)
{
    // four points on the plane z = 0.2 and one above it
    Points c(5, 3);
    c << 0, 0, 0.2,  1, 0, 0.2,  0, 1, 0.2,  1, 1, 0.2,  0.5, 0.5, 0.9;
    IncrementalSaddleSolver s = make(true, 3);
    s.reset(c);
    const Values before = weights(s);
    expectMessage([&] { s.remove(4); }, "coplanar");
    EXPECT_EQ(s.size(), 5);
    EXPECT_EQ(relDiff(weights(s), before), 0.0);
    EXPECT_NO_THROW(s.remove(0));  // the other four are not coplanar
    // without the polynomial the same removal is fine
    IncrementalSaddleSolver noPoly = make(false, 3);
    noPoly.reset(c);
    EXPECT_NO_THROW(noPoly.remove(4));
}

TEST(IncrementalSaddleSolverErrors, CollinearAfterRemovalIsRefused2D)
{
    Points c(4, 3);
    c << 0, 0, 0,  0.5, 0.5, 0,  1, 1, 0,  1, 0, 0;
    IncrementalSaddleSolver s = make(true, 2);
    s.reset(c);
    expectMessage([&] { s.remove(3); }, "collinear");
    EXPECT_EQ(s.size(), 4);
}

TEST(IncrementalSaddleSolverErrors, FailedReplaceChangesNothing)
{
    Points c(5, 3);
    c << 0, 0, 0.2,  1, 0, 0.2,  0, 1, 0.2,  1, 1, 0.2,  0.5, 0.5, 0.9;
    IncrementalSaddleSolver s = make(true, 3);
    s.reset(c);
    const Values before = weights(s);
    // the new point is in the plane too: removing point 4 leaves 5 coplanar
    expectMessage([&] { s.replace(4, Eigen::RowVector3d(0.3, 0.6, 0.2)); }, "coplanar");
    EXPECT_EQ(s.centres(), c);
    EXPECT_LT(relDiff(weights(s), before), 1e-12);
    // a duplicate new point: refused before anything is removed
    expectMessage([&] { s.replace(0, c.row(2)); }, "duplicates control point 2");
    EXPECT_EQ(s.centres(), c);
    // a valid swap
    s.replace(4, Eigen::RowVector3d(0.4, 0.4, 0.7));
    EXPECT_EQ(s.size(), 5);
    EXPECT_EQ(s.centres().row(4), Eigen::RowVector3d(0.4, 0.4, 0.7));
}

TEST(IncrementalSaddleSolverErrors, BadArguments)
{
    IncrementalSaddleSolver s = make(true, 3);
    expectMessage([&] { s.add(Eigen::RowVector3d(0.1, 0.2, 0.3)); }, "reset");
    expectMessage([&] { s.reset(randomPoints(3, 3, 54)); }, "too few");
    Points dup = randomPoints(10, 3, 55);
    dup.row(8) = dup.row(1);
    expectMessage([&] { s.reset(dup); }, "duplicate control points 1 and 8");
    EXPECT_EQ(s.size(), 0);

    s.reset(randomPoints(10, 3, 56));
    EXPECT_THROW(s.remove(10), Error);
    EXPECT_THROW(s.remove(-1), Error);
    EXPECT_THROW(s.replace(10, Eigen::RowVector3d(0.1, 0.2, 0.3)), Error);
    EXPECT_THROW(s.add(Eigen::RowVector3d(0.1, std::nan(""), 0.3)), Error);
    Values a;
    Eigen::MatrixX3d b;
    EXPECT_THROW(s.solve(Values::Zero(9, 3), a, b), Error);
    Values v = Values::Zero(10, 3);
    v(2, 1) = std::numeric_limits<double>::infinity();
    EXPECT_THROW(s.solve(v, a, b), Error);

    IncrementalSaddleSolver s2 = make(true, 2);
    s2.reset(randomPoints(6, 2, 57));
    expectMessage([&] { s2.add(Eigen::RowVector3d(0.1, 0.2, 0.3)); }, "z = 0");
    EXPECT_THROW(make(false, 3, "TPS"), Error);  // TPS needs the polynomial
}

TEST(IncrementalSaddleSolverErrors, NumericallyDependentPointIsRefused)
{
    // A wide Gaussian on a few close points: a new point between them is
    // far from every centre but adds nothing the round-off can resolve
    IncrementalSaddleSolver s
    (
        RadialKernel::fromName("Gaussian", 20.0), LinearPolynomial(false, 3)
    );
    s.reset(randomPoints(10, 3, 58, 0.1));
    expectMessage([&] { s.add(Eigen::RowVector3d(0.05, 0.05, 0.05)); }, "dependent");
    EXPECT_EQ(s.size(), 10);
}

TEST(IncrementalSaddleSolverErrors, RaisedTpsShiftGivesSameCoefficients)
{
    const RadialKernel k = RadialKernel::fromName("TPS", 1.0);
    const LinearPolynomial frame(true, 3, Eigen::RowVector3d::Constant(0.5), 2.0);
    const Points c = randomPoints(50, 3, 59);
    SaddleFactorization f(k, frame);
    f.factorize(c);
    const double c0 = f.kernel().shift();
    EXPECT_GT(c0, 0.0);
    f.raiseShiftAndFactorize(c);
    EXPECT_DOUBLE_EQ(f.kernel().shift(), 10*c0);
    const Values v = test::smoothField(c);
    Values a, aRef;
    Eigen::MatrixX3d b, bRef;
    f.solve(v, a, b);
    test::freshSolve(k, frame, c, v, aRef, bRef);
    EXPECT_LT(relDiff(a, aRef), 1e-10);
    EXPECT_LT(relDiff(b, bRef), 1e-10);
    // positive-definite kernels never shift
    AugmentedKernel pd(RadialKernel::fromName("WendlandC2", 1.0), frame);
    EXPECT_EQ(pd.shift(), 0.0);
    EXPECT_THROW(pd.increaseShift(), Error);
    AugmentedKernel tps(k, frame);
    for (int i = 0; i < 6; ++i) tps.increaseShift();
    EXPECT_THROW(tps.increaseShift(), Error);
}

} // namespace
