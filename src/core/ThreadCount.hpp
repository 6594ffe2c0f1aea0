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

} // namespace dcprbf
