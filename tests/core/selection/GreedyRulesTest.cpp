// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// GreedySelector: seed, stopping rules (tolerance, minPoints, maxPoints, all
// candidates) and every error path.
#include "GreedySelector.hpp"
#include "NaiveGreedyModel.hpp"
#include "TestPoints.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

using namespace dcprbf;
using test::randomPoints;

namespace
{

GreedySelector make(const GreedyOptions& o, bool poly = true, int dim = 3,
                    const std::string& name = "WendlandC2", double R = 0.5)
{
    return GreedySelector(RadialKernel::fromName(name, R), poly, dim, o);
}

GreedyOptions options(double tol, Eigen::Index minPoints, Eigen::Index maxPoints)
{
    GreedyOptions o;
    o.tolerance = tol;
    o.minPoints = minPoints;
    o.maxPoints = maxPoints;
    return o;
}

void expectMessage(const std::function<void()>& f, const std::string& part)
{
    try
    {
        f();
        ADD_FAILURE() << "no Error, expected one mentioning '" << part << "'";
    }
    catch (const Error& e)
    {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

TEST(GreedyRules, AffineMotionStopsAtTheSeed)
{
    const Points x = randomPoints(300, 3, 71);
    const GreedyResult r = make(options(1e-8, 0, 100)).select(x, test::affineField(x, 3));
    EXPECT_EQ(r.selected.size(), 4u);
    EXPECT_TRUE(r.converged);
    EXPECT_LT(r.historyError.back(), 1e-10);
    // without the polynomial the same motion needs many points
    const GreedyResult n = make(options(1e-3, 0, 100), false).select(x, test::affineField(x, 3));
    EXPECT_GT(n.selected.size(), 10u);
}

TEST(GreedyRules, ZeroDisplacementGivesTheSeedAndZeroCoefficients)
{
    const Points x = randomPoints(100, 3, 80);
    const GreedyResult r = make(options(1e-3, 0, 50)).select(x, Values::Zero(100, 3));
    EXPECT_EQ(r.selected.size(), 4u);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.maxDisplacement, 0.0);
    EXPECT_EQ(r.alpha.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(r.beta.cwiseAbs().maxCoeff(), 0.0);
}

TEST(GreedyRules, MinPointsAndMaxPoints)
{
    const Points x = randomPoints(300, 3, 72);
    const Values d = test::affineField(x, 3);
    EXPECT_EQ(make(options(1e-8, 25, 100)).select(x, d).selected.size(), 25u);
    const Values s = test::smoothField(x);
    const GreedyResult capped = make(options(1e-12, 0, 30)).select(x, s);
    EXPECT_EQ(capped.selected.size(), 30u);
    EXPECT_FALSE(capped.converged);
    // a tolerance out of reach and room for everything: all candidates
    const Points few = randomPoints(40, 3, 73);
    const GreedyResult all = make(options(1e-15, 0, 1000)).select(few, test::smoothField(few));
    EXPECT_EQ(all.selected.size(), 40u);
    EXPECT_EQ(all.historyError.back(), 0.0);
}

TEST(GreedyRules, DoubleEdgedRespectsMaxPoints)
{
    const Points x = randomPoints(300, 3, 74);
    GreedyOptions o = options(1e-12, 0, 11);
    o.doubleEdged = true;
    const GreedyResult r = make(o).select(x, test::smoothField(x));
    EXPECT_EQ(r.selected.size(), 11u);  // 4 + 2 + 2 + 2 + 1
}

TEST(GreedyRules, AutomaticSeedIsLargestDisplacementThenSpread)
{
    const Points x = randomPoints(200, 3, 75);
    Values d = Values::Zero(200, 3);
    d(123, 1) = 2.0;
    const GreedySelector g = make(options(1e-3, 0, 50));
    const std::vector<Eigen::Index> s = g.seed(x, d);
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0], 123);
    // the second is the candidate farthest from the first
    Eigen::Index far = 0;
    (x.rowwise() - x.row(123)).rowwise().squaredNorm().maxCoeff(&far);
    EXPECT_EQ(s[1], far);
    EXPECT_EQ(make(options(1e-3, 0, 50), false).seed(x, d), std::vector<Eigen::Index>{123});
}

TEST(GreedyRules, ExplicitSeedComesFirst)
{
    const Points x = randomPoints(200, 3, 76);
    GreedyOptions o = options(1e-2, 0, 50);
    o.seed = {3, 50, 77, 150, 199};
    const GreedyResult r = make(o).select(x, test::smoothField(x));
    ASSERT_GE(r.selected.size(), 5u);
    EXPECT_EQ(std::vector<Eigen::Index>(r.selected.begin(), r.selected.begin() + 5), o.seed);
    EXPECT_EQ(r.historySize.front(), 5);
}

TEST(GreedyRules, OptionErrors)
{
    expectMessage([] { make(options(0.0, 0, 10)); }, "tolerance");
    expectMessage([] { make(options(-1e-3, 0, 10)); }, "tolerance");
    expectMessage([] { make(options(std::nan(""), 0, 10)); }, "tolerance");
    expectMessage([] { make(options(1e-3, 20, 10)); }, "below minPoints");
    expectMessage([] { make(options(1e-3, 0, 3)); }, "below the seed size");
    expectMessage([] { make(options(1e-3, 0, 0)); }, "maxPoints >= 1");
    expectMessage([] { make(options(1e-3, 0, 10), false, 3, "TPS", 1.0); }, "polynomial");
    EXPECT_THROW(make(options(1e-3, 0, 10), true, 4), Error);
}

TEST(GreedyRules, InputErrors)
{
    const GreedySelector g = make(options(1e-3, 0, 10));
    const Points x = randomPoints(50, 3, 77);
    const Values d = test::smoothField(x);
    expectMessage([&] { g.select(x, d.topRows(49)); }, "49 displacements for 50");
    expectMessage([&] { g.select(x.topRows(3), d.topRows(3)); }, "too few");
    Points dup = x;
    dup.row(30) = dup.row(4);
    expectMessage([&] { g.select(dup, d); }, "duplicate candidate points 4 and 30");
    Values bad = d;
    bad(7, 2) = std::numeric_limits<double>::infinity();
    expectMessage([&] { g.select(x, bad); }, "not finite");
    Points flat = x;
    flat.col(2).setConstant(0.3);
    expectMessage([&] { g.select(flat, d); }, "coplanar");
    expectMessage([&] { selectNaive(g, flat, d); }, "coplanar");
    EXPECT_NO_THROW(make(options(1e-3, 0, 10), false).select(flat, d));

    // 2D: collinear candidates, and z must be 0
    Points line(20, 3);
    for (int i = 0; i < 20; ++i) line.row(i) << 0.05*i, 0.1*i, 0;
    const GreedySelector g2 = make(options(1e-3, 0, 10), true, 2);
    expectMessage([&] { g2.select(line, Values::Ones(20, 3)); }, "collinear");
    expectMessage([&] { g2.select(x, d); }, "z = 0");
}

TEST(GreedyRules, ExplicitSeedErrors)
{
    const Points x = randomPoints(50, 3, 78);
    const Values d = test::smoothField(x);
    GreedyOptions o = options(1e-3, 0, 10);
    o.seed = {1, 2, 2, 3};
    expectMessage([&] { make(o).select(x, d); }, "distinct");
    o.seed = {1, 2, 3, 50};
    expectMessage([&] { make(o).select(x, d); }, "distinct");
    o.seed = {1, 2, 3};
    expectMessage([&] { make(o).select(x, d); }, "too few");
    Points planar = x;
    planar.topRows(4).col(2).setConstant(0.5);
    o.seed = {0, 1, 2, 3};
    expectMessage([&] { make(o).select(planar, d); }, "coplanar");
}

// A point numerically dependent on those selected ends the selection (no
// error: the interpolant cannot fit better with this kernel and radius),
// said in the result; the points selected are a valid set
TEST(GreedyRules, DependentCandidateEndsTheSelection)
{
    // a very wide Gaussian on a tiny cluster: the kernel matrix of more than
    // a few points is singular to round-off; minPoints asks for more
    const Points x = randomPoints(30, 3, 79, 0.1);
    const GreedySelector g = make(options(1e-3, 25, 30), false, 3, "Gaussian", 20.0);
    const GreedyResult r = g.select(x, test::smoothField(x));
    EXPECT_TRUE(r.dependent);
    EXPECT_LT(r.selected.size(), 25u);
    EXPECT_GE(r.selected.size(), 1u);
    ASSERT_TRUE(r.factorization);
    EXPECT_EQ(r.factorization->size(), Eigen::Index(r.selected.size()));
}

} // namespace
