// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of StoredEvaluation: the stored product equals the evaluator for
// every kernel, polynomial and dimension; sets are reused, not rebuilt; the
// memory budget is kept.
#include "StoredEvaluation.hpp"
#include "RbfEvaluator.hpp"
#include "KernelCases.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

using namespace dcprbf;
using test::randomPoints;

namespace
{

class StoredCase : public ::testing::TestWithParam<test::KernelCase> {};

TEST_P(StoredCase, EqualsTheEvaluator)
{
    const auto [name, poly, dim] = GetParam();
    const RadialKernel k = RadialKernel::fromName(name, test::testRadius(name, 0.4));
    const LinearPolynomial frame(poly, dim);
    const Points x = randomPoints(700, dim, 31);
    const Points c = randomPoints(60, dim, 32);
    Values alpha = test::smoothField(c);
    Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
    if (dim == 2) { alpha.col(2).setZero(); }

    RbfEvaluator e(k, frame);
    e.assign(c, alpha, beta);
    const Values expected = e.evaluate(x);

    StoredEvaluation s(k, frame, x);
    ASSERT_TRUE(s.prepare(c, std::size_t(1) << 30));
    Values got;
    s.evaluate(alpha, beta, got);
    EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 1e-12*(1 + expected.cwiseAbs().maxCoeff()))
        << name << " poly " << poly << " " << dim << "D";
}

INSTANTIATE_TEST_SUITE_P(KernelsPolyDim, StoredCase, ::testing::ValuesIn(test::kernelCases()),
    test::kernelCaseName);

TEST(StoredEvaluation, ReusesTheTwoLastSetsAndKeepsTheBudget)
{
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.3);
    const LinearPolynomial frame(true, 3);
    const Points x = randomPoints(500, 3, 1);
    const Points a = randomPoints(40, 3, 2);
    Points b = a;
    b.row(7) << 0.5, 0.5, 0.5;   // one centre moved: another set
    StoredEvaluation s(k, frame, x);
    const std::size_t budget = std::size_t(1) << 30;
    ASSERT_TRUE(s.prepare(a, budget));
    ASSERT_TRUE(s.prepare(a, budget));
    EXPECT_EQ(s.builds(), 1);
    ASSERT_TRUE(s.prepare(b, budget));   // a trial
    ASSERT_TRUE(s.prepare(a, budget));   // undone: the older slot
    EXPECT_EQ(s.builds(), 2);
    EXPECT_GT(s.bytes(), 0u);

    // a budget below one matrix: nothing stored, the caller evaluates itself
    StoredEvaluation small(k, frame, x);
    EXPECT_FALSE(small.prepare(a, 64));
    EXPECT_EQ(small.bytes(), 0u);
}

} // namespace
