// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of StoredEvaluation's writes to targets: each row written to its
// target points, chosen rows alone, and rows evaluated for a set without
// preparing it equal to the prepared product.
#include "StoredEvaluation.hpp"
#include "RbfEvaluator.hpp"
#include "KernelCases.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace dcprbf;
using test::randomPoints;

namespace
{

// evaluateInto writes each row's value, bit for bit evaluate()'s, to each of
// its targets (none, one or several), the components beyond those asked
// zero, nothing else; for a patched set too (its columns added at the
// targets); it refuses (writes nothing) a global kernel's dense matrix
TEST(StoredEvaluation, EvaluateIntoWritesEachRowToItsTargets)
{
    const LinearPolynomial frame(true, 3);
    const Points x = randomPoints(300, 3, 51);
    const Points c = randomPoints(40, 3, 52);
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.5);
    StoredEvaluation s(k, frame, x);
    ASSERT_TRUE(s.prepare(c, std::size_t(1) << 30));
    Values alpha = test::smoothField(c);
    Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
    Values rows;
    s.evaluate(alpha, beta, rows);

    // row i to points 2i and 2i + 1 (even i), to 3i mod 1000 (i = 1 mod 4),
    // to none (the others); 1000 points, some untouched
    StoredEvaluation::Targets t;
    t.start.push_back(0);
    for (Eigen::Index i = 0; i < x.rows(); ++i)
    {
        if (i % 2 == 0) { t.point.push_back(int(2*i)); t.point.push_back(int(2*i + 1)); }
        else if (i % 4 == 1) { t.point.push_back(int((3*i) % 1000)); }
        t.start.push_back(t.point.size());
    }
    const double sentinel = std::numeric_limits<double>::quiet_NaN();
    const auto check = [&](const Values& expected, const char* what)
    {
        for (const int components : {3, 2})
        {
            std::vector<double> out(3*1000, sentinel);
            ASSERT_TRUE(s.evaluateInto(alpha, beta, t, components, out.data())) << what;
            std::vector<bool> written(1000, false);
            for (Eigen::Index i = 0; i < x.rows(); ++i)
            {
                for (std::size_t e = t.start[i]; e < t.start[i + 1]; ++e)
                {
                    const int p = t.point[e];
                    written[p] = true;
                    for (int q = 0; q < 3; ++q)
                    {
                        EXPECT_EQ(out[3*p + q], q < components ? expected(i, q) : 0.0)
                            << what << ": row " << i << " point " << p << " component " << q;
                    }
                }
            }
            int untouched = 0;
            for (int p = 0; p < 1000; ++p)
            {
                if (!written[p])
                {
                    ++untouched;
                    EXPECT_TRUE(std::isnan(out[3*p]) && std::isnan(out[3*p + 1]) && std::isnan(out[3*p + 2]))
                        << what << ": point " << p;
                }
            }
            EXPECT_GT(untouched, 100) << what;
        }
    };
    check(rows, "stored set");

    // the last columns zero (a 2D set: the two-column product)
    const Values alpha3 = alpha;
    const Eigen::MatrixX3d beta3 = beta;
    alpha.col(2).setZero();
    beta.col(2).setZero();
    Values rows2;
    s.evaluate(alpha, beta, rows2);
    check(rows2, "two columns");
    alpha = alpha3;
    beta = beta3;

    // a patched set: two centres moved (two patch columns)
    Points moved = c;
    moved.row(3) << 0.5, 0.5, 0.5;
    moved.row(17) << 0.45, 0.55, 0.5;
    ASSERT_TRUE(s.prepare(moved, std::size_t(1) << 30));
    ASSERT_EQ(s.patchColumns(), 2);
    Values patched;
    s.evaluate(alpha, beta, patched);
    check(patched, "patched set");

    // targets for another number of rows: an error
    StoredEvaluation::Targets wrong = t;
    wrong.start.pop_back();
    std::vector<double> buffer(3*1000);
    EXPECT_THROW(s.evaluateInto(alpha, beta, wrong, 3, buffer.data()), Error);

    // a dense matrix: refused, nothing written
    std::vector<double> out(3*1000, 7.0);
    const RadialKernel g = RadialKernel::fromName("Gaussian", 0.5);
    StoredEvaluation dense(g, frame, x);
    ASSERT_TRUE(dense.prepare(c, std::size_t(1) << 30));
    EXPECT_FALSE(dense.evaluateInto(alpha, beta, t, 3, out.data()));
    EXPECT_TRUE(std::all_of(out.begin(), out.end(), [](double v) { return v == 7.0; }));
}

// evaluateInto with rows writes those rows' values alone, bit for bit the
// whole product's (plain and patched sets, 2 and 3 columns, on 1 and 2
// threads: more rows than minParallelRows), and nothing else; a row out of
// range is an error, a dense matrix refused
TEST(StoredEvaluation, EvaluateIntoRowsWritesThoseRowsAlone)
{
    const LinearPolynomial frame(true, 3);
    const Eigen::Index n = StoredEvaluation::minParallelRows + 2000;
    const Points x = randomPoints(n, 3, 61);
    const Points c = randomPoints(60, 3, 62);
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.3);
    StoredEvaluation s(k, frame, x);
    ASSERT_TRUE(s.prepare(c, std::size_t(1) << 30));
    Values alpha = test::smoothField(c);
    const Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);

    // row i to point n - 1 - i; the rows: those not divisible by 7, descending
    StoredEvaluation::Targets t;
    t.start.push_back(0);
    for (Eigen::Index i = 0; i < n; ++i)
    {
        t.point.push_back(int(n - 1 - i));
        t.start.push_back(t.point.size());
    }
    std::vector<int> rows;
    for (Eigen::Index i = n - 1; i >= 0; --i)
    {
        if (i % 7) rows.push_back(int(i));
    }
    ASSERT_GE(std::ptrdiff_t(rows.size()), StoredEvaluation::minParallelRows);
    const double sentinel = std::numeric_limits<double>::quiet_NaN();
    const auto check = [&](const Values& a, const char* what)
    {
        for (const int threads : {1, 2})
        {
            const int nThreads = omp_get_max_threads();
            omp_set_num_threads(threads);
            std::vector<double> all(3*n), some(3*n, sentinel);
            ASSERT_TRUE(s.evaluateInto(a, beta, t, 3, all.data())) << what;
            ASSERT_TRUE(s.evaluateInto(a, beta, t, 3, some.data(), &rows)) << what;
            omp_set_num_threads(nThreads);
            for (Eigen::Index i = 0; i < n; ++i)
            {
                const Eigen::Index p = n - 1 - i;
                for (int q = 0; q < 3; ++q)
                {
                    if (i % 7)
                    {
                        ASSERT_EQ(some[3*p + q], all[3*p + q]) << what << ": row " << i;
                    }
                    else
                    {
                        ASSERT_TRUE(std::isnan(some[3*p + q])) << what << ": row " << i;
                    }
                }
            }
        }
    };
    check(alpha, "stored set");
    Values alpha2 = alpha;
    alpha2.col(2).setZero();
    Eigen::MatrixX3d beta2 = beta;
    beta2.col(2).setZero();
    {
        std::vector<double> all(3*n), some(3*n);
        ASSERT_TRUE(s.evaluateInto(alpha2, beta2, t, 2, all.data()));
        ASSERT_TRUE(s.evaluateInto(alpha2, beta2, t, 2, some.data(), &rows));
        for (const int i : rows)
        {
            for (int q = 0; q < 3; ++q) ASSERT_EQ(some[3*(n - 1 - i) + q], all[3*(n - 1 - i) + q]);
        }
    }
    Points moved = c;
    moved.row(5) << 0.5, 0.5, 0.5;
    moved.row(40) << 0.4, 0.6, 0.5;
    ASSERT_TRUE(s.prepare(moved, std::size_t(1) << 30));
    ASSERT_EQ(s.patchColumns(), 2);
    check(alpha, "patched set");

    std::vector<double> buffer(3*n);
    const std::vector<int> outside{0, int(n)};
    EXPECT_THROW(s.evaluateInto(alpha, beta, t, 3, buffer.data(), &outside), Error);
    StoredEvaluation dense(RadialKernel::fromName("Gaussian", 0.5), frame, x.topRows(50));
    ASSERT_TRUE(dense.prepare(c, std::size_t(1) << 30));
    StoredEvaluation::Targets t50;
    for (int i = 0; i <= 50; ++i) t50.start.push_back(std::size_t(i));
    for (int i = 0; i < 50; ++i) t50.point.push_back(i);
    const std::vector<int> few{1, 2};
    EXPECT_FALSE(dense.evaluateInto(alpha, beta, t50, 3, buffer.data(), &few));
}

// evaluateRowsFor gives, bit for bit, what prepare() then evaluateInto() at
// the rows would (its twin does that), without changing what is stored:
// for the current patch's set, each slot's set, a set a patch of the
// current slot serves (with and without a current patch, 2 and 3 columns);
// false, nothing written, for a set to build, over the budget, or dense
TEST(StoredEvaluation, EvaluateRowsForEqualsPrepareThenEvaluate)
{
    const LinearPolynomial frame(true, 3);
    const Points x = randomPoints(3000, 3, 71);
    const Points c = randomPoints(50, 3, 72);
    const Points extra = randomPoints(40, 3, 73);
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.35);
    const std::size_t budget = std::size_t(1) << 30;
    StoredEvaluation s(k, frame, x), twin(k, frame, x);
    StoredEvaluation::Targets t;
    t.start.push_back(0);
    for (Eigen::Index i = 0; i < x.rows(); ++i)
    {
        if (i % 3) t.point.push_back(int(i));
        t.start.push_back(t.point.size());
    }
    std::vector<int> rows;
    for (int i = 0; i < x.rows(); i += 2) rows.push_back(i);
    // centres at moved to new points (extra's, from its row e)
    const auto swapped = [&](const Points& from, std::initializer_list<int> at, int e = 20)
    {
        Points to = from;
        for (const int j : at) to.row(j) = extra.row(e++);
        return to;
    };
    const Points cB = swapped(c, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, 0);   // a build
    const auto check = [&](const Points& centres, const char* what, const bool served = true)
    {
        const Values alpha = test::smoothField(centres);
        Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
        for (const int components : {3, 2})
        {
            Values a = alpha;
            if (components == 2)
            {
                a.col(2).setZero();
                beta.col(2).setZero();
            }
            const int columns = s.patchColumns(), builds = s.builds();
            std::vector<double> mine(3*x.rows(), -1.0), theirs(3*x.rows(), -1.0);
            const bool ok = s.evaluateRowsFor(centres, budget, a, beta, t, components, mine.data(), rows);
            EXPECT_EQ(ok, served) << what;
            EXPECT_EQ(s.patchColumns(), columns) << what;
            EXPECT_EQ(s.builds(), builds) << what;
            if (!ok)
            {
                EXPECT_TRUE(std::all_of(mine.begin(), mine.end(), [](double v) { return v == -1.0; })) << what;
                continue;
            }
            StoredEvaluation copy(twin);
            ASSERT_TRUE(copy.prepare(centres, budget)) << what;
            ASSERT_TRUE(copy.evaluateInto(a, beta, t, components, theirs.data(), &rows)) << what;
            for (std::size_t m = 0; m < mine.size(); ++m)
            {
                ASSERT_EQ(mine[m], theirs[m]) << what << ": value " << m << ", " << components << " columns";
            }
        }
    };
    const auto both = [&](const Points& centres)
    {
        ASSERT_TRUE(s.prepare(centres, budget));
        ASSERT_TRUE(twin.prepare(centres, budget));
    };
    both(c);
    check(c, "the current slot's set");
    check(swapped(c, {3}), "one swap, no current patch");
    check(swapped(c, {3, 10, 20, 30, 40, 41, 42, 43}), "eight swaps");
    check(cB, "ten swaps: a build", false);
    both(swapped(c, {3}));
    check(swapped(c, {3}), "the current patch's set");
    check(swapped(c, {3, 17}), "a patch beside the current one");
    check(c, "the slot under the current patch");
    both(cB);
    both(swapped(cB, {5}, 30));
    check(cB, "the current slot beside a patch");
    check(c, "the other slot's set: prepare() would make it current", false);
    check(swapped(cB, {5}, 30), "the current patch's set again");
    check(swapped(cB, {5, 6}, 30), "a patch of the current slot beside its patch");
    check(swapped(c, {1}), "a patch of the other slot", false);

    // over the budget: a patch that might not fit is prepare()'s to decide
    std::vector<double> out(3*x.rows(), -1.0);
    const Values alpha = test::smoothField(c);
    const Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
    EXPECT_FALSE(s.evaluateRowsFor(swapped(cB, {9}, 35), s.bytes(), alpha, beta, t, 3, out.data(), rows));
    EXPECT_TRUE(std::all_of(out.begin(), out.end(), [](double v) { return v == -1.0; }));
    const std::vector<int> outside{int(x.rows())};
    EXPECT_THROW(s.evaluateRowsFor(cB, budget, alpha, beta, t, 3, out.data(), outside), Error);

    // a set refused before with no more room (both slots counted then;
    // one of them dropped): prepare() refuses it again at once, so must
    // this, though a patch of the current slot would now fit
    {
        StoredEvaluation onlyC(k, frame, x), onlyB(k, frame, x), u(k, frame, x);
        ASSERT_TRUE(onlyC.prepare(c, budget));
        ASSERT_TRUE(onlyB.prepare(cB, budget));
        const std::size_t tight = onlyB.bytes() + onlyC.bytes()/2;
        ASSERT_TRUE(u.prepare(c, budget));
        ASSERT_TRUE(u.prepare(cB, budget));
        const Points refusedSet = swapped(cB, {1}, 36);
        EXPECT_FALSE(u.prepare(refusedSet, tight));
        ASSERT_TRUE(u.prepare(cB, tight));          // the slot left
        EXPECT_FALSE(u.evaluateRowsFor(refusedSet, tight, alpha, beta, t, 3, out.data(), rows));
        EXPECT_FALSE(u.prepare(refusedSet, tight));
    }

    // a dense matrix: refused
    StoredEvaluation dense(RadialKernel::fromName("Gaussian", 0.5), frame, x);
    ASSERT_TRUE(dense.prepare(c, budget));
    EXPECT_FALSE(dense.evaluateRowsFor(c, budget, alpha, beta, t, 3, out.data(), rows));
    EXPECT_FALSE(dense.evaluateRowsFor(swapped(c, {2}), budget, alpha, beta, t, 3, out.data(), rows));
}

} // namespace
