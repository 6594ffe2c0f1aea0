// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Test helper of the cell-quality scan tests: a block of hexahedra (and its
// tetrahedral, prism and mixed variants) with the reference decomposition's
// quality, random deformations of its points, and the comparison of a scan
// with the reference.
#pragma once

#include "CellQualityScan.hpp"
#include "TetMeasures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace dcprbf
{
namespace test
{

// A block of n x n x n unit hexahedra (points on a lattice), each cell its
// six faces as point quadrilaterals (orientation as it comes: the quality
// does not depend on it)
struct HexBlock
{
    int n;
    std::vector<double> points;
    std::vector<std::size_t> cellStart{0}, faceStart{0};
    std::vector<int> cellFaces, facePoints;

    //- How each cube is split: not (a hexahedron), into the six
    //  tetrahedra around its diagonal (Kuhn; each its four triangles), into
    //  two triangular prisms (faces in varying order, orientation and first
    //  point), or cube by cube into each of these in turn (mixed)
    enum class Split { none, tets, prisms, mixed };

    explicit HexBlock(int nn, bool tets = false)
    :
        HexBlock(nn, tets ? Split::tets : Split::none)
    {}

    HexBlock(int nn, Split split) : n(nn)
    {
        for (int k = 0; k <= n; ++k)
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i)
                {
                    points.insert(points.end(), {double(i), double(j), 0.8*k});
                }
        const auto id = [this](int i, int j, int k) { return i + (n + 1)*(j + (n + 1)*k); };
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                {
                    const int cube = i + n*(j + n*k);
                    const Split as =
                        split == Split::mixed ? Split(cube % 3) : split;
                    if (as == Split::tets)
                    {
                        addKuhnTets(id, i, j, k);
                        continue;
                    }
                    if (as == Split::prisms)
                    {
                        addPrisms(id, i, j, k, cube);
                        continue;
                    }
                    const int v[8] =
                    {
                        id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                        id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)
                    };
                    const int f[6][4] =
                    {
                        {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                        {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}
                    };
                    for (const auto& face : f)
                    {
                        for (const int c : face) facePoints.push_back(v[c]);
                        faceStart.push_back(facePoints.size());
                        cellFaces.push_back(int(faceStart.size()) - 2);
                    }
                    cellStart.push_back(cellFaces.size());
                }
    }

    template<class Id>
    void addKuhnTets(const Id& id, int i, int j, int k)
    {
        const auto corner = [&](int bits)
        {
            return id(i + (bits & 1), j + ((bits >> 1) & 1), k + ((bits >> 2) & 1));
        };
        const int axes[6][3] = {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}};
        for (const auto& a : axes)
        {
            const int t[4] = {corner(0), corner(a[0]), corner(a[0] | a[1]), corner(7)};
            const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
            for (const auto& face : f)
            {
                for (const int c : face) facePoints.push_back(t[c]);
                faceStart.push_back(facePoints.size());
                cellFaces.push_back(int(faceStart.size()) - 2);
            }
            cellStart.push_back(cellFaces.size());
        }
    }

    template<class Id>
    void addPrisms(const Id& id, int i, int j, int k, int cube)
    {
        // the x-y square split along a diagonal, extruded in z
        const int lo[2][3] =
        {
            {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k)},
            {id(i, j, k), id(i + 1, j + 1, k), id(i, j + 1, k)}
        };
        for (int h = 0; h < 2; ++h)
        {
            const int a = lo[h][0], b = lo[h][1], c = lo[h][2];
            const int up = (n + 1)*(n + 1);
            std::vector<std::vector<int>> f =
            {
                {a, c, b}, {a + up, b + up, c + up}, {a, b, b + up, a + up},
                {b, c, c + up, b + up}, {c, a, a + up, c + up}
            };
            // vary the order of the faces, their orientation and first point
            std::rotate(f.begin(), f.begin() + (cube + h) % 5, f.end());
            for (std::size_t q = 0; q < f.size(); ++q)
            {
                if ((cube + q) % 2) std::reverse(f[q].begin(), f[q].end());
                std::rotate(f[q].begin(), f[q].begin() + (cube + h + q) % f[q].size(), f[q].end());
                for (const int p : f[q]) facePoints.push_back(p);
                faceStart.push_back(facePoints.size());
                cellFaces.push_back(int(faceStart.size()) - 2);
            }
            cellStart.push_back(cellFaces.size());
        }
    }

    // The reference: TetQuality::compute on the decomposition
    double reference(std::size_t c, const std::vector<double>& p, TetQuality::Metric m) const
    {
        const auto at = [](const std::vector<double>& x, int i)
        {
            return Eigen::Vector3d(x[3*i], x[3*i + 1], x[3*i + 2]);
        };
        const auto centre = [&](const std::vector<double>& x, int f)
        {
            Eigen::Vector3d s(Eigen::Vector3d::Zero());
            for (std::size_t j = faceStart[f]; j < faceStart[f + 1]; ++j) s += at(x, facePoints[j]);
            return Eigen::Vector3d(s/double(faceStart[f + 1] - faceStart[f]));
        };
        Eigen::Vector3d cc0(Eigen::Vector3d::Zero()), cc(Eigen::Vector3d::Zero());
        for (std::size_t k = cellStart[c]; k < cellStart[c + 1]; ++k)
        {
            cc0 += centre(points, cellFaces[k]);
            cc += centre(p, cellFaces[k]);
        }
        cc0 /= double(cellStart[c + 1] - cellStart[c]);
        cc /= double(cellStart[c + 1] - cellStart[c]);
        double q = 1e300;
        for (std::size_t k = cellStart[c]; k < cellStart[c + 1]; ++k)
        {
            const int f = cellFaces[k];
            const std::size_t j0 = faceStart[f], j1 = faceStart[f + 1];
            for (std::size_t j = j0; j < j1; ++j)
            {
                const int a = facePoints[j], b = facePoints[j + 1 < j1 ? j + 1 : j0];
                const Eigen::Vector3d r[4] = {cc0, centre(points, f), at(points, a), at(points, b)};
                const Eigen::Vector3d x[4] = {cc, centre(p, f), at(p, a), at(p, b)};
                q = std::min(q, TetQuality::compute(r, x, m));
            }
        }
        return q;
    }

    CellQualityScan scan(TetQuality::Metric m) const
    {
        return CellQualityScan(cellStart, cellFaces, faceStart, facePoints, points.data(), m);
    }
};

// Random smooth-ish deformation, large enough to invert some cells
inline std::vector<double> deformed(const std::vector<double>& x, double amplitude, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> p(x);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] += amplitude*u(gen);
    return p;
}



// Every metric: the scan of b at p equals the reference decomposition,
// some cells inverted, not all
inline void expectTheDecomposition(const HexBlock& b, const std::vector<double>& p, std::size_t nCells)
{
    for (const auto m : {TetQuality::Metric::sizeShape, TetQuality::Metric::size,
                         TetQuality::Metric::shape})
    {
        const CellQualityScan scan(b.scan(m));
        ASSERT_EQ(scan.size(), nCells);
        std::vector<double> q(scan.size());
        scan.measure(p.data(), q.data());
        std::size_t nInverted = 0;
        for (std::size_t c = 0; c < q.size(); ++c)
        {
            const double ref = b.reference(c, p, m);
            EXPECT_NEAR(q[c], ref, 1e-10*std::max(1.0, std::abs(ref))) << c;
            nInverted += (ref <= 0);
        }
        EXPECT_GT(nInverted, 0u);
        EXPECT_LT(nInverted, nCells);
    }
}

} // namespace test
} // namespace dcprbf
