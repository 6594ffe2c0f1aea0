// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of SwapBlend, the phasing in of kept swaps: weights 1/K, 2/K,
// ..., the new set alone at the K-th step; take/resume; stop; refresh and
// restart = a state factorized afresh.
#include "SwapBlend.hpp"
#include "SwapsTestSet.hpp"

#include <vector>

using namespace dcprbf;

namespace
{

using SwapBlendFixture = test::SwapsTestSet;

TEST_F(SwapBlendFixture, WeightsGoFromOneKthToOneOverKSteps)
{
    for (const int K : {2, 4, 5})
    {
        SwapBlend b(K);
        EXPECT_FALSE(b.active());
        b.start(set.state());
        std::vector<double> w;
        int steps = 1;
        while (b.active())
        {
            w.push_back(b.weight());
            b.advance();
            ++steps;
        }
        // the K-th step is the new set's alone (weight 1)
        EXPECT_EQ(steps, K) << "K " << K;
        ASSERT_EQ(int(w.size()), K - 1) << "K " << K;
        for (int s = 0; s < K - 1; ++s)
        {
            EXPECT_EQ(w[s], double(s + 1)/K) << "K " << K << " step " << s + 1;
        }
        b.advance();
        EXPECT_FALSE(b.active()) << "advance() without a blend: none";
    }
}

TEST_F(SwapBlendFixture, FromIsTheSetItStartedWith)
{
    SwapBlend b(4);
    const DynamicControlSet::State before = set.state();
    b.start(before);
    ASSERT_TRUE(set.swap(1, set.indices()[3]));
    EXPECT_EQ(b.from().indices, before.indices);
    EXPECT_NE(b.from().indices, set.indices());
    EXPECT_EQ(b.step(), 1);
    b.stop();
    EXPECT_FALSE(b.active());
}

TEST_F(SwapBlendFixture, TakeEndsItAndResumePutsItBack)
{
    SwapBlend b(4);
    b.start(set.state());
    b.advance();
    SwapBlend::Held h = b.take();
    EXPECT_FALSE(b.active());
    ASSERT_TRUE(h.from);
    EXPECT_EQ(h.step, 2);
    EXPECT_EQ(h.from->indices, set.indices());
    b.resume(std::move(h));
    ASSERT_TRUE(b.active());
    EXPECT_EQ(b.step(), 2);
    EXPECT_EQ(b.weight(), 0.5);
    EXPECT_EQ(b.from().indices, set.indices());
    // nothing to take: nothing put back
    SwapBlend none(4);
    SwapBlend::Held e = none.take();
    EXPECT_FALSE(e.from);
    none.resume(std::move(e));
    EXPECT_FALSE(none.active());
}

TEST_F(SwapBlendFixture, RefreshAndRestartGiveTheFreshState)
{
    // the phased-out set after updates (a swap and back): refresh() makes it
    // as a restart does, the same interpolant bit for bit
    ASSERT_TRUE(set.swap(2, set.indices()[5]));
    SwapBlend b(4);
    b.start(set.state());
    const DynamicControlSet::State fresh = set.freshState(set.indices(), set.ages());
    const auto c3 = coefficients(fresh);
    ASSERT_FALSE(coefficients(b.from()).first == c3.first)
        << "the updated set differs from a fresh one at round-off";
    b.refresh(set);
    SwapBlend r(4);
    r.restart(1, set.freshState(b.from().indices, b.from().ages));
    ASSERT_TRUE(r.active());
    EXPECT_EQ(r.step(), 1);
    EXPECT_EQ(r.from().indices, b.from().indices);
    EXPECT_EQ(r.from().ages, b.from().ages);
    const auto c1 = coefficients(b.from());
    const auto c2 = coefficients(r.from());
    EXPECT_TRUE(c1.first == c3.first && c1.second == c3.second) << "refresh() = a fresh factorization";
    EXPECT_TRUE(c2.first == c3.first && c2.second == c3.second) << "restart() = a fresh factorization";
    // without a blend refresh() does nothing
    SwapBlend none(4);
    none.refresh(set);
    EXPECT_FALSE(none.active());
}

} // namespace
