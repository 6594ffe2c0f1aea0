// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the default thread count: never more threads than cores.
#include "ThreadCount.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace dcprbf;

TEST(ThreadCount, SerialUsesEveryAvailableCore)
{
    EXPECT_EQ(threadsPerRank(2, 1), 2);
    EXPECT_EQ(threadsPerRank(16, 1), 16);
}

TEST(ThreadCount, RanksShareTheCoresWithoutOversubscribing)
{
    EXPECT_EQ(threadsPerRank(2, 2), 1);
    EXPECT_EQ(threadsPerRank(16, 4), 4);
    EXPECT_EQ(threadsPerRank(16, 3), 5);
    EXPECT_EQ(threadsPerRank(1, 1), 1);      // a rank bound to one core
    EXPECT_EQ(threadsPerRank(2, 8), 1);      // more ranks than cores
    EXPECT_EQ(threadsPerRank(0, 0), 1);      // unknown: one thread
    for (int cores = 1; cores <= 64; ++cores)
    {
        for (int ranks = 1; ranks <= 70; ++ranks)
        {
            const int t = threadsPerRank(cores, ranks);
            EXPECT_GE(t, 1);
            EXPECT_LE(t*ranks, std::max(cores, ranks)) << cores << ' ' << ranks;
            EXPECT_GT((t + 1)*ranks, cores) << cores << ' ' << ranks;   // and uses them
        }
    }
}
