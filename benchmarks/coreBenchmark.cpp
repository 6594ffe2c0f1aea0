// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// coreBenchmark: timings of the numerical core on a wing-like surface.
//
//     coreBenchmark [--quick] [eval] [update] [greedy] [stored]
//
// No section named: all four, in the order eval, update, greedy, stored (eval first
// so that the peak memory it reports is its own). --quick: small sizes, a
// smoke test of the benchmark itself.
#include "Benchmarks.hpp"
#include "Timing.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <cstdio>
#include <cstring>
#include <set>
#include <string>

using namespace dcprbf;
using namespace dcprbf::bench;

int main(int argc, char** argv)
{
    bool quick = false;
    std::set<std::string> sections;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strcmp(argv[i], "--quick") == 0) quick = true;
        else sections.insert(argv[i]);
    }
    if (sections.empty()) sections = {"eval", "update", "greedy", "stored"};

    Setup s;
    s.surface = quick ? s.wing.surface(30, 67) : s.wing.surface(100, 201);
    s.displacement = s.wing.displacement(s.surface);
    s.volumePoints = quick ? 100000 : 1000000;
    s.greedySizes = quick ? std::vector<Eigen::Index>{50, 100}
                          : std::vector<Eigen::Index>{100, 300, 1000};
    s.updateSize = quick ? 300 : 1000;
    s.updatePairs = quick ? 20 : 200;
    s.kernels =
    {
        RadialKernel::fromName("WendlandC2", 1.5),
        RadialKernel::fromName("TPS", 1.0)
    };

    int threads = 1;
    #ifdef _OPENMP
    threads = omp_get_max_threads();
    #endif
    std::printf
    (
        "# dcpRBF core benchmark\n\n"
        "Wing: NACA 0012, root chord %.1f, taper %.1f, semi-span %.1f,"
        " sweep %.0f deg; %ld surface points; %d OpenMP threads%s.\n"
        "Kernels: WendlandC2 (support radius 1.5 root chords), TPS (length"
        " 1.0), with the linear polynomial. Load average at start: %.2f.\n",
        s.wing.rootChord, s.wing.taper, s.wing.semiSpan, s.wing.sweepDeg,
        long(s.surface.rows()), threads, quick ? " (--quick sizes)" : "",
        loadAverage()
    );

    if (sections.count("eval")) benchmarkEvaluation(s);
    if (sections.count("update")) benchmarkUpdates(s);
    if (sections.count("greedy")) benchmarkGreedy(s);
    if (sections.count("stored")) benchmarkStored(s);
    std::printf
    (
        "\nPeak RSS of the whole run: %.0f MB. Load average at the end: %.2f.\n",
        peakRssMB(), loadAverage()
    );
    return 0;
}


Points dcprbf::bench::subsample
(
    const Points& x,
    Eigen::Index n,
    std::vector<Eigen::Index>* indices
)
{
    Points p(n, 3);
    for (Eigen::Index j = 0; j < n; ++j)
    {
        const Eigen::Index i = (j*x.rows())/n;
        p.row(j) = x.row(i);
        if (indices) indices->push_back(i);
    }
    return p;
}
