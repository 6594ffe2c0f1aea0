// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Unit tests of the greedy selection on candidates divided over ranks
// (threads standing for ranks, ThreadCollective): the same points, errors,
// coefficients and factorization as the serial selection, bit for bit,
// whatever the division (empty ranks, one rank holding all); errors thrown
// on every rank alike.
#include "GreedySelector.hpp"
#include "TestPoints.hpp"
#include "ThreadCollective.hpp"

#include <gtest/gtest.h>

#include <mutex>
#include <tuple>

using namespace dcprbf;
using test::randomPoints;

namespace
{

//- The serial result's comparable parts
struct Outcome
{
    std::vector<Eigen::Index> selected;
    std::vector<double> historyError;
    Values alpha;
    Eigen::MatrixX3d beta;
    Points centres;
    Points factorized;
    bool converged;
    bool dependent;
};

Outcome outcome(const GreedyResult& r)
{
    return
    {
        r.selected, r.historyError, r.alpha, r.beta, r.centres,
        r.factorization->centres(), r.converged, r.dependent
    };
}

void expectSame(const Outcome& a, const Outcome& b, const std::string& where)
{
    EXPECT_EQ(a.selected, b.selected) << where;
    EXPECT_EQ(a.historyError, b.historyError) << where;
    EXPECT_EQ(a.alpha, b.alpha) << where;
    EXPECT_EQ(a.beta, b.beta) << where;
    EXPECT_EQ(a.centres, b.centres) << where;
    EXPECT_EQ(a.factorized, b.factorized) << where;
    EXPECT_EQ(a.converged, b.converged) << where;
    EXPECT_EQ(a.dependent, b.dependent) << where;
}

//- Rows [start[r], start[r + 1]) to rank r
std::vector<Eigen::Index> blocks(Eigen::Index n, const std::vector<double>& shares)
{
    std::vector<Eigen::Index> start(1, 0);
    double sum = 0;
    for (const double s : shares) sum += s;
    double acc = 0;
    for (const double s : shares)
    {
        acc += s;
        start.push_back(Eigen::Index(std::llround(n*acc/sum)));
    }
    return start;
}

//- The selection on P threads, rows divided by shares; every rank's
//  outcome (they must agree)
std::vector<Outcome> divided
(
    const GreedySelector& g,
    const Points& x,
    const Values& d,
    const std::vector<double>& shares
)
{
    const int P = int(shares.size());
    const std::vector<Eigen::Index> start = blocks(x.rows(), shares);
    std::vector<Outcome> out(P);
    test::runRanks(P, [&](const Collective& comm)
    {
        const int r = comm.rank();
        const Points xr = x.middleRows(start[r], start[r + 1] - start[r]);
        const Values dr = d.middleRows(start[r], start[r + 1] - start[r]);
        out[r] = outcome(g.select(CandidateRows(comm, xr, dr)));
    });
    return out;
}

// kernel x polynomial x dimension x double-edged
using Case = std::tuple<std::string, bool, int, bool>;

class GreedyDivided : public ::testing::TestWithParam<Case>
{
protected:
    GreedySelector make(double tol, Eigen::Index maxPoints) const
    {
        GreedyOptions o;
        o.tolerance = tol;
        o.maxPoints = maxPoints;
        o.doubleEdged = std::get<3>(GetParam());
        const std::string name = std::get<0>(GetParam());
        return GreedySelector
        (
            RadialKernel::fromName(name, test::testRadius(name, 0.5)),
            std::get<1>(GetParam()), std::get<2>(GetParam()), o
        );
    }

    int dim() const { return std::get<2>(GetParam()); }
};

} // End anonymous namespace


TEST_P(GreedyDivided, SameAsSerialWhateverTheDivision)
{
    const Points x = randomPoints(600, dim(), 29);
    Values d = test::smoothField(x);
    if (dim() == 2) d.col(2).setZero();
    const GreedySelector g = make(1e-9, 60);
    const Outcome serial = outcome(g.select(x, d));
    ASSERT_EQ(serial.selected.size(), 60u);

    const std::vector<std::vector<double>> divisions =
    {
        {1, 1}, {1, 2, 3}, {1, 0, 1, 1}, {0, 1}, {1, 0}, {3, 1, 1, 1, 2}
    };
    for (const std::vector<double>& shares : divisions)
    {
        const std::vector<Outcome> ranks = divided(g, x, d, shares);
        for (std::size_t r = 0; r < ranks.size(); ++r)
        {
            expectSame(ranks[r], serial, std::to_string(shares.size())
                + " ranks, rank " + std::to_string(r));
        }
    }
}


INSTANTIATE_TEST_SUITE_P
(
    KernelsPolyDimEdges,
    GreedyDivided,
    ::testing::Values
    (
        Case{"WendlandC2", true, 3, false},
        Case{"WendlandC2", true, 2, true},
        Case{"WendlandC2", false, 3, true},
        Case{"TPS", true, 2, false}
    ),
    [](const ::testing::TestParamInfo<Case>& p)
    {
        return std::get<0>(p.param)
            + (std::get<1>(p.param) ? "_poly" : "_noPoly")
            + "_" + std::to_string(std::get<2>(p.param)) + "D"
            + (std::get<3>(p.param) ? "_double" : "_single");
    }
);


TEST(GreedyDividedRules, TiesGoToTheLowestGlobalIndex)
{
    // a regular grid with a symmetric field: many equal errors; the choice
    // among them must not depend on which rank holds which
    Points x(400, 3);
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) x.row(20*i + j) << i/19.0, j/19.0, 0;
    Values d(400, 3);
    for (int k = 0; k < 400; ++k)
    {
        const double u = x(k, 0) - 0.5, v = x(k, 1) - 0.5;
        d.row(k) << u*u + v*v, 0, 0;
    }
    GreedyOptions o;
    o.tolerance = 1e-12;
    o.maxPoints = 40;
    const GreedySelector g(RadialKernel::fromName("WendlandC2", 0.6), true, 2, o);
    const Outcome serial = outcome(g.select(x, d));
    for (const std::vector<double>& shares :
         std::vector<std::vector<double>>{{1, 1}, {1, 1, 1}, {2, 1, 1, 3}})
    {
        const std::vector<Outcome> ranks = divided(g, x, d, shares);
        expectSame(ranks.back(), serial, std::to_string(shares.size()) + " ranks");
    }
}


TEST(GreedyDividedRules, ErrorsOnEveryRankAlike)
{
    const Points x = randomPoints(200, 3, 5);
    Values d = test::smoothField(x);
    d(150, 1) = std::numeric_limits<double>::quiet_NaN();   // on the last rank
    GreedyOptions o;
    o.maxPoints = 20;
    const GreedySelector g(RadialKernel::fromName("WendlandC2", 0.6), true, 3, o);
    std::mutex m;
    std::vector<std::string> messages;
    test::runRanks(3, [&](const Collective& comm)
    {
        const Eigen::Index b = 70*comm.rank(), n = comm.rank() < 2 ? 70 : 60;
        const Points xr = x.middleRows(b, n);
        const Values dr = d.middleRows(b, n);
        try
        {
            g.select(CandidateRows(comm, xr, dr));
        }
        catch (const Error& e)
        {
            std::lock_guard<std::mutex> lock(m);
            messages.push_back(e.what());
        }
    });
    ASSERT_EQ(messages.size(), 3u);   // no rank left waiting, every one threw
    int named = 0;
    for (const std::string& s : messages) named += s.find("not finite") != std::string::npos;
    EXPECT_EQ(named, 1);
}


TEST(GreedyDividedRules, SeedIndicesAreGlobal)
{
    const Points x = randomPoints(300, 3, 8);
    const Values d = test::smoothField(x);
    GreedyOptions o;
    o.maxPoints = 25;
    o.seed = {250, 3, 120, 299};
    const GreedySelector g(RadialKernel::fromName("WendlandC2", 0.7), true, 3, o);
    const Outcome serial = outcome(g.select(x, d));
    EXPECT_EQ(std::vector<Eigen::Index>(serial.selected.begin(), serial.selected.begin() + 4), o.seed);
    expectSame(divided(g, x, d, {1, 1, 1})[1], serial, "3 ranks");
}
