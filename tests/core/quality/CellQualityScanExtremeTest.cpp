// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the flat cell-quality scan on extreme and degenerate cells:
// the ranking key, extreme and flat tetrahedra and prisms, SIMD builds, no
// floating-point trap.
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
