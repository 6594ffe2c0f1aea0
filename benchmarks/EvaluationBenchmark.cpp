// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Evaluation of an interpolant with 1000 control points at the volume
// points: RbfEvaluator (tree / blocked dense, 1 and 2 threads) against the
// naive double loop (one thread).
#include "Benchmarks.hpp"
#include "IncrementalSaddleSolver.hpp"
#include "RbfEvaluator.hpp"
#include "Timing.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <cstdio>

namespace dcprbf
{
namespace bench
{

namespace
{
void setThreads(int n)
{
    #ifdef _OPENMP
    omp_set_num_threads(n);
    #else
    (void)n;
    #endif
}

int maxThreads()
{
    #ifdef _OPENMP
    return omp_get_max_threads();
    #else
    return 1;
    #endif
}

//- Kernel evaluations the tree path performs: pairs closer than R
double pairsWithin(const RbfEvaluator& e, const Points& x)
{
    const PointTree tree(e.centres());
    double count = 0;
    #pragma omp parallel for reduction(+:count) schedule(static)
    for (Eigen::Index i = 0; i < x.rows(); ++i)
    {
        tree.forEachWithin(x.row(i).data(), e.kernel().radius(),
            [&](std::size_t, double) { count += 1; });
    }
    return count;
}
}


void benchmarkEvaluation(const Setup& s)
{
    const Eigen::Index nc = 1000;
    const Points c = subsample(s.surface, nc);
    const Values dc = s.wing.displacement(c);
    const Points x = s.wing.volume(s.volumePoints, 7);
    const LinearPolynomial frame = LinearPolynomial::boundingBox(true, 3, s.surface);
    const int threads = maxThreads();

    std::printf
    (
        "\n## Evaluation: %ld control points at %ld points\n\n"
        "| kernel | method | threads | seconds | kernel evals/s | speed-up vs naive |"
        " max rel. diff vs naive |\n"
        "|---|---|---|---|---|---|---|\n",
        long(nc), long(x.rows())
    );
    for (const RadialKernel& k : s.kernels)
    {
        IncrementalSaddleSolver solver(k, frame);
        solver.reset(c);
        Values alpha;
        Eigen::MatrixX3d beta;
        solver.solve(dc, alpha, beta);
        RbfEvaluator e(k, frame);
        e.assign(c, alpha, beta);

        Values ref(x.rows(), 3), out(x.rows(), 3);
        const double tNaive = seconds([&]
        {
            e.evaluateBruteForce(x.data(), x.rows(), ref.data());
        });
        const double dense = double(nc)*x.rows();
        std::printf
        (
            "| %s | naive double loop | 1 | %.2f | %.3g | 1.0 | - |\n",
            k.name().c_str(), tNaive, dense/tNaive
        );

        std::vector<RbfEvaluator::Method> methods{RbfEvaluator::Method::Dense};
        if (k.compact()) methods.push_back(RbfEvaluator::Method::Tree);
        const double treePairs = k.compact() ? pairsWithin(e, x) : dense;
        for (const auto m : methods)
        {
            e.setMethod(m);
            for (int t = 1; t <= threads; t *= 2)
            {
                setThreads(t);
                const double sec = minSeconds(2, [&]
                {
                    e.evaluate(x.data(), x.rows(), out.data());
                });
                const double evals = m == RbfEvaluator::Method::Tree ? treePairs : dense;
                std::printf
                (
                    "| %s | %s | %d | %.3f | %.3g | %.1f | %.1e |\n",
                    k.name().c_str(),
                    m == RbfEvaluator::Method::Tree ? "kd-tree" : "blocked dense",
                    t, sec, evals/sec, tNaive/sec,
                    (out - ref).cwiseAbs().maxCoeff()/ref.cwiseAbs().maxCoeff()
                );
            }
            setThreads(threads);
        }
        e.setMethod(RbfEvaluator::Method::Auto);
        std::printf
        (
            "| %s | (Auto picks: %s; %.0f%% of the pairs within R) | | | | | |\n",
            k.name().c_str(),
            e.usesTree(x.data(), x.rows()) ? "kd-tree" : "blocked dense",
            100*treePairs/dense
        );
    }
    const double inputMB = (x.size() + 2.0*x.rows()*3)*sizeof(double)/1048576.0;
    std::printf
    (
        "\nPeak RSS after the evaluation section: %.0f MB for %.2g points"
        " (points, result and naive reference arrays: %.0f MB of it).\n",
        peakRssMB(), double(x.rows()), inputMB
    );
}

} // namespace bench
} // namespace dcprbf
