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
