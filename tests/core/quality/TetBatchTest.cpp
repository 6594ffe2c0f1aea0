// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the SIMD qualities: detail::TetMeasures::quality over the whole
// ranked range, the same on the AVX-512, the AVX2 and the default build;
// the width cap picks each build.
#include "TetBatch.hpp"
#include "SimdWidths.hpp"
#include "TetMeasures.hpp"
#include "WorstBatch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace dcprbf;

namespace
{

//- The widest build this test's build and the processor allow, from
//  /proc/cpuinfo's flags (GCC on x86-64 Linux: the dispatching build)
unsigned expectedWidth()
{
    #if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
    {
        if (line.rfind("flags", 0) == 0)
        {
            const auto has = [&](const char* flag)
            {
                return (line + " ").find(std::string(" ") + flag + " ") != std::string::npos;
            };
            return has("avx512f") && has("avx512dq") && has("avx512vl") ? 512u
                : has("avx2") ? 256u : 0u;
        }
    }
    #endif
    return detail::TetBatch::width();   // no flags to read: not checked
}

} // namespace


// The processor's widest build is the one used; the cap picks each build
// (between the builds' widths: the narrower build), and restores
TEST(TetBatch, WidthCapPicksEachBuild)
{
    const test::WidthCapGuard guard;
    const unsigned widest = expectedWidth();
    detail::TetBatch::limitWidth(512);
    EXPECT_EQ(detail::TetBatch::width(), widest);
    detail::TetBatch::limitWidth(4096);
    EXPECT_EQ(detail::TetBatch::width(), widest);
    detail::TetBatch::limitWidth(300);
    EXPECT_EQ(detail::TetBatch::width(), std::min(widest, 256u));
    detail::TetBatch::limitWidth(256);
    EXPECT_EQ(detail::TetBatch::width(), std::min(widest, 256u));
    detail::TetBatch::limitWidth(100);
    EXPECT_EQ(detail::TetBatch::width(), 0u);
    EXPECT_FALSE(detail::TetBatch::wideAvailable());

    // the environment's DCPRBF_SIMD_WIDTH, read once for the first cap
    EXPECT_EQ(detail::TetBatch::widthCapOf(nullptr), 512u);
    EXPECT_EQ(detail::TetBatch::widthCapOf("256"), 256u);
    EXPECT_EQ(detail::TetBatch::widthCapOf("0"), 0u);
    EXPECT_EQ(detail::TetBatch::widthCapOf("1024"), 512u);
    EXPECT_EQ(detail::TetBatch::widthCapOf("avx2"), 512u);
    EXPECT_EQ(detail::TetBatch::widthCapOf("256bits"), 512u);
    EXPECT_EQ(detail::TetBatch::widthCapOf("-1"), 512u);
    EXPECT_EQ(detail::TetBatch::widthCapOf(""), 512u);
}


TEST(TetBatch, QualitiesEqualTetMeasuresOverTheRankedRange)
{
    // J from 1e-30 to 1e30 (log-uniform, and both ends), |A|^2 from its
    // least, 3 J^(2/3), up to e^8 times that (and below 1e25)
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> logJ(std::log(1e-30), std::log(1e30)), logA(0, 8);
    std::vector<double> J{1e-30, 1e30, 1.0, 1 - 1e-16, 1 + 1e-15}, a2;
    for (int i = 0; i < 20000; ++i) J.push_back(std::exp(logJ(gen)));
    for (const double j : J)
    {
        a2.push_back(std::min(1e24, 3*std::cbrt(j*j)*std::exp(logA(gen))));
    }
    for (const auto m : {TetQuality::Metric::sizeShape, TetQuality::Metric::size,
                         TetQuality::Metric::shape})
    {
        std::vector<double> wide(J.size()), narrow(J.size());
        detail::TetBatch::qualities(J.size(), J.data(), a2.data(), narrow.data(), m, false);
        // the AVX-512, the AVX2 and the default build: the same bits
        test::atEachSimdWidth([&](unsigned bits)
        {
            std::vector<double> w(J.size());
            detail::TetBatch::qualities(J.size(), J.data(), a2.data(), w.data(), m, true);
            EXPECT_EQ(w, narrow) << bits << " bits";
        });
        detail::TetBatch::qualities(J.size(), J.data(), a2.data(), wide.data(), m, true);
        for (std::size_t i = 0; i < J.size(); ++i)
        {
            const double ref = detail::TetMeasures::quality(J[i], a2[i], m);
            EXPECT_NEAR(wide[i], ref, 2e-15*ref) << J[i] << ' ' << a2[i];
        }
    }
}


TEST(TetBatch, WorstBatchPutsEachCellsQualityInItsPlace)
{
    // ranked cells (SIMD), an inverted one and one beyond the lanes' range
    // (J = 1e-35: Worst::quality), each written where asked
    const auto m = TetQuality::Metric::sizeShape;
    std::vector<detail::TetMeasures::Worst> cells(4, detail::TetMeasures::Worst(m));
    cells[0].add(0.5, 2.0);
    cells[0].add(2.0, 4.0);
    cells[1].add(0.9, 3.0);
    cells[1].add(-0.2, 1.0);
    cells[2].add(1e-35, 3e-23);
    cells[3].add(1.2, 3.5);
    std::vector<double> q(4, -7);
    detail::WorstBatch finals(m);
    for (int i = 3; i >= 0; --i) finals.add(cells[i], &q[i]);
    finals.finish();
    for (int i = 0; i < 4; ++i)
    {
        EXPECT_NEAR(q[i], cells[i].quality(), 1e-15*std::abs(cells[i].quality())) << i;
    }
    EXPECT_EQ(q[1], -0.2);
}
