// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the flat cell-quality scan: the same values as the reference
// TetQuality::compute on the same decomposition, whatever the thread count.
#include "CellQualityScan.hpp"
#include "TetBatch.hpp"
#include "SimdWidths.hpp"
#include "TetMeasures.hpp"

#include <gtest/gtest.h>

#include <omp.h>

#include <fenv.h>

#include <algorithm>
#include <random>

using namespace dcprbf;

namespace
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
std::vector<double> deformed(const std::vector<double>& x, double amplitude, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> p(x);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] += amplitude*u(gen);
    return p;
}

} // namespace


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


// Every metric: the scan of b at p equals the reference decomposition,
// some cells inverted, not all
static void expectTheDecomposition(const HexBlock& b, const std::vector<double>& p, std::size_t nCells)
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


TEST(CellQualityScan, KeyRanksAsTheQuality)
{
    // rankKey increases with the quality for every metric, so the worst
    // tetrahedron of a cell is found without cbrt and sqrt
    std::mt19937 gen(13);
    std::uniform_real_distribution<double> logJ(-6, 6), logA(0, 8);
    for (const auto m : {TetQuality::Metric::sizeShape, TetQuality::Metric::size,
                         TetQuality::Metric::shape})
    {
        for (int t = 0; t < 5000; ++t)
        {
            const double J1 = std::exp(logJ(gen)), J2 = std::exp(logJ(gen));
            // |A|^2 >= 3 J^(2/3) (arithmetic-geometric mean of the squared
            // singular values)
            const double a1 = 3*std::cbrt(J1*J1)*std::exp(logA(gen));
            const double a2 = 3*std::cbrt(J2*J2)*std::exp(logA(gen));
            const double q1 = detail::TetMeasures::quality(J1, a1, m);
            const double q2 = detail::TetMeasures::quality(J2, a2, m);
            if (std::abs(q1 - q2) > 1e-12*std::max(q1, q2))
            {
                EXPECT_EQ(q1 < q2, detail::TetMeasures::rankKey(J1, a1, m) < detail::TetMeasures::rankKey(J2, a2, m));
            }
        }
    }
}


// The scan of b at p (extreme cells) equals the reference to 1e-10
static void expectExtremeAsTheReference
(
    const HexBlock& b,
    const std::vector<double>& p,
    const double factor
)
{
    const CellQualityScan scan(b.scan(TetQuality::Metric::sizeShape));
    std::vector<double> q(scan.size());
    scan.measure(p.data(), q.data());
    for (std::size_t c = 0; c < q.size(); ++c)
    {
        const double ref = b.reference(c, p, TetQuality::Metric::sizeShape);
        EXPECT_NEAR(q[c], ref, 1e-10*std::abs(ref) + 1e-300) << c << ' ' << factor;
    }
}


TEST(CellQualityScan, ExtremeTetrahedraCompareByTheirQuality)
{
    // a cell flattened to J ~ 1e-45 (q^6 underflows) and one stretched
    // 1e30 times (overflows): still the reference value
    const HexBlock b(2);
    for (const double factor : {1e-45, 1e30})
    {
        std::vector<double> p(b.points);
        for (std::size_t i = 0; i < p.size()/3; ++i)
        {
            if (p[3*i] < 1.5 && p[3*i + 1] < 1.5 && p[3*i + 2] < 1.0) continue;
            p[3*i + 2] = 0.8 + (p[3*i + 2] - 0.8)*factor;
        }
        expectExtremeAsTheReference(b, p, factor);
    }
}


TEST(CellQualityScan, DegenerateReferenceCellsAreOne)
{
    // a flat reference block: every tetrahedron degenerate, quality 1
    // (TetQuality's convention) whatever the deformation, on every path
    for (const auto split : {HexBlock::Split::none, HexBlock::Split::prisms,
                             HexBlock::Split::tets})
    {
        HexBlock b(2, split);
        for (std::size_t i = 2; i < b.points.size(); i += 3) b.points[i] = 0;
        const std::vector<double> p(deformed(b.points, 0.3, 17));
        const CellQualityScan scan(b.scan(TetQuality::Metric::sizeShape));
        std::vector<double> q(scan.size());
        scan.measure(p.data(), q.data());
        for (std::size_t c = 0; c < q.size(); ++c)
        {
            EXPECT_EQ(b.reference(c, p, TetQuality::Metric::sizeShape), 1.0);
            EXPECT_EQ(q[c], 1.0) << c;
        }
    }
}


TEST(CellQualityScan, PrismsWithSomeDegenerateReferenceTetrahedraEqualTheDecomposition)
{
    // one reference point moved onto the point below it: the prisms around
    // that vertical edge have degenerate reference tetrahedra among valid
    // ones (the checked kernel), the others all valid (the unchecked one)
    HexBlock b(3, HexBlock::Split::prisms);
    const int n1 = 4, above = 1 + n1*(1 + n1*1), below = 1 + n1*1;
    for (int d = 0; d < 3; ++d) b.points[3*above + d] = b.points[3*below + d];
    expectTheDecomposition(b, deformed(b.points, 0.45, 13), 2*27);
}


TEST(CellQualityScan, PrismCellsEqualTheDecomposition)
{
    // 2 x 6^3 prisms, faces in every order, orientation and first point,
    // some inverted: the prism kernel (one prism per SIMD lane) equals the
    // minimum over the 18 tetrahedra of the decomposition
    const HexBlock b(6, HexBlock::Split::prisms);
    expectTheDecomposition(b, deformed(b.points, 0.45, 7), 2*216);
}


TEST(CellQualityScan, MixedCellsEachInItsPlace)
{
    // hexahedra, tetrahedra and prisms in turn (three paths, one Morton
    // order): every value where the caller's cell is (a wrong scatter
    // fails)
    const HexBlock b(6, HexBlock::Split::mixed);
    expectTheDecomposition(b, deformed(b.points, 0.45, 9), 72 + 6*72 + 2*72);
}


TEST(CellQualityScan, SimdBuildsBitIdentical)
{
    // the AVX-512 and AVX2 builds (where the processor has them) and the
    // default one: no contraction, the same values to the last bit
    if (!detail::TetBatch::wideAvailable())
    {
        GTEST_SKIP() << "no AVX2 or AVX-512 build on this processor: one build only";
    }
    const HexBlock b(8, HexBlock::Split::mixed);
    const std::vector<double> p(deformed(b.points, 0.3, 21));
    for (const auto m : {TetQuality::Metric::sizeShape, TetQuality::Metric::size,
                         TetQuality::Metric::shape})
    {
        const CellQualityScan scan(b.scan(m));
        std::vector<double> narrow(scan.size());
        scan.measure(p.data(), narrow.data(), false);
        test::atEachSimdWidth([&](unsigned bits)
        {
            std::vector<double> wide(scan.size());
            scan.measure(p.data(), wide.data(), true);
            EXPECT_EQ(wide, narrow) << bits << " bits";
        });
    }
}


TEST(CellQualityScan, ExtremePrismsAndTetrahedraCompareByTheirQuality)
{
    // prisms and tetrahedra flattened to J = 1e-45 or stretched 1e30 times
    // (beyond the SIMD kernels' key range: the scalar path), then sheared
    // so that the tetrahedra differ: uniform in z, so no value is round-off
    // (a cell flattened on one side only is: its J's are then noise)
    for (const auto split : {HexBlock::Split::prisms, HexBlock::Split::tets})
    {
        const HexBlock b(2, split);
        for (const double factor : {1e-45, 1e30})
        {
            std::vector<double> p(b.points);
            for (std::size_t i = 0; i < p.size()/3; ++i)
            {
                p[3*i + 2] *= factor;
                p[3*i] += 0.2*p[3*i + 1]*p[3*i + 1];
            }
            expectExtremeAsTheReference(b, p, factor);
        }
    }
}


TEST(CellQualityScan, NoFloatingPointTrapOnExtremeOrDegenerateCells)
{
    // OpenFOAM traps division by zero, invalid operations and overflow: no
    // lane of the SIMD kernels, no scalar path may raise one, for cells
    // collapsed to 1e-25 of their size in every direction (J = 1e-75,
    // |A|^2 = 3e-50), flattened to 1e-45 or stretched 1e30 times, inverted
    // or on a flat reference (a trap kills the test)
    for (const auto split : {HexBlock::Split::none, HexBlock::Split::prisms,
                             HexBlock::Split::tets, HexBlock::Split::mixed})
    {
        HexBlock b(3, split);
        std::vector<std::vector<double>> moved;
        for (const double f : {1e-25, 1e-45, 1e30})
        {
            std::vector<double> p(b.points);
            for (std::size_t i = 0; i < p.size(); ++i)
            {
                if (f == 1e-25 || i % 3 == 2) p[i] *= f;
            }
            moved.push_back(p);
        }
        moved.push_back(deformed(b.points, 0.6, 23));
        HexBlock flat(b);
        for (std::size_t i = 2; i < flat.points.size(); i += 3) flat.points[i] = 0;
        for (const auto m : {TetQuality::Metric::sizeShape, TetQuality::Metric::size,
                             TetQuality::Metric::shape})
        {
            const CellQualityScan scan(b.scan(m)), flatScan(flat.scan(m));
            std::vector<double> q(scan.size());
            // on this thread only (the trap mask is per thread)
            const int nThreads = omp_get_max_threads();
            omp_set_num_threads(1);
            feclearexcept(FE_ALL_EXCEPT);
            feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
            for (const auto& p : moved)
            {
                for (const bool wide : {true, false})
                {
                    scan.measure(p.data(), q.data(), wide);
                    flatScan.measure(p.data(), q.data(), wide);
                }
            }
            fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
            omp_set_num_threads(nThreads);
            for (const double x : q) EXPECT_EQ(x, 1.0);   // the flat reference's
        }
    }
}
