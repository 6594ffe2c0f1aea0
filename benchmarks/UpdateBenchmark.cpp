// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// One add + one remove of a control point (IncrementalSaddleSolver) against
// a refactorization of the same set from scratch.
#include "Benchmarks.hpp"
#include "IncrementalSaddleSolver.hpp"
#include "Timing.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cstdio>
#include <random>

namespace dcprbf
{
namespace bench
{

namespace
{
double relDiff(const Values& a, const Values& b)
{
    return (a - b).cwiseAbs().maxCoeff()/b.cwiseAbs().maxCoeff();
}

//- 1/rcond of the saddle matrix [Phi P; P^T 0] (LU estimate): differences
//  between two backward-stable solves scale with it
double conditionEstimate
(
    const RadialKernel& k,
    const LinearPolynomial& frame,
    const Points& c
)
{
    const Eigen::Index n = c.rows(), m = frame.size();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + m, n + m);
    A.topLeftCorner(n, n) = AugmentedKernel(k, frame).radialMatrix(c, c);
    A.topRightCorner(n, m) = frame.basis(c);
    A.bottomLeftCorner(m, n) = frame.basis(c).transpose();
    return 1.0/Eigen::PartialPivLU<Eigen::MatrixXd>(A).rcond();
}
}


void benchmarkUpdates(const Setup& s)
{
    const Eigen::Index n = s.updateSize;
    std::vector<Eigen::Index> used;
    const Points c = subsample(s.surface, n, &used);
    std::vector<char> isUsed(s.surface.rows(), 0);
    for (const Eigen::Index i : used) isUsed[i] = 1;
    std::vector<Eigen::Index> pool;
    for (Eigen::Index i = 0; i < s.surface.rows(); ++i) if (!isUsed[i]) pool.push_back(i);
    const LinearPolynomial frame = LinearPolynomial::boundingBox(true, 3, s.surface);

    std::printf
    (
        "\n## Dynamic update at N = %ld: one add + one remove vs refactorization\n\n"
        "| kernel | refactorization (s) | add + remove, random index (s) |"
        " ratio | add + remove of index 0 (s) | ratio | solve (s) |"
        " max rel. diff vs fresh solve after %d pairs | cond. estimate |\n"
        "|---|---|---|---|---|---|---|---|---|\n",
        long(n), s.updatePairs
    );
    for (const RadialKernel& k : s.kernels)
    {
        IncrementalSaddleSolver solver(k, frame);
        const double tReset = minSeconds(3, [&] { solver.reset(c); });

        // add a random unused surface point, remove a random centre (or the
        // first one, the most expensive deletion)
        std::mt19937 gen(11);
        std::shuffle(pool.begin(), pool.end(), gen);
        std::size_t next = 0;
        auto pair = [&](bool first)
        {
            std::uniform_int_distribution<Eigen::Index> pick(0, solver.size() - 1);
            solver.add(s.surface.row(pool[next++ % pool.size()]));
            solver.remove(first ? 0 : pick(gen));
        };
        const double tPair = seconds([&]
        {
            for (int p = 0; p < s.updatePairs; ++p) pair(false);
        })/s.updatePairs;
        const int worstPairs = std::max(1, s.updatePairs/10);
        const double tWorst = seconds([&]
        {
            for (int p = 0; p < worstPairs; ++p) pair(true);
        })/worstPairs;

        const Values d = s.wing.displacement(solver.centres());
        Values alpha, alphaRef;
        Eigen::MatrixX3d beta, betaRef;
        const double tSolve = minSeconds(5, [&] { solver.solve(d, alpha, beta); });
        IncrementalSaddleSolver fresh(k, frame);
        fresh.reset(solver.centres());
        fresh.solve(d, alphaRef, betaRef);

        std::printf
        (
            "| %s | %.4f | %.5f | %.1f %% | %.5f | %.1f %% | %.5f | %.1e | %.1e |\n",
            k.name().c_str(), tReset, tPair, 100*tPair/tReset, tWorst,
            100*tWorst/tReset, tSolve, relDiff(alpha, alphaRef),
            conditionEstimate(k, frame, solver.centres())
        );
    }
}

} // namespace bench
} // namespace dcprbf
