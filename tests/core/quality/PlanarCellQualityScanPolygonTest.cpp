// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the 2D cell-quality scan on polygons of every kind: the
// same values as their triangles' qualities, and the same bits as the
// classes it used before detail::PlanarPolygonBatch.
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

TEST(PlanarCellQualityScan, PolygonsOfEveryKindEqualTheirTrianglesQualities)
{
    // 400 separate triangles, quadrilaterals or pentagons (several of
    // detail::PlanarPolygonBatch's chunks; pentagons: detail::PlanarMapBatch), each with its
    // own points, moved each by its own map: a shear, a scaling by 1e16 or
    // 1e-16 (J beyond the rank key's range: the scalar path), a reflection
    // (inverted), one point pushed across (some triangles inverted), a flat
    // reference (quality 1; the points overlap: the cells are separate);
    // the value: the least TetQuality of the triangles (a triangle: its
    // own; else those of the vertex average and an edge)
    const double corners[5][2] = {{0, 0}, {1, 0}, {1.2, 0.6}, {0.5, 1}, {-0.2, 0.6}};
    for (const int N : {3, 4, 5})
    {
        const int n = 400;
        std::mt19937 gen(11);
        std::uniform_real_distribution<double> u(-0.1, 0.1);
        std::vector<double> p0(3*N*n), p(3*N*n);
        std::vector<std::size_t> start{0};
        std::vector<int> polygon;
        for (int c = 0; c < n; ++c)
        {
            const int kind = c % 6;
            for (int k = 0; k < N; ++k)
            {
                double* r = &p0[3*(N*c + k)];
                r[0] = corners[N == 3 ? 2*k % 5 : k][0] + u(gen);
                r[1] = kind == 5 ? 0.5*r[0] : corners[N == 3 ? 2*k % 5 : k][1] + u(gen);
                r[2] = 0;
                const double x = r[0], y = r[1];
                const double scale = kind == 1 ? 1e16 : kind == 2 ? 1e-16 : 1.0;
                double* m = &p[3*(N*c + k)];
                m[0] = scale*(kind == 3 ? -x : x + 0.3*y);
                m[1] = scale*y + (kind == 4 && k == 0 ? 2.0 : 0.0);
                m[2] = 0;
                polygon.push_back(N*c + k);
            }
            start.push_back(polygon.size());
        }
        for (const auto metric : {TetQuality::Metric::sizeShape, TetQuality::Metric::size,
                                  TetQuality::Metric::shape})
        {
            const PlanarCellQualityScan scan(start, polygon, p0.data(), 0, 1, metric);
            std::vector<double> q(n);
            scan.measure(p.data(), q.data());
            // a subset (pentagons: the maps' path) measures as the whole
            const std::vector<int> some{n - 1, 7, 3, 200, 201};
            const PlanarCellQualityScan sub(scan, some, p0.data());
            std::vector<double> qs(some.size());
            sub.measure(p.data(), qs.data());
            for (std::size_t k = 0; k < some.size(); ++k)
            {
                EXPECT_EQ(qs[k], q[std::size_t(some[k])]) << N << "-gons, cell " << some[k];
            }
            int nTiny = 0, nInverted = 0, nOne = 0;
            for (int c = 0; c < n; ++c)
            {
                // (A = diag(F, 1): the edges (a - o, b - o, unit z), o the
                // vertex average or, a triangle, its point 0)
                const auto edges = [&](const std::vector<double>& x, const int j)
                {
                    Eigen::Matrix3d E = Eigen::Matrix3d::Identity();
                    const double* v = &x[3*N*c];
                    for (int d = 0; d < 2; ++d)
                    {
                        double o = 0;
                        for (int k = 0; k < N; ++k) o += v[3*k + d]/N;
                        o = N == 3 ? v[d] : o;
                        const int a = N == 3 ? 1 : j, b = N == 3 ? 2 : (j + 1) % N;
                        E(d, 0) = v[3*a + d] - o;
                        E(d, 1) = v[3*b + d] - o;
                    }
                    return E;
                };
                double expected = 1e308;
                for (int j = 0; j < (N == 3 ? 1 : N); ++j)
                {
                    expected = std::min
                    (
                        expected, TetQuality::compute(edges(p0, j), edges(p, j), metric)
                    );
                }
                EXPECT_NEAR(q[c], expected, 1e-12*std::abs(expected)) << N << " " << c;
                nTiny += (expected > 0 && expected < 1e-8);
                nInverted += (expected <= 0);
                nOne += (expected == 1);
            }
            EXPECT_GT(nTiny, 100);
            EXPECT_GT(nInverted, 50);
            EXPECT_GT(nOne, 50);
        }
    }
}


namespace
{

// The qualities as the scan computed them before detail::PlanarPolygonBatch, from
// the classes it still uses for the other polygons: per map (a triangle:
// its own, (b - a, c - a); else (a - c, b - c), c the vertex average) the
// reference inverse, detail::PlanarMapBatch, detail::TetMeasures::Worst (the first of
// equal keys), detail::WorstBatch
std::vector<double> mapBatchQualities
(
    const std::vector<std::size_t>& start,
    const std::vector<int>& polygon,
    const std::vector<double>& p0,
    const std::vector<double>& p,
    const TetQuality::Metric metric,
    const bool wide
)
{
    const std::size_t n = start.size() - 1;
    std::vector<double> q(n);
    detail::WorstBatch finals(metric, wide);
    for (std::size_t c = 0; c < n; ++c)
    {
        const std::size_t j0 = start[c], k = start[c + 1] - j0;
        // the edges (ea, eb) of map j for the points x (x y from x + 3 v)
        const auto edges = [&](const std::vector<double>& x, const std::size_t j, double e[4])
        {
            const auto at = [&](const std::size_t m, const int d)
            {
                return x[3*std::size_t(polygon[j0 + m]) + d];
            };
            if (k == 3)
            {
                for (int d = 0; d < 2; ++d)
                {
                    e[d] = at(1, d) - at(0, d);
                    e[2 + d] = at(2, d) - at(0, d);
                }
                return;
            }
            for (int d = 0; d < 2; ++d)
            {
                double o = 0;
                for (std::size_t m = 0; m < k; ++m) o += at(m, d);
                o /= double(k);
                e[d] = at(j, d) - o;
                e[2 + d] = at((j + 1) % k, d) - o;
            }
        };
        const std::size_t nMaps = k == 3 ? 1 : k;
        detail::PlanarMapBatch maps;
        maps.resize(nMaps);
        for (std::size_t j = 0; j < nMaps; ++j)
        {
            double e0[4], e[4];
            edges(p0, j, e0);
            edges(p, j, e);
            const double det0 = e0[0]*e0[3] - e0[1]*e0[2];
            const double s2 = std::max(e0[0]*e0[0] + e0[1]*e0[1], e0[2]*e0[2] + e0[3]*e0[3]);
            const bool flat = !(det0*det0 > 1e-28*s2*s2);
            const double inv[4] =
            {
                flat ? 0 : e0[3]/det0, flat ? 0 : -e0[2]/det0,
                flat ? 0 : -e0[1]/det0, flat ? 0 : e0[0]/det0
            };
            maps.set(j, e[0], e[1], e[2], e[3], inv, flat);
        }
        maps.measure(metric, wide);
        detail::TetMeasures::Worst worst(metric);
        for (std::size_t j = 0; j < nMaps; ++j) worst.add(maps.J(j), maps.a2(j), maps.key(j));
        finals.add(worst, &q[c]);
    }
    finals.finish();
    return q;
}

} // namespace


TEST(PlanarCellQualityScan, SameBitsAsTheMapBatchPath)
{
    // Random triangles and quadrilaterals (convex and not, repeated points,
    // nearly flat, scaled by 1e+-150), rigidly moved and mirrored squares
    // and rhombi (equal keys of different maps), and two found by a
    // review: a quadrilateral with only map 0 degenerate, a triangle whose
    // key underflows in range (J = 1e-29); every build, every metric
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> p0, p;
    std::vector<std::size_t> start{0};
    std::vector<int> polygon;
    const auto addCell = [&](const std::vector<std::array<double, 4>>& xy)
    {
        for (const auto& v : xy)
        {
            polygon.push_back(int(p0.size()/3));
            p0.insert(p0.end(), {v[0], v[1], 0});
            p.insert(p.end(), {v[2], v[3], 0});
        }
        start.push_back(polygon.size());
    };
    for (int c = 0; c < 3000; ++c)
    {
        const int N = 3 + c % 2;
        const double scale = c % 7 == 0 ? 1e150 : c % 7 == 1 ? 1e-150 : 1.0;
        const double rot = u(gen), cs = std::cos(rot), sn = std::sin(rot);
        std::vector<std::array<double, 4>> xy;
        for (int k = 0; k < N; ++k)
        {
            // c % 5 == 0: a square (rhombus if c % 3) moved rigidly or
            // mirrored; c % 5 == 1: a point repeated; else random
            double x = u(gen), y = u(gen);
            if (c % 5 == 0)
            {
                const double a = 2*M_PI*k/N + 0.3;
                x = std::cos(a)*(c % 3 ? 1.5 : 1.0);
                y = std::sin(a);
            }
            if (c % 5 == 1 && k == 1)
            {
                x = xy[0][0];
                y = xy[0][1];
            }
            const double mx = c % 5 == 0 ? cs*x - sn*y : x + 0.3*u(gen);
            const double my = c % 5 == 0 ? (c % 2 ? -1 : 1)*(sn*x + cs*y) : y + 0.3*u(gen);
            xy.push_back({scale*x, scale*y, scale*mx, scale*my});
        }
        addCell(xy);
    }
    addCell({{0, 0, 0, 0}, {2, 0, 2, 0.5}, {3, 1, 3.2, 1}, {-1, -1, -1, -1.4}});
    addCell({{0, 0, 0, 0}, {1, 0, 3e4, 0}, {0, 1, 0, 3e-34}});
    for (const auto metric : {TetQuality::Metric::sizeShape, TetQuality::Metric::size,
                              TetQuality::Metric::shape})
    {
        const PlanarCellQualityScan scan(start, polygon, p0.data(), 0, 1, metric);
        for (const bool wide : {true, false})
        {
            std::vector<double> q(scan.size());
            scan.measure(p.data(), q.data(), wide);
            const std::vector<double> ref
            (
                mapBatchQualities(start, polygon, p0, p, metric, wide)
            );
            int nDiffer = 0;
            for (std::size_t c = 0; c < q.size(); ++c)
            {
                nDiffer += std::memcmp(&q[c], &ref[c], sizeof(double)) != 0;
            }
            EXPECT_EQ(nDiffer, 0) << "metric " << int(metric) << " wide " << wide;
        }
    }
}
