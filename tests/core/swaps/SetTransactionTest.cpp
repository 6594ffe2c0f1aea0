// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of SetTransaction: a rollback puts the set back bit for bit
// (indices, ages, the same coefficients), a commit keeps the changes, and
// one transaction at a time.
#include "SetTransaction.hpp"
#include "SwapsTestSet.hpp"

#include <vector>

using namespace dcprbf;

namespace
{

using SetTransactionFixture = test::SwapsTestSet;

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
