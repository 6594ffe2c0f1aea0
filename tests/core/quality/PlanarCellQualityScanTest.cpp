// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the 2D cell-quality scan: on prisms extruded from polygons and
// moved in the plane, the same values as CellQualityScan's decomposition of
// the prisms, whatever the thread count.
#include "CellQualityScan.hpp"
#include "PlanarCellQualityScan.hpp"
#include "PlanarMapBatch.hpp"
#include "TetBatch.hpp"
#include "SimdWidths.hpp"
#include "TetMeasures.hpp"
#include "WorstBatch.hpp"

#include <gtest/gtest.h>

#include <omp.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstring>
#include <random>

using namespace dcprbf;

namespace
{

// An n x n lattice of unit squares in the plane of the components
// (axis0, axis1), every third one split into two triangles; the prisms
// extruded from them by a thickness h along the third component (back
// points 0 .. N-1, front points N .. 2N-1)
struct Extrusion
{
    int axis0, axis1, axis2;
    std::vector<double> points;
    std::vector<std::size_t> polygonStart{0}, cellStart{0}, faceStart{0};
    std::vector<int> polygonPoints, cellFaces, facePoints;

    Extrusion(int n, int a0, int a1, double h) : axis0(a0), axis1(a1), axis2(3 - a0 - a1)
    {
        const int N = (n + 1)*(n + 1);
        points.resize(6*N);
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i)
            {
                const int p = i + (n + 1)*j;
                for (const int plane : {0, 1})
                {
                    double* x = &points[3*(p + plane*N)];
                    x[axis0] = i;
                    x[axis1] = 0.7*j;
                    x[axis2] = plane*h;
                }
            }
        const auto id = [n](int i, int j) { return i + (n + 1)*j; };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
            {
                const int q[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
                if ((i + j) % 3 == 0)
                {
                    addPrism({q[0], q[1], q[2]}, N);
                    addPrism({q[0], q[2], q[3]}, N);
                }
                else
                {
                    addPrism({q[0], q[1], q[2], q[3]}, N);
                }
            }
    }

    void addFace(const std::vector<int>& f)
    {
        facePoints.insert(facePoints.end(), f.begin(), f.end());
        faceStart.push_back(facePoints.size());
        cellFaces.push_back(int(faceStart.size()) - 2);
    }

    void addPrism(const std::vector<int>& polygon, int N)
    {
        polygonPoints.insert(polygonPoints.end(), polygon.begin(), polygon.end());
        polygonStart.push_back(polygonPoints.size());
        addFace(std::vector<int>(polygon.rbegin(), polygon.rend()));
        std::vector<int> front(polygon);
        for (int& p : front) p += N;
        addFace(front);
        for (std::size_t k = 0; k < polygon.size(); ++k)
        {
            const int a = polygon[k], b = polygon[(k + 1) % polygon.size()];
            addFace({a, b, b + N, a + N});
        }
        cellStart.push_back(cellFaces.size());
    }

    // The same random in-plane displacement for a back point and its
    // front twin
    std::vector<double> moved(double amplitude, unsigned seed) const
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> u(-1, 1);
        std::vector<double> p(points);
        const std::size_t N = points.size()/6;
        for (std::size_t i = 0; i < N; ++i)
        {
            const double d0 = amplitude*u(gen), d1 = amplitude*u(gen);
            for (const std::size_t k : {i, i + N})
            {
                p[3*k + axis0] += d0;
                p[3*k + axis1] += d1;
            }
        }
        return p;
    }
};

} // namespace


TEST(PlanarCellQualityScan, EqualsTheDecompositionOfThePrismsIncludingInverted)
{
    for (const auto& axes : {std::pair<int, int>(0, 1), std::pair<int, int>(2, 0)})
    {
        for (const double h : {1.0, 0.01})
        {
            const Extrusion e(8, axes.first, axes.second, h);
            const std::vector<double> p(e.moved(0.4, 3));
            for (const auto m : {TetQuality::Metric::sizeShape, TetQuality::Metric::size,
                                 TetQuality::Metric::shape})
            {
                const PlanarCellQualityScan planar
                (
                    e.polygonStart, e.polygonPoints, e.points.data(), e.axis0, e.axis1, m
                );
                const CellQualityScan prisms
                (
                    e.cellStart, e.cellFaces, e.faceStart, e.facePoints, e.points.data(), m
                );
                ASSERT_EQ(planar.size(), prisms.size());
                std::vector<double> q(planar.size()), ref(prisms.size());
                planar.measure(p.data(), q.data());
                prisms.measure(p.data(), ref.data());
                int nInverted = 0;
                for (std::size_t c = 0; c < q.size(); ++c)
                {
                    EXPECT_NEAR(q[c], ref[c], 1e-10*std::max(1.0, std::abs(ref[c]))) << c;
                    nInverted += (ref[c] <= 0);
                }
                EXPECT_GT(nInverted, 0);
                EXPECT_LT(nInverted, int(q.size()));
            }
        }
    }
}


TEST(PlanarCellQualityScan, RigidMotionIsOneAndThreadsAreBitIdentical)
{
    // 10800 cells (5400 quadrilaterals, 5400 triangles): several chunks of
    // each detail::PlanarPolygonBatch, enough for the scan to use threads
    const Extrusion e(90, 0, 1, 0.1);
    std::vector<double> p(e.points);
    const double c = std::cos(0.7), s = std::sin(0.7);
    for (std::size_t i = 0; i < p.size()/3; ++i)
    {
        const double x = p[3*i], y = p[3*i + 1];
        p[3*i] = c*x - s*y + 3;
        p[3*i + 1] = s*x + c*y - 1;
    }
    const PlanarCellQualityScan scan(e.polygonStart, e.polygonPoints, e.points.data(), 0, 1);
    ASSERT_GE(scan.size(), PlanarCellQualityScan::minParallelCells);
    std::vector<double> q(scan.size());
    scan.measure(p.data(), q.data());
    for (const double x : q) EXPECT_NEAR(x, 1.0, 1e-12);

    const std::vector<double> d(e.moved(0.3, 9));
    std::vector<double> q1(scan.size()), q2(scan.size());
    const int nThreads = omp_get_max_threads();
    omp_set_num_threads(1);
    scan.measure(d.data(), q1.data());
    omp_set_num_threads(2);
    scan.measure(d.data(), q2.data());
    omp_set_num_threads(nThreads);
    EXPECT_EQ(q1, q2);
}


// A subset of a scan's cells (in any order), built from its polygons
// without classifying the cells again, measures each of them as the whole
// scan does, bit for bit; a second subset from the same scan too (its
// scratch numbering reset); a cell index out of range refused
TEST(PlanarCellQualityScan, SubsetsEqualTheWholeScan)
{
    const Extrusion e(12, 0, 1, 0.1);
    const PlanarCellQualityScan scan(e.polygonStart, e.polygonPoints, e.points.data(), 0, 1);
    const std::vector<double> d(e.moved(0.3, 9));
    std::vector<double> all(scan.size());
    scan.measure(d.data(), all.data());
    for (const int stride : {5, 3})
    {
        std::vector<int> cells;
        for (int c = int(scan.size()) - 1; c >= 0; c -= stride) cells.push_back(c);
        std::swap(cells[0], cells[cells.size()/2]);
        const PlanarCellQualityScan sub(scan, cells, e.points.data());
        ASSERT_EQ(sub.size(), cells.size());
        std::vector<double> q(sub.size());
        sub.measure(d.data(), q.data());
        for (std::size_t k = 0; k < cells.size(); ++k)
        {
            EXPECT_EQ(q[k], all[std::size_t(cells[k])]) << "cell " << cells[k];
        }
    }
    // refused part-way (its first cells numbered), then a valid subset:
    // the scratch reset
    EXPECT_THROW
    (
        PlanarCellQualityScan(scan, {0, 1, int(scan.size())}, e.points.data()),
        std::invalid_argument
    );
    const PlanarCellQualityScan after(scan, {1, 0}, e.points.data());
    std::vector<double> q(2);
    after.measure(d.data(), q.data());
    EXPECT_EQ(q[0], all[1]);
    EXPECT_EQ(q[1], all[0]);
}


TEST(PlanarCellQualityScan, SimdBuildsBitIdentical)
{
    // the AVX-512, the AVX2 and the default build of the SIMD kernels:
    // the same bits
    if (!detail::TetBatch::wideAvailable())
    {
        GTEST_SKIP() << "no AVX2 or AVX-512 build on this processor: one build only";
    }
    const Extrusion e(10, 0, 1, 0.1);
    const PlanarCellQualityScan scan(e.polygonStart, e.polygonPoints, e.points.data(), 0, 1);
    const std::vector<double> d(e.moved(0.3, 9));
    std::vector<double> narrow(scan.size());
    scan.measure(d.data(), narrow.data(), false);
    test::atEachSimdWidth([&](unsigned bits)
    {
        std::vector<double> wide(scan.size());
        scan.measure(d.data(), wide.data(), true);
        EXPECT_EQ(wide, narrow) << bits << " bits";
    });
}


TEST(PlanarCellQualityScan, RefusesBadInput)
{
    const double p0[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    EXPECT_THROW(PlanarCellQualityScan({0, 4}, {0, 1, 2}, p0, 0, 1), std::invalid_argument);
    EXPECT_THROW(PlanarCellQualityScan({0, 2}, {0, 1}, p0, 0, 1), std::invalid_argument);
    EXPECT_THROW(PlanarCellQualityScan({0, 3}, {0, 1, 2}, p0, 1, 1), std::invalid_argument);
    EXPECT_THROW(PlanarCellQualityScan({0, 3}, {0, -1, 2}, p0, 0, 1), std::invalid_argument);
}


TEST(PlanarCellQualityScan, DegenerateReferenceIsOne)
{
    // a flat reference polygon (its points on a line): quality 1 whatever
    // the motion (TetQuality's convention); a proper triangle beside it
    // (a quadrilateral and a triangle: n maps and the triangle's own)
    const double p0[15] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 0, 1, 0};
    const double p[15] = {0, 0, 0, 1, 0.5, 0, 2, -0.3, 0, 3, 0.2, 0, 0.5, 1, 0};
    const PlanarCellQualityScan scan({0, 4, 7, 10}, {0, 1, 2, 3, 0, 1, 4, 0, 1, 2}, p0, 0, 1);
    std::vector<double> q(3);
    scan.measure(p, q.data());
    EXPECT_EQ(q[0], 1.0);
    EXPECT_LT(q[1], 1.0);
    EXPECT_GT(q[1], 0.0);
    EXPECT_EQ(q[2], 1.0);
}
