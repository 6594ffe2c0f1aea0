// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// The sections of coreBenchmark. Each prints a markdown table to stdout;
// every ratio in it compares two timings taken in the same run.
#pragma once

#include "RadialKernel.hpp"
#include "WingSurface.hpp"

#include <vector>

namespace dcprbf
{
namespace bench
{

struct Setup
{
    Wing wing;
    Points surface;              // the candidate boundary points
    Values displacement;         // their displacements
    std::size_t volumePoints;    // evaluation points
    std::vector<Eigen::Index> greedySizes;
    Eigen::Index updateSize;     // control points of the update benchmark
    int updatePairs;             // add+remove pairs timed
    std::vector<RadialKernel> kernels;
};

//- Evaluation of 1000 control points at volumePoints points
void benchmarkEvaluation(const Setup& s);

//- One add + remove against a refactorization
void benchmarkUpdates(const Setup& s);

//- Greedy selection: incremental against naive re-solving
void benchmarkGreedy(const Setup& s);

//- The stored matrix of a control set: made (built, merged, patched)
//  against a product; a product at listed rows against every row
void benchmarkStored(const Setup& s);

//- Every Nb/n-th surface point: n well-spread control points
Points subsample(const Points& x, Eigen::Index n, std::vector<Eigen::Index>* indices = nullptr);

} // namespace bench
} // namespace dcprbf
