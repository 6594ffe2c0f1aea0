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

TEST(ThreadCount, SmallMeshesUseOneThread)
{
    // short parallel loops stall when other processes share the cores
    EXPECT_EQ(threadsForSize(2, 26254), 1);
    EXPECT_EQ(threadsForSize(16, pointsPerThread - 1), 1);
    EXPECT_EQ(threadsForSize(16, 2*pointsPerThread - 1), 1);
    EXPECT_EQ(threadsForSize(16, 2*pointsPerThread), 2);
    EXPECT_EQ(threadsForSize(2, 2351960), 2);      // the fine wing: every core
    EXPECT_EQ(threadsForSize(16, 2351960), 9);
    EXPECT_EQ(threadsForSize(1, 10000000), 1);     // never beyond the cores given
    EXPECT_EQ(threadsForSize(0, 0), 1);
    EXPECT_EQ(threadsForSize(16, 1000, 0), 16);    // no limit by size
    EXPECT_EQ(threadsForSize(16, 1000, 100), 10);
    for (int threads = 1; threads <= 32; ++threads)
    {
        for (long n = 0; n < 40*pointsPerThread; n += pointsPerThread/3)
        {
            const int t = threadsForSize(threads, n);
            EXPECT_GE(t, 1);
            EXPECT_LE(t, threads);
            EXPECT_LE(long(t - 1)*pointsPerThread, n) << threads << ' ' << n;
        }
    }
}
