// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the flat cell-quality scan: the same values as the reference
// TetQuality::compute on the same decomposition, whatever the thread count.
#include "HexBlock.hpp"
#include "TetBatch.hpp"
#include "SimdWidths.hpp"

#include <gtest/gtest.h>

#include <omp.h>

#include <fenv.h>

#include <algorithm>
#include <random>

using namespace dcprbf;
using namespace dcprbf::test;


TEST(CellQualityScan, TetQualityEqualsTheReferenceMetric)
{
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    int nInverted = 0;
    for (int t = 0; t < 2000; ++t)
    {
        Eigen::Vector3d r[4], c[4];
        for (int k = 0; k < 4; ++k)
        {
            r[k] = Eigen::Vector3d(u(gen), u(gen), u(gen));
            c[k] = r[k] + (t % 3 ? 0.3 : 1.0)*Eigen::Vector3d(u(gen), u(gen), u(gen));
        }
        for (const auto m : {TetQuality::Metric::sizeShape, TetQuality::Metric::size,
                             TetQuality::Metric::shape})
        {
            const double ref = TetQuality::compute(r, c, m);
            const double q = detail::TetMeasures::tetQuality
            (
                r[0].data(), r[1].data(), r[2].data(), r[3].data(),
                c[0].data(), c[1].data(), c[2].data(), c[3].data(), m
            );
            EXPECT_NEAR(q, ref, 1e-10*std::max(1.0, std::abs(ref))) << t;
            nInverted += (m == TetQuality::Metric::sizeShape && ref <= 0);
        }
    }
    EXPECT_GT(nInverted, 100);   // the inverted branch was exercised
}


TEST(CellQualityScan, DegenerateReferenceIsOne)
{
    const double r[4][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    const double c[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    EXPECT_EQ(detail::TetMeasures::tetQuality(r[0], r[1], r[2], r[3], c[0], c[1], c[2], c[3],
                                          TetQuality::Metric::sizeShape), 1.0);
}



TEST(CellQualityScan, CellsEqualTheReferenceDecompositionIncludingInverted)
{
    const HexBlock b(6);
    expectTheDecomposition(b, deformed(b.points, 0.45, 3), 216);
}


TEST(CellQualityScan, TetrahedralCellsMeasuredAsThemselvesEqualTheDecomposition)
{
    // 6 x 6^3 Kuhn tetrahedra, some inverted: the one measure per cell
    // equals the minimum over its twelve decomposition tetrahedra
    const HexBlock b(6, true);
    expectTheDecomposition(b, deformed(b.points, 0.3, 5), 6*216);
}


TEST(CellQualityScan, MixedCellsOverManyBlocksEqualTheDecomposition)
{
    // hexahedra, tetrahedra and prisms in turn: 2187 cells, several of
    // the scan's blocks of 256 (each block's batches hold every kind; some
    // cells inverted)
    const HexBlock b(9, HexBlock::Split::mixed);
    const CellQualityScan probe(b.scan(TetQuality::Metric::sizeShape));
    ASSERT_EQ(probe.size(), 2187u);
    expectTheDecomposition(b, deformed(b.points, 0.3, 7), probe.size());
}


TEST(CellQualityScan, EachShapeMeasuredByItsPath)
{
    // the mixed block: hexahedra (detail::HexBatch), Kuhn tetrahedra, prisms
    // (faces in every order), recognised; the scan of a general cell (a
    // hexahedron split by a seventh face) goes from its faces
    const HexBlock b(6, HexBlock::Split::mixed);
    const CellQualityScan::Shapes s = b.scan(TetQuality::Metric::sizeShape).shapes();
    EXPECT_EQ(s.hexahedra, 72u);
    EXPECT_EQ(s.tetrahedra, 6*72u);
    EXPECT_EQ(s.prisms, 2*72u);
    EXPECT_EQ(s.others, 0u);
    const HexBlock h(3);
    EXPECT_EQ(h.scan(TetQuality::Metric::sizeShape).shapes().hexahedra, 27u);
}


TEST(CellQualityScan, RigidMotionIsOne)
{
    const HexBlock b(3);
    std::vector<double> p(b.points.size());
    const double c = std::cos(0.6), s = std::sin(0.6);
    for (std::size_t i = 0; i < p.size()/3; ++i)
    {
        const double* x = &b.points[3*i];
        p[3*i] = c*x[0] - s*x[1] + 5;
        p[3*i + 1] = s*x[0] + c*x[1] - 2;
        p[3*i + 2] = x[2] + 1;
    }
    const CellQualityScan scan(b.scan(TetQuality::Metric::sizeShape));
    std::vector<double> q(scan.size());
    scan.measure(p.data(), q.data());
    for (const double x : q) EXPECT_NEAR(x, 1.0, 1e-12);
}


TEST(CellQualityScan, BitIdenticalOnOneAndTwoThreads)
{
    // hexahedra, tetrahedra and prisms (every path)
    const HexBlock b(12, HexBlock::Split::mixed);
    const std::vector<double> p(deformed(b.points, 0.3, 11));
    const CellQualityScan scan(b.scan(TetQuality::Metric::sizeShape));
    ASSERT_GE(scan.size(), CellQualityScan::minParallelCells);
    std::vector<double> q1(scan.size()), q2(scan.size());
    const int nThreads = omp_get_max_threads();
    omp_set_num_threads(1);
    scan.measure(p.data(), q1.data());
    omp_set_num_threads(2);
    scan.measure(p.data(), q2.data());
    omp_set_num_threads(nThreads);
    EXPECT_EQ(q1, q2);
}


TEST(CellQualityScan, RepeatedMeasurementsEqualAFreshScans)
{
    // each thread's batches are kept between measurements: a scan that
    // measured other points (on other thread counts and builds) gives the
    // bits of a fresh scan
    const HexBlock b(12, HexBlock::Split::mixed);
    const std::vector<double> p1(deformed(b.points, 0.45, 31)), p2(deformed(b.points, 0.2, 32));
    const CellQualityScan used(b.scan(TetQuality::Metric::sizeShape));
    std::vector<double> q(used.size()), fresh(used.size());
    const int nThreads = omp_get_max_threads();
    omp_set_num_threads(2);
    used.measure(p1.data(), q.data(), false);
    omp_set_num_threads(1);
    used.measure(p1.data(), q.data());
    used.measure(p2.data(), q.data());
    omp_set_num_threads(nThreads);
    b.scan(TetQuality::Metric::sizeShape).measure(p2.data(), fresh.data());
    EXPECT_EQ(q, fresh);
    EXPECT_NE(std::count(q.begin(), q.end(), 1.0), std::ptrdiff_t(q.size()));
}


TEST(CellQualityScan, ASubsetMeasuresItsCellsAsTheWholeScan)
{
    // some of a mixed scan's cells (hexahedra, tetrahedra, prisms; in no
    // order, over several blocks), and a subset of that subset: each cell's
    // value is the whole scan's, bit for bit; a cell given twice or out of
    // range is refused
    const HexBlock b(12, HexBlock::Split::mixed);
    const std::vector<double> p(deformed(b.points, 0.35, 41));
    const CellQualityScan whole(b.scan(TetQuality::Metric::sizeShape));
    std::vector<double> all(whole.size());
    whole.measure(p.data(), all.data());
    std::vector<int> cells;
    for (int i = int(whole.size()) - 2; i >= 0; i -= 7) cells.push_back(i);
    for (int i = 0; i < 60; i += 7) cells.push_back(i);     // (the others: 2 mod 7)
    const CellQualityScan some(whole, cells);
    ASSERT_EQ(some.size(), cells.size());
    std::vector<double> q(some.size());
    some.measure(p.data(), q.data());
    for (std::size_t k = 0; k < cells.size(); ++k)
    {
        ASSERT_EQ(q[k], all[std::size_t(cells[k])]) << "cell " << cells[k];
    }
    EXPECT_LT(*std::min_element(q.begin(), q.end()), 0.0);    // inverted ones among them

    const std::vector<int> again{5, 0, 17, 3};
    const CellQualityScan fewer(some, again);
    std::vector<double> r(fewer.size());
    fewer.measure(p.data(), r.data());
    for (std::size_t k = 0; k < again.size(); ++k)
    {
        EXPECT_EQ(r[k], q[std::size_t(again[k])]);
    }
    EXPECT_THROW(CellQualityScan(whole, std::vector<int>{3, 9, 3}), std::invalid_argument);
    EXPECT_THROW(CellQualityScan(whole, std::vector<int>{int(whole.size())}), std::invalid_argument);
    EXPECT_EQ(CellQualityScan(whole, std::vector<int>{}).size(), 0u);
}


TEST(CellQualityScan, ASubsetsPointsAreThoseItsCellsRead)
{
    // A subset's pointIds: each once, the whole scan's, and exactly the
    // points its qualities depend on (the trial window makes the mesh at
    // those alone): every other point moved, its qualities are the same
    // bit for bit; each of its points moved alone, one changes. A second
    // subset of the same scan numbers its points afresh
    const HexBlock b(6, HexBlock::Split::mixed);
    const std::vector<double> p(deformed(b.points, 0.2, 7));
    const CellQualityScan whole(b.scan(TetQuality::Metric::sizeShape));
    const std::vector<int> cells{40, 3, 77, 12};
    const CellQualityScan some(whole, cells);
    const std::vector<int>& ids = some.pointIds();
    std::vector<int> sorted(ids);
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a point twice";
    for (const int i : ids)
    {
        ASSERT_NE(std::find(whole.pointIds().begin(), whole.pointIds().end(), i),
            whole.pointIds().end());
    }
    std::vector<double> q0(some.size()), q(some.size());
    some.measure(p.data(), q0.data());
    std::vector<double> moved(p);
    for (std::size_t i = 0; i < moved.size()/3; ++i)
    {
        if (!std::binary_search(sorted.begin(), sorted.end(), int(i))) moved[3*i] += 0.3;
    }
    some.measure(moved.data(), q.data());
    EXPECT_EQ(q, q0) << "a quality read a point not among pointIds";
    for (const int i : ids)
    {
        moved = p;
        moved[3*std::size_t(i) + 1] += 0.05;
        some.measure(moved.data(), q.data());
        EXPECT_NE(q, q0) << "point " << i << " is not read";
    }
    EXPECT_EQ(CellQualityScan(whole, cells).pointIds(), ids);
    EXPECT_EQ(CellQualityScan(whole, std::vector<int>{}).pointIds().size(), 0u);
}


TEST(CellQualityScan, RefusesInconsistentRows)
{
    const double p0[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    EXPECT_THROW(CellQualityScan({0, 2}, {0}, {0, 3}, {0, 1, 2}, p0), std::invalid_argument);
    EXPECT_THROW(CellQualityScan({0, 1}, {1}, {0, 3}, {0, 1, 2}, p0), std::invalid_argument);
    EXPECT_THROW(CellQualityScan({0, 1}, {0}, {0, 2}, {0, 1}, p0), std::invalid_argument);
    EXPECT_THROW(CellQualityScan({0, 0, 1}, {0}, {0, 3}, {0, 1, 2}, p0), std::invalid_argument);
}

