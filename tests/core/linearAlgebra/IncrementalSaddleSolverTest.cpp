// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of IncrementalSaddleSolver and UpdatableCholesky: after any
// sequence of add/remove/replace the coefficients equal a fresh solve of the
// same set; every guard.
#include "IncrementalSaddleSolver.hpp"
#include "KernelCases.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <random>
#include <tuple>

using namespace dcprbf;
using test::randomPoints;
using test::relDiff;

namespace
{

// kernel name x polynomial x dimension
using Case = test::KernelCase;

class IncrementalCase : public ::testing::TestWithParam<Case>
{
protected:
    std::string name() const { return std::get<0>(GetParam()); }
    bool poly() const { return std::get<1>(GetParam()); }
    int dim() const { return std::get<2>(GetParam()); }
    RadialKernel kernel() const
    {
        return RadialKernel::fromName(name(), test::testRadius(name()));
    }
    LinearPolynomial frame() const
    {
        return LinearPolynomial::boundingBox(poly(), dim(), randomPoints(2, dim(), 0));
    }

    //- Coefficients of the solver equal a fresh solve on its centres
    void expectFreshSolve(const IncrementalSaddleSolver& s) const
    {
        const Points c = s.centres();
        const Values v = test::smoothField(c);
        Values a, aRef;
        Eigen::MatrixX3d b, bRef;
        s.solve(v, a, b);
        test::freshSolve(kernel(), s.polynomial(), c, v, aRef, bRef);
        EXPECT_LT(relDiff(a, aRef), 1e-10) << "alpha, N = " << c.rows();
        EXPECT_LT(relDiff(b, bRef), 1e-10) << "beta, N = " << c.rows();
    }
};

TEST_P(IncrementalCase, ResetEqualsFreshSolve)
{
    IncrementalSaddleSolver s(kernel(), frame());
    s.reset(randomPoints(60, dim(), 41));
    EXPECT_EQ(s.size(), 60);
    expectFreshSolve(s);
}

TEST_P(IncrementalCase, RandomAddRemoveReplaceEqualFreshSolve)
{
    const Points pool = randomPoints(140, dim(), 42);
    IncrementalSaddleSolver s(kernel(), frame());
    s.reset(pool.topRows(40));
    std::mt19937 gen(43);
    Eigen::Index next = 40;
    for (int step = 0; step < 60; ++step)
    {
        const int op = step % 3;
        std::uniform_int_distribution<Eigen::Index> pick(0, s.size() - 1);
        if (op == 0)
        {
            s.add(pool.row(next++));
        }
        else if (op == 1)
        {
            s.remove(pick(gen));
        }
        else
        {
            s.replace(pick(gen), pool.row(next++));
        }
        if (step % 7 == 0) expectFreshSolve(s);
    }
    EXPECT_EQ(s.size(), 40 + 20 - 20);
    EXPECT_EQ(s.factorizations(), 1);  // only the reset: no refactorization
    expectFreshSolve(s);
}

TEST_P(IncrementalCase, RemovingFirstAndLastKeepsOrder)
{
    const Points c = randomPoints(30, dim(), 44);
    IncrementalSaddleSolver s(kernel(), frame());
    s.reset(c);
    s.remove(0);
    s.remove(s.size() - 1);
    EXPECT_EQ(s.centres(), c.middleRows(1, 28));
    expectFreshSolve(s);
}

TEST_P(IncrementalCase, ExactAtCentresAfterUpdates)
{
    const Points pool = randomPoints(50, dim(), 45);
    IncrementalSaddleSolver s(kernel(), frame());
    s.reset(pool.topRows(30));
    for (int i = 30; i < 50; ++i) s.add(pool.row(i));
    for (int i = 0; i < 10; ++i) s.remove(3*i % s.size());
    const Points c = s.centres();
    const Values v = test::smoothField(c);
    Values a;
    Eigen::MatrixX3d b;
    s.solve(v, a, b);
    const Values back = test::kernelMatrix(s.kernel(), c, c)*a
        + s.polynomial().basis(c)*b;
    EXPECT_LT(relDiff(back, v), 1e-10);
    if (poly())  // the constraint P^T alpha = 0
    {
        EXPECT_LT((s.polynomial().basis(c).transpose()*a).cwiseAbs().maxCoeff(),
                  1e-10*a.cwiseAbs().maxCoeff());
    }
}

INSTANTIATE_TEST_SUITE_P
(
    KernelsPolyDim,
    IncrementalCase,
    ::testing::ValuesIn(test::kernelCases()),
    test::kernelCaseName
);


// UpdatableCholesky alone

TEST(UpdatableCholesky, DeleteEqualsCholeskyOfReducedMatrix)
{
    const int n = 40;
    const Eigen::MatrixXd B = Eigen::MatrixXd::Random(n, n);
    const Eigen::MatrixXd A = B*B.transpose() + n*Eigen::MatrixXd::Identity(n, n);
    const Eigen::MatrixXd P = Eigen::MatrixXd::Random(n, 3);
    for (int k : {0, 17, n - 1})
    {
        UpdatableCholesky f;
        f.assign(Eigen::LLT<Eigen::MatrixXd>(A).matrixL());
        Eigen::MatrixXd X = P;
        f.solveLowerInPlace(X);
        f.remove(k, X);

        std::vector<int> keep;
        for (int i = 0; i < n; ++i) if (i != k) keep.push_back(i);
        const Eigen::MatrixXd Ar = A(keep, keep);
        const Eigen::MatrixXd Lr = Eigen::LLT<Eigen::MatrixXd>(Ar).matrixL();
        const Eigen::MatrixXd L = f.matrixL().triangularView<Eigen::Lower>();
        EXPECT_LT((L - Lr).cwiseAbs().maxCoeff(), 1e-12) << k;
        const Eigen::MatrixXd Xr = Lr.triangularView<Eigen::Lower>().solve(P(keep, Eigen::all));
        EXPECT_LT((X.topRows(n - 1) - Xr).cwiseAbs().maxCoeff(), 1e-12) << k;
    }
}

TEST(UpdatableCholesky, AppendGrowsBeyondCapacity)
{
    const int n = 70;  // initial capacity is 16
    const Eigen::MatrixXd B = Eigen::MatrixXd::Random(n, n);
    const Eigen::MatrixXd A = B*B.transpose() + n*Eigen::MatrixXd::Identity(n, n);
    UpdatableCholesky f;
    for (int i = 0; i < n; ++i)
    {
        const Eigen::VectorXd l = f.forwardRow(A.row(i).head(i).transpose());
        f.append(l, std::sqrt(A(i, i) - l.squaredNorm()));
    }
    const Eigen::MatrixXd L = f.matrixL().triangularView<Eigen::Lower>();
    EXPECT_LT(relDiff(L*L.transpose(), A), 1e-13);
    EXPECT_THROW(f.append(Eigen::VectorXd::Zero(n), 0.0), Error);
    EXPECT_THROW(f.append(Eigen::VectorXd::Zero(3), 1.0), Error);
    Eigen::MatrixXd X(n, 0);
    EXPECT_THROW(f.remove(n, X), Error);
}

} // namespace
