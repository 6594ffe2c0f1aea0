// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// The stored matrix of a control set (StoredEvaluation): what making it
// costs (built, merged from the stored one, patched) against one product,
// and a product at a few listed rows (a trial's window) against every row.
#include "Benchmarks.hpp"
#include "StoredEvaluation.hpp"
#include "Timing.hpp"

#include <algorithm>
#include <cstdio>
#include <random>

namespace dcprbf
{
namespace bench
{

namespace
{

//- c with the centres at positions from, from + 1, ... (count of them)
//  replaced by new points (next: the surface point the next one is off)
Points swapped(const Points& c, const Points& surface, Eigen::Index from, int count, Eigen::Index& next)
{
    Points out = c;
    for (int k = 0; k < count; ++k)
    {
        out.row((from + k) % c.rows()) =
            surface.row(next % surface.rows()).array() + 1e-3*double(next + 1);
        next += 7;
    }
    return out;
}

} // namespace


void benchmarkStored(const Setup& s)
{
    const Eigen::Index nPoints = Eigen::Index(s.volumePoints/16);
    const Eigen::Index nCentres = 289, nRows = 5000;
    const double R = 0.9;
    const RadialKernel k = RadialKernel::fromName("WendlandC2", R);
    const LinearPolynomial frame = LinearPolynomial::boundingBox(true, 3, s.surface);
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(0, 1);
    const Eigen::RowVector3d lo = s.surface.colwise().minCoeff().array() - 0.5;
    const Eigen::RowVector3d hi = s.surface.colwise().maxCoeff().array() + 0.5;
    Points x(nPoints, 3);
    for (Eigen::Index i = 0; i < nPoints; ++i)
    {
        for (int q = 0; q < 3; ++q) x(i, q) = lo(q) + (hi(q) - lo(q))*u(gen);
    }
    const Points base = subsample(s.surface, nCentres);
    const std::size_t budget = std::size_t(4) << 30;
    Eigen::Index next = 3;

    // made: built from a tree of the centres; merged (a set 12 centres
    // away, past a patch), the first into a slot never filled, the others
    // into storage of earlier matrices; patched (4 new centres)
    double build = 0;
    std::size_t bytes = 0;
    StoredEvaluation stored(k, frame, x);
    build = seconds([&] { stored.prepare(base, budget); });
    bytes = stored.bytes();
    Points c = base;
    std::vector<double> merges;
    for (int m = 0; m < 6; ++m)
    {
        c = swapped(c, s.surface, 12*m, 12, next);
        merges.push_back(seconds([&] { stored.prepare(c, budget); }));
    }
    const Points patched = swapped(c, s.surface, 100, 4, next);
    const double patch = seconds([&] { stored.prepare(patched, budget); });

    // products: every row; 5000 listed rows (ascending, random); the same
    // rows for a set 3 centres away (a trial: its new columns at those rows)
    const Values alpha = Values::Random(nCentres, 3);
    const Eigen::MatrixX3d beta = Eigen::MatrixX3d::Random(frame.size(), 3);
    Values out;
    const double all = minSeconds(5, [&] { stored.evaluate(alpha, beta, out); });
    std::vector<int> rows;
    for (Eigen::Index r = 0; r < nRows; ++r) rows.push_back(int(gen() % std::uint32_t(nPoints)));
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    StoredEvaluation::Targets targets;
    for (Eigen::Index i = 0; i <= nPoints; ++i) targets.start.push_back(std::size_t(i));
    for (Eigen::Index i = 0; i < nPoints; ++i) targets.point.push_back(int(i));
    std::vector<double> field(3*std::size_t(nPoints));
    const double listed = minSeconds(5, [&]
    {
        stored.evaluateInto(alpha, beta, targets, 3, field.data(), &rows);
    });
    // cold, as in a run (the mesh's own work in between): after a pass
    // over 256 MB
    std::vector<double> flush(std::size_t(32) << 20, 1.0);
    double listedCold = 1e300;
    for (int r = 0; r < 5; ++r)
    {
        for (double& f : flush) f += 1.0;
        keepWrites(flush.data());
        listedCold = std::min(listedCold, seconds([&]
        {
            stored.evaluateInto(alpha, beta, targets, 3, field.data(), &rows);
        }));
    }
    const Points trial = swapped(patched, s.surface, 200, 3, next);
    const double rowsFor = minSeconds(5, [&]
    {
        stored.evaluateRowsFor(trial, budget, alpha, beta, targets, 3, field.data(), rows);
    });

    std::printf
    (
        "\n## Stored matrix: %ld points, %ld centres (WendlandC2, R = %.1f)\n\n"
        "%.1f entries a row, %.0f MB. Made once each, in this order (every"
        " set 12 centres from the one before: past a patch); products the"
        " best of 5.\n\n"
        "| operation | ms | against one product of every row |\n|---|---|---|\n",
        long(nPoints), long(nCentres), R,
        // (an entry: its value and a 16-bit column)
        double(bytes - (nPoints + 1)*sizeof(std::size_t))/10.0/double(nPoints),
        double(bytes)/1048576.0
    );
    const auto row = [&](const std::string& what, double t)
    {
        std::printf("| %s | %.2f | %.2fx |\n", what.c_str(), 1e3*t, t/all);
    };
    row("build (tree of the centres, two passes)", build);
    row("merge into a slot never filled", merges[0]);
    row("merge into an earlier matrix's storage (the second)", merges[1]);
    row("merge into an earlier matrix's storage, best of the next four",
        *std::min_element(merges.begin() + 2, merges.end()));
    row("patch of 4 new centres", patch);
    row("product, every row", all);
    row(fmt("product at %zu listed rows", rows.size()), listed);
    row(fmt("the same, cold (after a pass over 256 MB)"), listedCold);
    row(fmt("a set 3 centres away at those rows (evaluateRowsFor)"), rowsFor);
    std::printf("\nMerges made: %d of %d sets.\n", stored.merges(), int(merges.size()));
}

} // namespace bench
} // namespace dcprbf
