// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of GreedySelector: the incremental selection picks the same
// points as the naive re-solving reference with the same coefficients; the
// stopping rules; the models' invariants.
#include "GreedySelector.hpp"
#include "NaiveGreedyModel.hpp"
#include "IncrementalGreedyModel.hpp"
#include "IncrementalSaddleSolver.hpp"
#include "RbfEvaluator.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <tuple>

using namespace dcprbf;
using test::randomPoints;
using test::relDiff;

namespace
{

// kernel name x polynomial x dimension x double-edged
using Case = std::tuple<std::string, bool, int, bool>;

class GreedyCase : public ::testing::TestWithParam<Case>
{
protected:
    std::string name() const { return std::get<0>(GetParam()); }
    bool poly() const { return std::get<1>(GetParam()); }
    int dim() const { return std::get<2>(GetParam()); }
    bool doubleEdged() const { return std::get<3>(GetParam()); }

    GreedySelector make(double tol, Eigen::Index maxPoints) const
    {
        GreedyOptions o;
        o.tolerance = tol;
        o.maxPoints = maxPoints;
        o.doubleEdged = doubleEdged();
        return GreedySelector
        (
            RadialKernel::fromName(name(), test::testRadius(name(), 0.5)),
            poly(), dim(), o
        );
    }

    Points candidates() const { return randomPoints(500, dim(), 61); }

    Values field(const Points& x) const
    {
        Values d = test::smoothField(x);
        if (dim() == 2) d.col(2).setZero();
        return d;
    }
};

TEST_P(GreedyCase, IncrementalPicksSameAsNaive)
{
    const Points x = candidates();
    const Values d = field(x);
    const GreedySelector g = make(1e-9, 70);
    const GreedyResult inc = g.select(x, d);
    const GreedyResult ref = selectNaive(g, x, d);

    ASSERT_EQ(inc.selected, ref.selected);
    EXPECT_EQ(inc.selected.size(), 70u);  // the tolerance is out of reach
    EXPECT_FALSE(inc.converged);
    EXPECT_EQ(inc.historySize, ref.historySize);
    for (std::size_t k = 0; k < inc.historyError.size(); ++k)
    {
        EXPECT_NEAR(inc.historyError[k], ref.historyError[k],
                    1e-8*ref.historyError[0]) << k;
    }
    EXPECT_LT(relDiff(inc.alpha, ref.alpha), 1e-10);
    EXPECT_LT(relDiff(inc.beta, ref.beta), 1e-10);
    EXPECT_EQ(inc.centres, ref.centres);
    // double-edged adds two points per iteration (when an opposite one exists)
    if (doubleEdged())
    {
        EXPECT_LT(inc.historySize.size(), inc.selected.size());
    }
    else
    {
        EXPECT_EQ(inc.historySize.back() - inc.historySize.front(),
                  Eigen::Index(inc.historySize.size() - 1));
    }
}

TEST_P(GreedyCase, ExactAtSelectedAndWithinToleranceElsewhere)
{
    const Points x = candidates();
    const Values d = field(x);
    const double tol = 0.05;
    const GreedyResult r = make(tol, 500).select(x, d);
    ASSERT_TRUE(r.converged);
    EXPECT_LE(r.historyError.back(), tol);

    RbfEvaluator e(RadialKernel::fromName(name(), test::testRadius(name(), 0.5)), r.frame);
    e.assign(r.centres, r.alpha, r.beta);
    const Values s = e.evaluate(x);
    const Values err = s - d;
    double worst = 0;
    for (std::size_t j = 0; j < r.selected.size(); ++j)
    {
        EXPECT_LT(err.row(r.selected[j]).norm(), 1e-9*r.maxDisplacement);
    }
    worst = err.rowwise().norm().maxCoeff()/r.maxDisplacement;
    EXPECT_LE(worst, tol*(1 + 1e-9));
    EXPECT_NEAR(worst, r.historyError.back(), 1e-9);
}

TEST_P(GreedyCase, FactorizationContinuesAsIncrementalSolver)
{
    const Points x = candidates();
    const Values d = field(x);
    GreedyResult r = make(1e-9, 40).select(x, d);
    ASSERT_TRUE(r.factorization);
    IncrementalSaddleSolver s(std::move(*r.factorization));
    EXPECT_EQ(s.centres(), r.centres);
    Values alpha, dc(r.selected.size(), 3);
    Eigen::MatrixX3d beta;
    for (std::size_t j = 0; j < r.selected.size(); ++j) dc.row(j) = d.row(r.selected[j]);
    s.solve(dc, alpha, beta);
    EXPECT_LT(relDiff(alpha, r.alpha), 1e-12);
    // and it accepts the dynamic updates
    Eigen::Index fresh = 0;
    while (std::count(r.selected.begin(), r.selected.end(), fresh)) ++fresh;
    s.replace(5, x.row(fresh));
    EXPECT_EQ(s.size(), 40);
    EXPECT_EQ(s.centres().row(39), x.row(fresh));
}

TEST_P(GreedyCase, RebuildAndShiftKeepTheResidual)
{
    const Points x = candidates();
    const Values d = field(x);
    const LinearPolynomial frame = LinearPolynomial::boundingBox(poly(), dim(), x);
    const RadialKernel k = RadialKernel::fromName(name(), test::testRadius(name(), 0.5));
    IncrementalGreedyModel m(k, frame, x, d);
    const GreedySelector g = make(1e-9, 40);
    m.add(g.seed(x, d));
    for (Eigen::Index i : {17, 230, 412, 5, 99}) m.add({i});
    const Values before = m.residual();
    m.rebuild();
    EXPECT_LT(relDiff(m.residual(), before), 1e-10);
    if (!k.positiveDefinite())
    {
        const double c0 = m.factorization().kernel().shift();
        m.raiseShiftAndRebuild();
        EXPECT_DOUBLE_EQ(m.factorization().kernel().shift(), 10*c0);
        EXPECT_LT(relDiff(m.residual(), before), 1e-9);
    }
}

std::vector<Case> allCases()
{
    std::vector<Case> cases;
    for (const auto& name : RadialKernel::names())
    {
        for (bool poly : {false, true})
        {
            if (name == "TPS" && !poly) continue;
            for (int dim : {2, 3})
            {
                for (bool de : {false, true}) cases.emplace_back(name, poly, dim, de);
            }
        }
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P
(
    KernelsPolyDimEdges,
    GreedyCase,
    ::testing::ValuesIn(allCases()),
    // (not named "info": INSTANTIATE_TEST_SUITE_P has a parameter of that
    // name, -Wshadow)
    [](const ::testing::TestParamInfo<Case>& p)
    {
        return std::get<0>(p.param)
            + (std::get<1>(p.param) ? "_poly" : "_noPoly")
            + "_" + std::to_string(std::get<2>(p.param)) + "D"
            + (std::get<3>(p.param) ? "_double" : "_single");
    }
);

// The selection does not depend on the number of threads: large enough for
// the incremental model's parallel update (candidates x points above its
// threshold), 1 and 2 threads select the same points with the same
// coefficients, bit for bit
TEST(GreedyThreads, SameSelectionOnOneAndTwoThreads)
{
    const Points x = randomPoints(2500, 3, 17);
    const Values d = test::smoothField(x);
    GreedyOptions o;
    o.tolerance = 1e-12;
    o.maxPoints = 60;
    const GreedySelector g(RadialKernel::fromName("WendlandC2", 0.8), true, 3, o);
    ASSERT_GT(x.rows()*o.maxPoints, 100000) << "too small for the parallel update";
    const int nThreads = omp_get_max_threads();
    omp_set_num_threads(1);
    const GreedyResult one = g.select(x, d);
    omp_set_num_threads(2);
    const GreedyResult two = g.select(x, d);
    omp_set_num_threads(nThreads);
    ASSERT_EQ(one.selected.size(), std::size_t(o.maxPoints));
    EXPECT_EQ(one.selected, two.selected);
    EXPECT_TRUE(one.alpha == two.alpha);
    EXPECT_TRUE(one.beta == two.beta);
    EXPECT_EQ(one.historyError, two.historyError);
}

} // namespace
