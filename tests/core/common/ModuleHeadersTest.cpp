// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// The core's module headers (one per folder of src/core) are self-contained
// and together declare the core's public classes.
#include "Common.hpp"
#include "Kernels.hpp"
#include "LinearAlgebra.hpp"
#include "Selection.hpp"
#include "Swaps.hpp"
#include "Evaluation.hpp"
#include "SpatialSearch.hpp"
#include "Quality.hpp"
#include "RigidMotion.hpp"
#include "Parallel.hpp"

#include <gtest/gtest.h>

#include <type_traits>

using namespace dcprbf;

TEST(ModuleHeaders, DeclareThePublicClasses)
{
    // one class of each module, named through its module header alone
    EXPECT_TRUE(std::is_class<RadialKernel>::value);
    EXPECT_TRUE(std::is_class<SaddleFactorization>::value);
    EXPECT_TRUE(std::is_class<GreedySelector>::value);
    EXPECT_TRUE(std::is_class<TrialSwaps>::value);
    EXPECT_TRUE(std::is_class<StoredEvaluation>::value);
    EXPECT_TRUE(std::is_class<PointTree>::value);
    EXPECT_TRUE(std::is_class<CellQualityScan>::value);
    EXPECT_TRUE(std::is_class<RigidMotion>::value);
    EXPECT_TRUE(std::is_class<CandidateRows>::value);
    const unsigned bits = SimdWidth::bits();
    EXPECT_TRUE(bits == 0 || bits == 256 || bits == 512) << bits;
}
