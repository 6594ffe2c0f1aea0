// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of SetTransaction: a rollback puts the set back bit for bit
// (indices, ages, the same coefficients), a commit keeps the changes, and
// one transaction at a time.
#include "SetTransaction.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace dcprbf;
using test::randomPoints;
using test::smoothField;

namespace
{

struct SetTransactionFixture : ::testing::Test
{
    Points cand = randomPoints(150, 3, 17);
    Values v = smoothField(cand);
    DynamicControlSet set
    {
        cand, std::vector<char>(cand.rows(), 1),
        RadialKernel::fromName("WendlandC2", 0.6), true, 3, DynamicControlSet::Options()
    };

    void SetUp() override
    {
        std::vector<Eigen::Index> idx;
        for (Eigen::Index i = 0; i < cand.rows(); i += 3) idx.push_back(i);
        set.reset(idx);
        set.solve(v);
    }
};

TEST_F(SetTransactionFixture, RollBackRestoresTheSetBitForBit)
{
    const std::vector<Eigen::Index> idx = set.indices();
    const std::vector<int> ages = set.ages();
    const Values before = set.evaluator().evaluate(cand);
    SetTransaction t(set);
    EXPECT_FALSE(t.open());
    t.begin(set.state());
    ASSERT_TRUE(t.open());
    ASSERT_TRUE(set.swap(1, idx[4]));
    ASSERT_TRUE(set.swap(2, idx[7]));
    set.nextStep();
    EXPECT_EQ(t.before().indices, idx);
    t.rollBack();
    EXPECT_FALSE(t.open());
    EXPECT_EQ(set.indices(), idx);
    EXPECT_EQ(set.ages(), ages);
    EXPECT_FALSE(set.contains(1));
    EXPECT_TRUE(set.contains(idx[4]));
    set.solve(v);
    EXPECT_TRUE(set.evaluator().evaluate(cand) == before);
}

TEST_F(SetTransactionFixture, CommitKeepsTheChanges)
{
    const std::vector<Eigen::Index> idx = set.indices();
    SetTransaction t(set);
    t.begin(set.state());
    ASSERT_TRUE(set.swap(1, idx[4]));
    const std::vector<Eigen::Index> swapped = set.indices();
    t.commit();
    EXPECT_FALSE(t.open());
    EXPECT_EQ(set.indices(), swapped);
    EXPECT_TRUE(set.contains(1));
}

TEST_F(SetTransactionFixture, OneAtATime)
{
    SetTransaction t(set);
    EXPECT_THROW(t.before(), Error);
    EXPECT_THROW(t.commit(), Error);
    EXPECT_THROW(t.rollBack(), Error);
    t.begin(set.state());
    EXPECT_THROW(t.begin(set.state()), Error);
    t.commit();
    t.begin(set.state());
    EXPECT_TRUE(t.open());
}

} // namespace
