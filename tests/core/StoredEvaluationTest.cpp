// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of StoredEvaluation: the stored product equals the evaluator for
// every kernel, polynomial and dimension; sets are reused, not rebuilt; the
// memory budget is kept; the values written straight to their targets.
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

class StoredCase : public ::testing::TestWithParam<test::KernelCase> {};

//- Largest difference, relative, between the stored product of s for the
//  centres c (prepared) and the evaluator on the points x, for smooth weights;
//  in 2D the last column of the weights zero (the product's two-column
//  path: that column of the result exactly zero), unless lastColumn
double storedVsEvaluator
(
    const StoredEvaluation& s,
    const RadialKernel& k,
    const LinearPolynomial& frame,
    const Points& x,
    const Points& c,
    int dim,
    bool lastColumn = false
)
{
    Values alpha = test::smoothField(c);
    Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
    if (dim == 2) { alpha.col(2).setZero(); }
    if (dim == 2 && !lastColumn) { beta.col(2).setZero(); }
    RbfEvaluator e(k, frame);
    e.assign(c, alpha, beta);
    const Values expected = e.evaluate(x);
    Values got;
    s.evaluate(alpha, beta, got);
    if (dim == 2 && !lastColumn)
    {
        EXPECT_TRUE(got.col(2).isZero(0));
    }
    return (got - expected).cwiseAbs().maxCoeff()/(1 + expected.cwiseAbs().maxCoeff());
}

TEST_P(StoredCase, EqualsTheEvaluator)
{
    const auto [name, poly, dim] = GetParam();
    const RadialKernel k = RadialKernel::fromName(name, test::testRadius(name, 0.4));
    const LinearPolynomial frame(poly, dim);
    const Points x = randomPoints(700, dim, 31);
    const Points c = randomPoints(60, dim, 32);
    StoredEvaluation s(k, frame, x);
    ASSERT_TRUE(s.prepare(c, std::size_t(1) << 30));
    EXPECT_LT(storedVsEvaluator(s, k, frame, x, c, dim), 1e-12)
        << name << " poly " << poly << " " << dim << "D";
    // the three-column path where only the polynomial has a last column
    EXPECT_LT(storedVsEvaluator(s, k, frame, x, c, dim, true), 1e-12)
        << name << " poly " << poly << " " << dim << "D, last column";
}

INSTANTIATE_TEST_SUITE_P(KernelsPolyDim, StoredCase, ::testing::ValuesIn(test::kernelCases()),
    test::kernelCaseName);

TEST(StoredEvaluation, BitIdenticalOnOneAndTwoThreads)
{
    // enough kernel entries for the product to use threads
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.6);
    const LinearPolynomial frame(true, 3);
    const Points x = randomPoints(6000, 3, 41);
    const Points c = randomPoints(80, 3, 42);
    StoredEvaluation s(k, frame, x);
    ASSERT_TRUE(s.prepare(c, std::size_t(1) << 30));
    ASSERT_GE(s.bytes()/(sizeof(double) + 1), StoredEvaluation::minParallelEntries);
    // the set as built, then patched (three centres moved: their columns
    // added in the same pass over the rows)
    Points moved = c;
    moved.row(5) = randomPoints(1, 3, 43);
    moved.row(40) = randomPoints(1, 3, 44);
    moved.row(79) = randomPoints(1, 3, 45);
    for (const Points* set : std::vector<const Points*>{&c, &moved})
    {
        ASSERT_TRUE(s.prepare(*set, std::size_t(1) << 30));
        ASSERT_EQ(s.patchColumns(), set == &c ? 0 : 3);
        const Values alpha = test::smoothField(*set);
        const Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
        Values v1, v2;
        // and written straight to targets (each row to point n - 1 - i)
        StoredEvaluation::Targets t;
        for (Eigen::Index i = 0; i <= x.rows(); ++i) t.start.push_back(std::size_t(i));
        for (Eigen::Index i = 0; i < x.rows(); ++i) t.point.push_back(int(x.rows() - 1 - i));
        std::vector<double> o1(3*x.rows()), o2(3*x.rows());
        const int nThreads = omp_get_max_threads();
        omp_set_num_threads(1);
        s.evaluate(alpha, beta, v1);
        ASSERT_TRUE(s.evaluateInto(alpha, beta, t, 3, o1.data()));
        omp_set_num_threads(2);
        s.evaluate(alpha, beta, v2);
        ASSERT_TRUE(s.evaluateInto(alpha, beta, t, 3, o2.data()));
        omp_set_num_threads(nThreads);
        EXPECT_TRUE(v1 == v2);
        EXPECT_TRUE(o1 == o2);
        for (Eigen::Index i = 0; i < x.rows(); ++i)
        {
            for (int q = 0; q < 3; ++q) ASSERT_EQ(o1[3*(x.rows() - 1 - i) + q], v1(i, q)) << i;
        }
        EXPECT_LT(storedVsEvaluator(s, k, frame, x, *set, 3), 1e-12);
    }
}

TEST(StoredEvaluation, ColumnsOfEightSixteenAndThirtyTwoBitsEqualTheEvaluator)
{
    // columns stored in 8 bits up to 256 centres, in 16 up to 65536, in 32
    // beyond: each side of each switch against the evaluator (a narrow
    // column beyond its range would wrap to another centre)
    const LinearPolynomial frame(true, 3);
    const Points x = randomPoints(200, 3, 41);
    for (const int n : {256, 257, 65536, 65600})
    {
        const double R = n > 1000 ? 0.08 : 0.5;
        const RadialKernel k = RadialKernel::fromName("WendlandC2", R);
        const Points c = randomPoints(n, 3, 42);
        StoredEvaluation s(k, frame, x);
        ASSERT_TRUE(s.prepare(c, std::size_t(1) << 30));
        EXPECT_LT(storedVsEvaluator(s, k, frame, x, c, 3), 1e-12) << n << " centres";
        // the bytes: per entry a value and a column of 1, 2 or 4 bytes,
        // with room for 1/32 more (the budget allows it: merges later
        // reuse the storage)
        std::size_t entries = 0;
        for (Eigen::Index i = 0; i < x.rows(); ++i)
        {
            for (Eigen::Index j = 0; j < c.rows(); ++j)
            {
                entries += (x.row(i) - c.row(j)).squaredNorm() < R*R;
            }
        }
        EXPECT_GT(entries, std::size_t(n > 1000 ? 100 : 50)*x.rows()) << n << " centres";
        const std::size_t columnBytes = n <= 256 ? 1 : n <= 65536 ? 2 : 4;
        EXPECT_EQ
        (
            s.bytes(),
            (x.rows() + 1)*sizeof(std::size_t)
          + (entries + entries/32)*(sizeof(double) + columnBytes)
        ) << n << " centres";
    }
}

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
    ASSERT_TRUE(s.prepare(b, budget));   // a trial: a patch of a
    EXPECT_EQ(s.patchColumns(), 1);
    ASSERT_TRUE(s.prepare(a, budget));   // undone: the stored set
    EXPECT_EQ(s.patchColumns(), 0);
    EXPECT_EQ(s.builds(), 1);
    EXPECT_GT(s.bytes(), 0u);

    // a budget below one matrix: nothing stored, the caller evaluates itself;
    // asked again with no more room, not tried again; with room, built
    StoredEvaluation small(k, frame, x);
    EXPECT_FALSE(small.prepare(a, 64));
    EXPECT_EQ(small.bytes(), 0u);
    EXPECT_FALSE(small.prepare(a, 64));
    EXPECT_EQ(small.attempts(), 1);
    EXPECT_TRUE(small.prepare(a, budget));
    EXPECT_EQ(small.attempts(), 2);
    EXPECT_EQ(small.builds(), 1);
}

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

// A set that differs from the stored one by swaps, additions or removals is
// served by a patch (no rebuild) and evaluates as the evaluator does; more
// changes than maxPatchColumns build the matrix.
TEST_P(StoredCase, PatchedSetsEqualTheEvaluator)
{
    const auto [name, poly, dim] = GetParam();
    const RadialKernel k = RadialKernel::fromName(name, test::testRadius(name, 0.4));
    const LinearPolynomial frame(poly, dim);
    const Points x = randomPoints(600, dim, 41);
    const Points base = randomPoints(50, dim, 42);
    const Points extra = randomPoints(20, dim, 43);
    const std::size_t budget = std::size_t(1) << 30;
    StoredEvaluation s(k, frame, x);
    ASSERT_TRUE(s.prepare(base, budget));

    const auto check = [&](const Points& c, int patchColumns, int builds, const char* what)
    {
        ASSERT_TRUE(s.prepare(c, budget)) << what;
        EXPECT_EQ(s.patchColumns(), patchColumns) << what;
        EXPECT_EQ(s.builds(), builds) << what;
        EXPECT_LT(storedVsEvaluator(s, k, frame, x, c, dim), 1e-12)
            << what << ": " << name << " poly " << poly << " " << dim << "D";
    };

    Points swapped = base;                 // two swaps, the order changed too
    swapped.row(3) = extra.row(0);
    swapped.row(17) = extra.row(1);
    swapped.row(0).swap(swapped.row(49));
    check(swapped, 2, 1, "two swaps");

    Points grown(base.rows() + 3, 3);      // three points added
    grown << base, extra.topRows(3);
    check(grown, 3, 1, "three added");

    const Points shrunk = base.topRows(base.rows() - 5);   // five removed
    check(shrunk, 0, 1, "five removed");

    Points union_(base.rows() + 4, 3);     // a blend: old and new centres
    union_ << swapped, extra.middleRows(2, 4);
    check(union_, 6, 1, "union");

    Points once(base.rows() + 1, 3);       // a centre added, then given twice:
    once << base, extra.row(7);            // the second copy's column is
    check(once, 1, 1, "added once");       // computed, the first one's kept
    Points twice(base.rows() + 2, 3);
    twice << base, extra.row(7), extra.row(7);
    check(twice, 2, 1, "added twice");
    Points stored(base.rows() + 1, 3);     // a stored centre given twice:
    stored << base, base.row(5);           // both weights on its column
    check(stored, 0, 1, "stored one twice");

    Points many = base;                    // too many: a matrix made (from
    many.topRows(StoredEvaluation::maxPatchColumns + 1) =    // the stored
        extra.topRows(StoredEvaluation::maxPatchColumns + 1); // one, compact)
    check(many, 0, 2, "many swaps");
    EXPECT_EQ(s.merges(), k.compact() ? 1 : 0);
    check(base, 0, 2, "back");
}

//- The stored product of s and of a matrix built anew for the centres c
//  (prepared in both), largest difference relative to the values' size
double storedVsBuilt
(
    const StoredEvaluation& s,
    const RadialKernel& k,
    const LinearPolynomial& frame,
    const Points& x,
    const Points& c
)
{
    StoredEvaluation built(k, frame, x);
    EXPECT_TRUE(built.prepare(c, std::size_t(1) << 30));
    EXPECT_EQ(built.merges(), 0);
    const Values alpha = test::smoothField(c);
    const Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
    Values a, b;
    s.evaluate(alpha, beta, a);
    built.evaluate(alpha, beta, b);
    return (a - b).cwiseAbs().maxCoeff()/(1 + b.cwiseAbs().maxCoeff());
}

// A set too far from the stored one for a patch, but sharing at least half
// of its centres, is merged from it: the same entries as a matrix built anew
// (the same product to round-off; the entries' order is
// the stored one's), whether its new centres are few (by the patches' loop)
// or many (by a tree), centres given twice, the columns' width growing from
// 8 to 16 bits; with fewer shared than new centres, built
TEST(StoredEvaluation, MergedSetsEqualBuiltOnes)
{
    const RadialKernel k = RadialKernel::fromName("WendlandC2", 0.35);
    const LinearPolynomial frame(true, 3);
    const Points x = randomPoints(2000, 3, 61);
    const Points base = randomPoints(250, 3, 62);
    const Points extra = randomPoints(150, 3, 63);
    const std::size_t budget = std::size_t(1) << 30;
    StoredEvaluation s(k, frame, x);
    ASSERT_TRUE(s.prepare(base, budget));
    int merges = 0;
    const auto check = [&](const Points& c, bool merged, const char* what)
    {
        ASSERT_TRUE(s.prepare(c, budget)) << what;
        merges += merged;
        EXPECT_EQ(s.merges(), merges) << what;
        EXPECT_EQ(s.patchColumns(), 0) << what;
        EXPECT_LT(storedVsBuilt(s, k, frame, x, c), 1e-13) << what;
        EXPECT_LT(storedVsEvaluator(s, k, frame, x, c, 3), 1e-12) << what;
    };

    Points swaps = base;                   // ten swaps, reordered
    swaps.topRows(10) = extra.topRows(10);
    swaps.row(20).swap(swaps.row(200));
    check(swaps, true, "ten swaps");

    Points grown(swaps.rows() + 40, 3);    // 40 added (a tree), 16-bit
    grown << swaps, extra.middleRows(10, 40);
    check(grown, true, "forty added");

    Points twice(grown.rows(), 3);         // ten shared centres given twice,
    twice << grown.topRows(grown.rows() - 20), // ten new, twenty gone
        grown.middleRows(100, 10), extra.middleRows(60, 10);
    check(twice, true, "given twice");

    Points far = twice;                    // most centres new: built
    far.topRows(far.rows()/2 + 10) = randomPoints(far.rows()/2 + 10, 3, 64);
    check(far, false, "most new");

    // a merge over the budget is refused as a build would be: nothing kept
    StoredEvaluation tight(k, frame, x);
    ASSERT_TRUE(tight.prepare(base, budget));
    const std::size_t one = tight.bytes();
    EXPECT_FALSE(tight.prepare(swaps, one + one/2));
    EXPECT_EQ(tight.merges(), 0);
    EXPECT_TRUE(tight.prepare(swaps, 2*one + one/2));
    EXPECT_EQ(tight.merges(), 1);

    // a budget for one matrix: a set refused (nothing current) leaves the
    // set before stored, but the next set that fits alone is stored (the
    // one of the past dropped), not refused for its sake
    StoredEvaluation one1(k, frame, x);
    ASSERT_TRUE(one1.prepare(base, one + one/2));
    EXPECT_FALSE(one1.prepare(swaps, one + one/2));
    EXPECT_TRUE(one1.prepare(grown, one + one/2));
    EXPECT_LT(storedVsEvaluator(one1, k, frame, x, grown, 3), 1e-12);
}

} // namespace
