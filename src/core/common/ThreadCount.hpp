// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// dcpRBF numerical core: how many threads a process may use.
#pragma once

namespace dcprbf
{

//- Threads per process when the cores available to it (its CPU affinity)
//  are shared by ranksOnNode processes on the node: the cores divided
//  among the ranks, at least 1, so that ranks x threads never exceeds the
//  cores (unless there are more ranks than cores: then 1 each)
int threadsPerRank(int coresAvailable, int ranksOnNode);

//- Mesh points per thread by default: a process with fewer points uses one
//  thread. A step on a smaller mesh is a series of short parallel loops
//  (well under a millisecond each), and when other processes share the
//  cores every one of them waits for a thread the scheduler has put aside,
//  several times longer than the loop itself
constexpr long pointsPerThread = 250000;

//- The threads for a process of nPoints mesh points that may use up to
//  threads: one per perThread points, at least 1, at most threads
//  (perThread 0: threads)
int threadsForSize(int threads, long nPoints, long perThread = pointsPerThread);

} // namespace dcprbf
