// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of RbfEvaluator (tree, blocked dense and brute force agree) and
// of LinearPolynomial (frames, unisolvence).
#include "RbfEvaluator.hpp"
#include "RbfInterpolant.hpp"
#include "KernelCases.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

using namespace dcprbf;
using test::randomPoints;

namespace
{

// kernel name x polynomial x dimension
using Case = test::KernelCase;

class EvaluatorCase : public ::testing::TestWithParam<Case>
{
protected:
    std::string name() const { return std::get<0>(GetParam()); }
    bool poly() const { return std::get<1>(GetParam()); }
    int dim() const { return std::get<2>(GetParam()); }

    //- An evaluator with random coefficients over n random centres; the
    //  centre count is not a multiple of the dense blocks (1024 centres)
    RbfEvaluator make(int n, double radius) const
    {
        const Points c = randomPoints(n, dim(), 21);
        const LinearPolynomial frame =
            LinearPolynomial::boundingBox(poly(), dim(), c);
        RbfEvaluator e(RadialKernel::fromName(name(), radius), frame);
        Values alpha = Values::Random(n, 3);
        Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
        e.assign(c, alpha, beta);
        return e;
    }
};

TEST_P(EvaluatorCase, AllMethodsEqualBruteForce)
{
    // 1100 centres: two centre blocks; 1000 points: a partial point block
    RbfEvaluator e = make(1100, test::testRadius(name(), 0.2));
    const Points x = randomPoints(1000, dim(), 22, 1.2);
    Values ref(x.rows(), 3);
    e.evaluateBruteForce(x.data(), x.rows(), ref.data());
    for (auto m : {RbfEvaluator::Method::Auto, RbfEvaluator::Method::Tree,
                   RbfEvaluator::Method::Dense})
    {
        e.setMethod(m);
        const Values v = e.evaluate(x);
        EXPECT_LT(test::relDiff(v, ref), 1e-12) << int(m);
    }
    // the reference itself is not trivially zero
    EXPECT_GT(ref.cwiseAbs().maxCoeff(), 1e-3);
}

TEST_P(EvaluatorCase, ReassignedCentresEqualBruteForce)
{
    // new weights for the same centres (the tree kept), then as many
    // centres moved (a new tree): the tree method as brute force each time
    RbfEvaluator e = make(300, test::testRadius(name(), 0.2));
    const Points x = randomPoints(400, dim(), 24, 1.2);
    e.setMethod(RbfEvaluator::Method::Tree);
    const auto check = [&](const char* what)
    {
        Values ref(x.rows(), 3);
        e.evaluateBruteForce(x.data(), x.rows(), ref.data());
        EXPECT_LT(test::relDiff(e.evaluate(x), ref), 1e-12) << what;
        EXPECT_GT(ref.cwiseAbs().maxCoeff(), 1e-3) << what;
    };
    Points c = e.centres();
    const Eigen::MatrixX3d beta = e.polynomialCoeffs();
    e.assign(c, Values::Random(c.rows(), 3), beta);
    check("same centres");
    c = randomPoints(300, dim(), 25);
    e.assign(c, Values::Random(c.rows(), 3), beta);
    check("moved centres");
}

TEST_P(EvaluatorCase, AutoPicksTreeOnlyForSmallCompactSupport)
{
    const RbfEvaluator small = make(500, 0.1);
    const RbfEvaluator large = make(500, 5.0);
    const Points x = randomPoints(300, dim(), 23);
    const bool compact = small.kernel().compact();
    EXPECT_EQ(small.usesTree(x.data(), x.rows()), compact);
    EXPECT_FALSE(large.usesTree(x.data(), x.rows()));
}

// The method is the whole evaluation's: points mostly far from the centres
// (a tree), the listed ones among them (alone: dense)
TEST(RbfEvaluator, RowsTakeTheWholeEvaluationsMethod)
{
    const Points c = randomPoints(200, 3, 27);
    const LinearPolynomial frame = LinearPolynomial::boundingBox(true, 3, c);
    RbfEvaluator e(RadialKernel::fromName("WendlandC2", 0.8), frame);
    e.assign(c, Values::Random(c.rows(), 3), Eigen::MatrixX3d::Random(frame.size(), 3));
    Points x = randomPoints(1000, 3, 28);
    x.array() += 5.0;                       // beyond the support
    std::vector<int> rows;
    for (int i = 0; i < 1000; i += 10)
    {
        x.row(i) = c.row(i/10);             // at a centre: most within reach
        rows.push_back(i);
    }
    Points xr(rows.size(), 3);
    for (std::size_t k = 0; k < rows.size(); ++k) xr.row(k) = x.row(rows[k]);
    ASSERT_TRUE(e.usesTree(x.data(), x.rows()));
    ASSERT_FALSE(e.usesTree(xr.data(), xr.rows()));
    const Values all = e.evaluate(x);
    Values some(rows.size(), 3);
    e.evaluateRows(x.data(), x.rows(), rows, some.data());
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
        for (int q = 0; q < 3; ++q) ASSERT_EQ(some(k, q), all(rows[k], q)) << "point " << rows[k];
    }
}

// evaluateRows gives evaluate()'s values at the listed points bit for bit,
// with the method picked for all the points (a small and a large support:
// tree and dense), in the order listed; a point out of range is an error
TEST_P(EvaluatorCase, RowsEqualTheWholeEvaluationBitForBit)
{
    for (const double radius : {0.1, 5.0})
    {
        const RbfEvaluator e = make(1100, test::testRadius(name(), radius));
        const Points x = randomPoints(1000, dim(), 26, 1.2);
        const Values all = e.evaluate(x);
        std::vector<int> rows;
        for (int i = int(x.rows()) - 1; i >= 0; i -= 3) rows.push_back(i);
        Values some(rows.size(), 3);
        e.evaluateRows(x.data(), x.rows(), rows, some.data());
        for (std::size_t k = 0; k < rows.size(); ++k)
        {
            for (int q = 0; q < 3; ++q)
            {
                ASSERT_EQ(some(k, q), all(rows[k], q)) << "radius " << radius << ", point " << rows[k];
            }
        }
        const std::vector<int> outside{0, int(x.rows())};
        EXPECT_THROW(e.evaluateRows(x.data(), x.rows(), outside, some.data()), Error);
    }
}

INSTANTIATE_TEST_SUITE_P
(
    KernelsPolyDim,
    EvaluatorCase,
    ::testing::ValuesIn(test::kernelCases()),
    test::kernelCaseName
);

// identity(): new at every construction and assign() (the same weights
// assigned again too: a caller keeping values cannot tell), kept by a move
TEST(RbfEvaluator, IdentityNewAtEveryAssignKeptByAMove)
{
    const Points c = randomPoints(20, 3, 31);
    const LinearPolynomial frame = LinearPolynomial::boundingBox(true, 3, c);
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.8);
    RbfEvaluator e(k, frame);
    const RbfEvaluator other(k, frame);
    EXPECT_NE(e.identity(), other.identity());
    const Values alpha = Values::Random(c.rows(), 3);
    const Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
    std::uint64_t before = e.identity();
    for (int n = 0; n < 2; ++n)
    {
        e.assign(c, alpha, beta);
        EXPECT_NE(e.identity(), before) << "assignment " << n;
        before = e.identity();
    }
    const RbfEvaluator moved(std::move(e));
    EXPECT_EQ(moved.identity(), before);
}

TEST(RbfEvaluator, InterpolantUsesEvaluator)
{
    const Points c = randomPoints(200, 3, 24);
    RbfInterpolant s(RadialKernel::fromName("WendlandC2", 0.3), true, 3);
    s.fit(c, test::smoothField(c));
    const Points x = randomPoints(500, 3, 25);
    Values ref(x.rows(), 3);
    s.evaluator().evaluateBruteForce(x.data(), x.rows(), ref.data());
    EXPECT_LT(test::relDiff(s.evaluate(x), ref), 1e-12);
    EXPECT_EQ(s.evaluator().size(), 200u);
}

TEST(RbfEvaluator, Errors)
{
    RbfEvaluator e
    (
        RadialKernel::fromName("Gaussian", 1.0),
        LinearPolynomial(true, 3)
    );
    const Points c = randomPoints(10, 3, 26);
    EXPECT_THROW(e.evaluate(c), Error);  // nothing assigned
    EXPECT_THROW(e.assign(c, Values::Zero(9, 3), Eigen::MatrixX3d::Zero(4, 3)), Error);
    EXPECT_THROW(e.assign(c, Values::Zero(10, 3), Eigen::MatrixX3d::Zero(3, 3)), Error);
    EXPECT_NO_THROW(e.assign(c, Values::Zero(10, 3), Eigen::MatrixX3d::Zero(4, 3)));
}


// LinearPolynomial

TEST(LinearPolynomial, BoundingBoxFrameKeepsBasisInUnitRange)
{
    const Points x = randomPoints(100, 3, 27, 50.0);
    const LinearPolynomial p = LinearPolynomial::boundingBox(true, 3, x);
    const Eigen::MatrixXd Q = p.basis(x);
    EXPECT_EQ(Q.cols(), 4);
    EXPECT_TRUE((Q.col(0).array() == 1.0).all());
    EXPECT_LE(Q.rightCols(3).cwiseAbs().maxCoeff(), 1.0);
    EXPECT_GT(Q.rightCols(3).cwiseAbs().maxCoeff(), 0.3);
    EXPECT_EQ(LinearPolynomial::boundingBox(false, 2, x).size(), 0);
}

TEST(LinearPolynomial, ChangeFrameKeepsTheFunction)
{
    const Points x = randomPoints(20, 3, 28, 3.0);
    for (int dim : {2, 3})
    {
        const LinearPolynomial a(true, dim, Eigen::RowVector3d(0.3, -1, 2), 0.7);
        const LinearPolynomial b(true, dim, Eigen::RowVector3d(-5, 4, 1), 3.1);
        const Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(dim + 1, 3);
        const Eigen::MatrixX3d betaB = a.changeFrame(beta, b);
        EXPECT_LT(test::relDiff(b.basis(x)*betaB, a.basis(x)*beta), 1e-13);
        EXPECT_GT((betaB - beta).cwiseAbs().maxCoeff(), 0.1);  // not trivial
    }
    EXPECT_THROW
    (
        LinearPolynomial(true, 3).changeFrame
        (
            Eigen::MatrixX3d::Zero(4, 3), LinearPolynomial(true, 2)
        ),
        Error
    );
}

TEST(LinearPolynomial, UnisolvenceChecks)
{
    const LinearPolynomial p3(true, 3), p2(true, 2);
    Points coplanar = randomPoints(10, 3, 29);
    coplanar.col(2) = (0.5*coplanar.col(0)).array() + 0.2;  // a tilted plane
    EXPECT_THROW(p3.checkUnisolvent(coplanar), Error);
    EXPECT_NO_THROW(p2.checkUnisolvent(randomPoints(3, 2, 30)));
    Points collinear(5, 3);
    for (int i = 0; i < 5; ++i) collinear.row(i) << i, 2.0*i - 1, 0;
    EXPECT_THROW(p2.checkUnisolvent(collinear), Error);
    EXPECT_THROW(p3.checkUnisolvent(randomPoints(3, 3, 31)), Error);  // too few
    EXPECT_NO_THROW(LinearPolynomial(false, 3).checkUnisolvent(collinear));
    EXPECT_THROW(LinearPolynomial(true, 4), Error);
    EXPECT_THROW(LinearPolynomial(true, 3, Eigen::RowVector3d::Zero(), 0.0), Error);
}

} // namespace
