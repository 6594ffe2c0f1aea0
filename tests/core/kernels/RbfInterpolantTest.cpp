// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of RbfInterpolant and SaddleSolver: exactness, polynomial
// reproduction, and every error path.
#include "RbfInterpolant.hpp"
#include "KernelCases.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <tuple>

using namespace dcprbf;
using test::affineField;
using test::randomPoints;
using test::smoothField;

namespace
{

// kernel name x polynomial x dimension
using Case = test::KernelCase;

class InterpolantCase : public ::testing::TestWithParam<Case>
{
protected:
    std::string name() const { return std::get<0>(GetParam()); }
    bool poly() const { return std::get<1>(GetParam()); }
    int dim() const { return std::get<2>(GetParam()); }

    //- Compact kernels: support radius; global kernels: a shape length that
    //  keeps the 120-point test systems well conditioned
    RbfInterpolant make(double radius = 0.6) const
    {
        const bool global = name() == "Gaussian" || name() == "IMQ";
        return RbfInterpolant
        (
            RadialKernel::fromName(name(), global ? 0.1 : radius), poly(), dim()
        );
    }
};

TEST_P(InterpolantCase, ExactAtControlPoints)
{
    const Points c = randomPoints(120, dim(), 1);
    Values v = smoothField(c);
    if (dim() == 2) v.col(2).setZero();
    RbfInterpolant s = make();
    s.fit(c, v);
    const Values e = s.evaluate(c);
    EXPECT_LT((e - v).cwiseAbs().maxCoeff(), 1e-9*v.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P
(
    KernelsPolyDim,
    InterpolantCase,
    ::testing::ValuesIn(test::kernelCases()),
    test::kernelCaseName
);


// Only the polynomial guarantees affine reproduction: the cases with it
class InterpolantPolyCase : public InterpolantCase {};

TEST_P(InterpolantPolyCase, AffineFieldReproducedWithPolynomial)
{
    ASSERT_TRUE(poly());
    const Points c = randomPoints(80, dim(), 2);
    const Points x = randomPoints(500, dim(), 3);
    RbfInterpolant s = make();
    s.fit(c, affineField(c, dim()));
    const Values ref = affineField(x, dim());
    const Values e = s.evaluate(x);
    EXPECT_LT((e - ref).cwiseAbs().maxCoeff(), 1e-10*ref.cwiseAbs().maxCoeff());
    // all the motion is in the polynomial: the kernel weights vanish
    EXPECT_LT(s.weights().cwiseAbs().maxCoeff(), 1e-6);
}

INSTANTIATE_TEST_SUITE_P
(
    KernelsPolyDim,
    InterpolantPolyCase,
    ::testing::ValuesIn(test::kernelCases([](const test::KernelCase& c)
    {
        return std::get<1>(c);
    })),
    test::kernelCaseName
);


// A compact kernel without the polynomial vanishes beyond its support (the
// polynomial would not): the compact kernels without it
class InterpolantCompactCase : public InterpolantCase {};

TEST_P(InterpolantCompactCase, CompactKernelIsZeroOutsideSupport)
{
    RbfInterpolant s = make(0.3);
    ASSERT_TRUE(s.kernel().compact());
    ASSERT_FALSE(poly());
    const Points c = randomPoints(20, dim(), 4);
    s.fit(c, smoothField(c));
    Points far(1, 3);
    far << 5.0, 5.0, dim() == 3 ? 5.0 : 0.0;
    EXPECT_EQ(s.evaluate(far).cwiseAbs().maxCoeff(), 0.0);
}

INSTANTIATE_TEST_SUITE_P
(
    KernelsPolyDim,
    InterpolantCompactCase,
    ::testing::ValuesIn(test::kernelCases([](const test::KernelCase& c)
    {
        return !std::get<1>(c)
            && RadialKernel::fromName(std::get<0>(c), 1.0).compact();
    })),
    test::kernelCaseName
);


// Error paths

TEST(RbfInterpolantErrors, DuplicatePointsAreReported)
{
    Points c = randomPoints(10, 3, 5);
    c.row(7) = c.row(2);
    RbfInterpolant s(RadialKernel::fromName("WendlandC2", 0.5), true, 3);
    try
    {
        s.setCentres(c);
        FAIL() << "no error for duplicate points";
    }
    catch (const Error& e)
    {
        EXPECT_NE(std::string(e.what()).find("duplicate control points 2 and 7"),
                  std::string::npos) << e.what();
    }
}

TEST(RbfInterpolantErrors, CoplanarPointsCannotCarryPolynomial3D)
{
    Points c = randomPoints(30, 3, 6);
    c.col(2).setConstant(0.25);
    RbfInterpolant s(RadialKernel::fromName("WendlandC2", 0.5), true, 3);
    EXPECT_THROW(s.setCentres(c), Error);
    RbfInterpolant noPoly(RadialKernel::fromName("WendlandC2", 0.5), false, 3);
    EXPECT_NO_THROW(noPoly.setCentres(c));
}

TEST(RbfInterpolantErrors, CollinearPointsCannotCarryPolynomial2D)
{
    Points c(6, 3);
    for (int i = 0; i < 6; ++i) c.row(i) << 0.1*i, 0.2*i + 0.3, 0.0;
    RbfInterpolant s(RadialKernel::fromName("WendlandC2", 1.0), true, 2);
    try
    {
        s.setCentres(c);
        FAIL() << "no error for collinear points";
    }
    catch (const Error& e)
    {
        EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos);
    }
}

TEST(RbfInterpolantErrors, TooFewPoints)
{
    RbfInterpolant s(RadialKernel::fromName("WendlandC2", 1.0), true, 3);
    EXPECT_THROW(s.setCentres(randomPoints(3, 3, 7)), Error);
    EXPECT_THROW(s.setCentres(Points(0, 3)), Error);
}

TEST(RbfInterpolantErrors, NonFiniteInput)
{
    Points c = randomPoints(10, 3, 8);
    RbfInterpolant s(RadialKernel::fromName("WendlandC2", 1.0), false, 3);
    Points bad = c;
    bad(3, 1) = std::nan("");
    EXPECT_THROW(s.setCentres(bad), Error);
    try
    {
        s.setCentres(bad);
        ADD_FAILURE() << "no error for non-finite control points";
    }
    catch (const Error& e)
    {
        EXPECT_NE(std::string(e.what()).find("control point coordinates"),
                  std::string::npos) << e.what();
    }
    s.setCentres(c);
    Values v = smoothField(c);
    v(0, 0) = std::numeric_limits<double>::infinity();
    EXPECT_THROW(s.solve(v), Error);
}

TEST(RbfInterpolantErrors, UseBeforeSetup)
{
    RbfInterpolant s(RadialKernel::fromName("WendlandC2", 1.0), false, 3);
    EXPECT_THROW(s.solve(Values(3, 3)), Error);
    EXPECT_THROW(s.evaluate(randomPoints(2, 3, 9)), Error);
    s.setCentres(randomPoints(5, 3, 9));
    EXPECT_THROW(s.solve(Values::Zero(4, 3)), Error);
}

TEST(RbfInterpolantErrors, BadKernelSettings)
{
    EXPECT_THROW(RadialKernel::fromName("WendlandC3", 1.0), Error);
    EXPECT_THROW(RadialKernel::fromName("WendlandC2", 0.0), Error);
    EXPECT_THROW(RadialKernel::fromName("WendlandC2", -1.0), Error);
    EXPECT_THROW(RbfInterpolant(RadialKernel::fromName("TPS", 1.0), false, 3), Error);
    EXPECT_THROW(RbfInterpolant(RadialKernel::fromName("Gaussian", 1.0), true, 4), Error);
    try
    {
        RadialKernel::fromName("wendland", 1.0);
        ADD_FAILURE() << "no error for the unknown kernel name 'wendland'";
    }
    catch (const Error& e)
    {
        // the message lists the allowed names
        EXPECT_NE(std::string(e.what()).find("WendlandC2"), std::string::npos);
    }
}

TEST(RbfInterpolantErrors, NinePointsIn2DNeedZeroZ)
{
    Points c = randomPoints(9, 3, 10);
    RbfInterpolant s(RadialKernel::fromName("WendlandC2", 1.0), true, 2);
    EXPECT_THROW(s.setCentres(c), Error);
}

} // namespace
