// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the cells' quality bounds (CellQualityBound) and of the scan
// of the lowest cells (CellQualityScan::measureLowest): a bound never above
// the quality, for every kind of cell, inverted and degenerate ones
// included; the lowest cells, the minimum and the inverted cells as the
// full scan's, bit for bit.
#include "HexBlock.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <random>

using namespace dcprbf;
using namespace dcprbf::test;

namespace
{

const TetQuality::Metric metrics[3] =
{
    TetQuality::Metric::sizeShape, TetQuality::Metric::size, TetQuality::Metric::shape
};

//- Cells of every kind, each with its own points: hexahedron, prism,
//  tetrahedron, pyramid, and snappyHexMesh's split hexahedron (a cube whose
//  top face is split into four: 13 points, 9 faces, 5-sided sides)
struct Cells
{
    std::vector<double> points;
    std::vector<std::size_t> cellStart{0}, faceStart{0};
    std::vector<int> cellFaces, facePoints;
    std::vector<int> kind;

    void add(const std::vector<Eigen::Vector3d>& p, const std::vector<std::vector<int>>& faces, int k)
    {
        const int first = int(points.size()/3);
        for (const auto& x : p) points.insert(points.end(), {x.x(), x.y(), x.z()});
        for (const auto& f : faces)
        {
            for (const int v : f) facePoints.push_back(first + v);
            faceStart.push_back(facePoints.size());
            cellFaces.push_back(int(faceStart.size()) - 2);
        }
        cellStart.push_back(cellFaces.size());
        kind.push_back(k);
    }

    //- n cells of each kind, their reference shapes jittered (shift: apart)
    explicit Cells(int n, unsigned seed = 1)
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> u(-1, 1);
        const auto cube = [](double x, double y, double z) { return Eigen::Vector3d(x, y, 0.5*z); };
        for (int c = 0; c < n; ++c)
        {
            const Eigen::Vector3d shift(3.0*c, 0, 0);
            const auto jitter = [&](std::vector<Eigen::Vector3d> p)
            {
                for (auto& x : p) x += shift + 0.1*Eigen::Vector3d(u(gen), u(gen), u(gen));
                return p;
            };
            const std::vector<Eigen::Vector3d> hex =
            {
                cube(0, 0, 0), cube(1, 0, 0), cube(1, 1, 0), cube(0, 1, 0),
                cube(0, 0, 1), cube(1, 0, 1), cube(1, 1, 1), cube(0, 1, 1)
            };
            add(jitter(hex), {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}}, 0);
            add
            (
                jitter({cube(0, 0, 0), cube(1, 0, 0), cube(0, 1, 0), cube(0, 0, 1), cube(1, 0, 1), cube(0, 1, 1)}),
                {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}, 1
            );
            add
            (
                jitter({cube(0, 0, 0), cube(1, 0, 0), cube(0, 1, 0), cube(0, 0, 1)}),
                {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}, 2
            );
            add
            (
                jitter({cube(0, 0, 0), cube(1, 0, 0), cube(1, 1, 0), cube(0, 1, 0), cube(0.5, 0.5, 1)}),
                {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}, 3
            );
            std::vector<Eigen::Vector3d> split(hex);
            // top edge midpoints 8 (4-5), 9 (5-6), 10 (6-7), 11 (7-4); centre 12
            split.insert
            (
                split.end(),
                {cube(0.5, 0, 1), cube(1, 0.5, 1), cube(0.5, 1, 1), cube(0, 0.5, 1), cube(0.5, 0.5, 1)}
            );
            add
            (
                jitter(split),
                {
                    {0, 3, 2, 1}, {0, 1, 5, 8, 4}, {1, 2, 6, 9, 5}, {2, 3, 7, 10, 6}, {3, 0, 4, 11, 7},
                    {4, 8, 12, 11}, {8, 5, 9, 12}, {12, 9, 6, 10}, {11, 12, 10, 7}
                },
                4
            );
        }
    }

    CellQualityScan scan(TetQuality::Metric m) const
    {
        return CellQualityScan(cellStart, cellFaces, faceStart, facePoints, points.data(), m);
    }

    //- The points moved cell by cell: an affine map near a rotation
    //  (random), then each point by up to noise
    std::vector<double> moved(double noise, unsigned seed) const
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> u(-1, 1);
        std::vector<double> p(points);
        for (std::size_t c = 0; c + 1 < cellStart.size(); ++c)
        {
            const Eigen::Matrix3d T =
                Eigen::AngleAxisd(3*u(gen), Eigen::Vector3d(u(gen), u(gen), u(gen)).normalized()).toRotationMatrix()
               *(Eigen::Matrix3d::Identity() + 0.2*Eigen::Matrix3d::Random());
            const Eigen::Vector3d t(u(gen), u(gen), u(gen));
            std::vector<int> pts;
            for (std::size_t k = cellStart[c]; k < cellStart[c + 1]; ++k)
            {
                const int f = cellFaces[k];
                pts.insert(pts.end(), facePoints.begin() + long(faceStart[f]), facePoints.begin() + long(faceStart[f + 1]));
            }
            std::sort(pts.begin(), pts.end());
            pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
            for (const int i : pts)
            {
                const Eigen::Vector3d x(points[3*i], points[3*i + 1], points[3*i + 2]);
                const Eigen::Vector3d y = T*x + t + noise*Eigen::Vector3d(u(gen), u(gen), u(gen));
                for (int d = 0; d < 3; ++d) p[3*i + d] = y[d];
            }
        }
        return p;
    }
};

} // namespace


TEST(CellQualityBound, NeverAboveTheQualityOfAnyKindOfCell)
{
    const Cells cells(60);
    for (const auto m : metrics)
    {
        const CellQualityScan scan(cells.scan(m));
        std::vector<double> q(scan.size()), lb(scan.size());
        int bounded[5] = {0, 0, 0, 0, 0}, inverted = 0;
        unsigned seed = 1;
        for (const double noise : {0.0, 1e-12, 1e-6, 1e-3, 0.01, 0.05, 0.2, 0.5})
        {
            const std::vector<double> p(cells.moved(noise, seed++));
            scan.measure(p.data(), q.data());
            scan.lowerBounds(p.data(), lb.data());
            for (std::size_t c = 0; c < q.size(); ++c)
            {
                EXPECT_LE(lb[c], q[c]) << "cell " << c << " kind " << cells.kind[c] << " noise " << noise;
                bounded[cells.kind[c]] += std::isfinite(lb[c]);
                inverted += q[c] <= 0;
                if (noise == 0 && cells.kind[c] != 2)
                {
                    // an affine motion: the bound is the quality (to the
                    // round-off it allows for)
                    EXPECT_NEAR(lb[c], q[c], 1e-5) << c;
                }
            }
        }
        // bounded: every kind but the tetrahedron (measured as cheaply)
        EXPECT_EQ(bounded[2], 0);
        for (const int k : {0, 1, 3, 4}) EXPECT_GT(bounded[k], 200) << k;
        EXPECT_GT(inverted, 20);
    }
}


TEST(CellQualityBound, NeverAboveTheQualityWhenOneVertexMovesAlone)
{
    // each vertex of each cell moved alone (the others fixed: the fit of
    // the others is exact, so every vertex must enter the bound)
    const Cells cells(1);
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const auto m : metrics)
    {
        const CellQualityScan scan(cells.scan(m));
        std::vector<double> q(scan.size()), lb(scan.size());
        int nBounded = 0;
        for (std::size_t v = 0; v < cells.points.size()/3; ++v)
        {
            for (const double d : {0.01, 0.05, 0.2})
            {
                std::vector<double> p(cells.points);
                for (int k = 0; k < 3; ++k) p[3*v + k] += d*u(gen);
                scan.measure(p.data(), q.data());
                scan.lowerBounds(p.data(), lb.data());
                for (std::size_t c = 0; c < q.size(); ++c)
                {
                    EXPECT_LE(lb[c], q[c]) << "cell " << c << " point " << v << " by " << d;
                    nBounded += std::isfinite(lb[c]) && q[c] < 1 - 1e-3;
                }
            }
        }
        EXPECT_GT(nBounded, 20);
    }
}


TEST(CellQualityBound, InverseNormIsTheReciprocalLeastSingularValue)
{
    // |E^-1|_2 = 1/sigma_min(E), against Eigen's SVD: from above, within
    // its round-off margin (u cond(E))
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int t = 0; t < 500; ++t)
    {
        Eigen::Matrix3d E;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) E(i, j) = u(gen)*(t % 5 ? 1.0 : 1e-3*(j + 1));
        const double* c = E.data();   // columns: the edges
        const double k = CellQualityBound::inverseNorm(c, c + 3, c + 6);
        // dynamic size: the fixed-size SVD trips GCC's -Wmaybe-uninitialized
        const Eigen::JacobiSVD<Eigen::MatrixXd> svd{Eigen::MatrixXd(E)};
        const double expected = 1/svd.singularValues().minCoeff();
        if (std::isfinite(k))
        {
            EXPECT_GE(k, expected) << t;
            EXPECT_LE(k, expected*(1 + 2e-6)) << t;
        }
    }
}


TEST(CellQualityBound, NoBoundForAnInvertingFitOrAPoorOne)
{
    const double inf = std::numeric_limits<double>::infinity();
    for (const auto m : metrics)
    {
        EXPECT_EQ(CellQualityBound::fromMap(-1, 3, 1, 0, m), -inf);
        EXPECT_EQ(CellQualityBound::fromMap(0, 3, 1, 0, m), -inf);
        // the identity: s = 1; eps at or above it: none
        EXPECT_EQ(CellQualityBound::fromMap(1, 3, 1, 1, m), -inf);
        EXPECT_NEAR(CellQualityBound::fromMap(1, 3, 1, 0, m), 1, 1e-11);
        EXPECT_LT(CellQualityBound::fromMap(1, 3, 1, 0.1, m), CellQualityBound::fromMap(1, 3, 1, 0.01, m));
    }
    // a degenerate reference tetrahedron: no bound from it
    const double e0[3] = {1, 0, 0}, e1[3] = {0, 1, 0}, flat[3] = {1, 1, 0};
    EXPECT_EQ(CellQualityBound::inverseNorm(e0, e1, flat), inf);
}


namespace
{

//- measureLowest(k) against measure(): the k lowest (value and cell), the
//  minimum and the inverted cells the same, bit for bit; every other value
//  a lower bound above the k-th lowest
std::size_t expectTheLowest(const CellQualityScan& scan, const std::vector<double>& p, std::size_t k)
{
    const std::size_t n = scan.size();
    std::vector<double> q(n), ql(n);
    scan.measure(p.data(), q.data());
    const std::size_t nMeasured = scan.measureLowest(p.data(), ql.data(), k);
    std::vector<int> byQ(n), byQl(n);
    for (std::size_t i = 0; i < n; ++i) byQ[i] = byQl[i] = int(i);
    const auto lowest = [](const std::vector<double>& v, std::vector<int>& idx)
    {
        std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) { return v[a] < v[b]; });
    };
    lowest(q, byQ);
    lowest(ql, byQl);
    for (std::size_t j = 0; j < std::min(k, n); ++j)
    {
        EXPECT_EQ(byQ[j], byQl[j]) << "rank " << j;
        EXPECT_EQ(q[byQ[j]], ql[byQl[j]]) << "rank " << j;
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        EXPECT_EQ(q[i] <= 0, ql[i] <= 0) << "cell " << i;
        EXPECT_LE(ql[i], q[i]) << "cell " << i;
        if (ql[i] != q[i])
        {
            EXPECT_GT(ql[i], q[byQ[std::min(k, n) - 1]]) << "cell " << i;
        }
    }
    return nMeasured;
}

} // namespace


TEST(CellQualityScan, LowestCellsAsTheFullScanFewMeasured)
{
    // blocks of hexahedra and of prisms turned about an axis, fading over
    // the block (0.3 rad at the axis: a smooth motion, as the RBF's), and
    // squeezed near their centre (the few worst cells, quality ~0.9): few
    // cells need measuring to find the few worst (metric shape: the
    // squeeze keeps the worst shapes within a few % of the rest, the bounds
    // clear few cells; correct all the same)
    for (const auto split : {HexBlock::Split::none, HexBlock::Split::prisms})
    {
        const HexBlock b(14, split);
        std::vector<double> p(b.points);
        for (std::size_t i = 0; i < p.size()/3; ++i)
        {
            const double x = p[3*i] - 7, y = p[3*i + 1] - 7, z = p[3*i + 2] - 5.6;
            const double a = 0.3*std::exp(-(x*x + y*y)/2000);
            p[3*i] = 7 + std::cos(a)*x - std::sin(a)*y;
            p[3*i + 1] = 7 + std::sin(a)*x + std::cos(a)*y;
            p[3*i + 2] -= 0.3*std::exp(-(x*x + y*y + z*z)/2);
        }
        for (const auto m : metrics)
        {
            const CellQualityScan scan(b.scan(m));
            for (const std::size_t k : {1, 5, 60})
            {
                const std::size_t nMeasured = expectTheLowest(scan, p, k);
                if (k < 60 && m != TetQuality::Metric::shape)
                {
                    EXPECT_LT(nMeasured, scan.size()/4) << "k " << k;
                }
            }
        }
    }
}


TEST(CellQualityScan, LowestCellsAsTheFullScanWithInvertedCells)
{
    const Cells cells(40);
    const HexBlock b(10, HexBlock::Split::mixed);
    for (const auto m : metrics)
    {
        const CellQualityScan scan(cells.scan(m)), block(b.scan(m));
        unsigned seed = 11;
        for (const double noise : {0.0, 1e-3, 0.1, 0.4})
        {
            for (const std::size_t k : {1, 7, 100, 1000})
            {
                expectTheLowest(scan, cells.moved(noise, seed++), k);
                expectTheLowest(block, deformed(b.points, noise, seed++), k);
            }
        }
    }
}


TEST(CellQualityScan, LowestCellsFindABarelyInvertedHexahedron)
{
    // one hexahedron of a block folded until one tetrahedron of its
    // decomposition is inverted by a hair: pushed down until measure() says
    // so, then measureLowest must say the same at every k
    const HexBlock b(6);
    const CellQualityScan scan(b.scan(TetQuality::Metric::sizeShape));
    std::vector<double> p(b.points), q(scan.size());
    const int corner = 3*(3 + 7*(3 + 7*3)) + 2;     // point (3, 3, 3), z
    double lo = p[corner] - 1.2, hi = p[corner];
    for (int it = 0; it < 200; ++it)
    {
        // bisection on the point's height: the least quality crosses 0
        p[corner] = 0.5*(lo + hi);
        scan.measure(p.data(), q.data());
        (*std::min_element(q.begin(), q.end()) <= 0 ? lo : hi) = p[corner];
    }
    p[corner] = lo;
    scan.measure(p.data(), q.data());
    const double qMin = *std::min_element(q.begin(), q.end());
    ASSERT_LE(qMin, 0);
    EXPECT_GT(qMin, -1e-9);
    for (const std::size_t k : {1, 3, 50}) expectTheLowest(scan, p, k);
}
