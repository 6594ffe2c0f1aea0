// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "ThreadCount.hpp"

#include <algorithm>

namespace dcprbf
{

int threadsPerRank(const int coresAvailable, const int ranksOnNode)
{
    return std::max(1, std::max(1, coresAvailable)/std::max(1, ranksOnNode));
}


int threadsForSize(const int threads, const long nPoints, const long perThread)
{
    const long bySize = perThread > 0 ? std::max(1L, nPoints/perThread) : long(threads);
    return int(std::max(1L, std::min(long(std::max(1, threads)), bySize)));
}

} // namespace dcprbf
