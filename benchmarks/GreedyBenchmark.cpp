// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Greedy selection of N control points among the surface points:
// incremental (GreedySelector::select) against the naive re-solve per added
// point (selectNaive, tests/core/reference), both measured to the end.
#include "Benchmarks.hpp"
#include "GreedySelector.hpp"
#include "NaiveGreedyModel.hpp"
#include "Timing.hpp"

#include <cstdio>
#include <memory>

namespace dcprbf
{
namespace bench
{

void benchmarkGreedy(const Setup& s)
{
    std::printf
    (
        "\n## Greedy selection from Nb = %ld candidates: incremental vs naive\n\n"
        "| kernel | N | incremental (s) | naive (s) | speed-up | same picks |"
        " max rel. diff of alpha | final rel. error |\n"
        "|---|---|---|---|---|---|---|---|\n",
        long(s.surface.rows())
    );
    for (const RadialKernel& k : s.kernels)
    {
        for (const Eigen::Index n : s.greedySizes)
        {
            GreedyOptions o;
            o.tolerance = 1e-12;  // out of reach: exactly n points
            o.maxPoints = n;
            const GreedySelector g(k, true, 3, o);
            std::unique_ptr<GreedyResult> a, b;
            const double tInc = seconds([&]
            {
                a.reset(new GreedyResult(g.select(s.surface, s.displacement)));
            });
            const double tNaive = seconds([&]
            {
                b.reset(new GreedyResult(selectNaive(g, s.surface, s.displacement)));
            });
            const GreedyResult& inc = *a;
            const GreedyResult& ref = *b;
            std::printf
            (
                "| %s | %ld | %.2f | %.2f | %.1f | %s | %.1e | %.2e |\n",
                k.name().c_str(), long(n), tInc, tNaive, tNaive/tInc,
                inc.selected == ref.selected ? "yes" : "no",
                (inc.alpha - ref.alpha).cwiseAbs().maxCoeff()
                    /ref.alpha.cwiseAbs().maxCoeff(),
                inc.historyError.back()
            );
            std::fflush(stdout);
        }
    }
}

} // namespace bench
} // namespace dcprbf
