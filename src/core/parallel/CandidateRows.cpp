// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "CandidateRows.hpp"
#include "SerialCollective.hpp"

#include <algorithm>
#include <limits>

namespace dcprbf
{

CandidateRows::CandidateRows
(
    const Collective& comm,
    const Points& x,
    const Values& d
)
:
    comm_(&comm),
    x_(&x),
    d_(&d)
{
    if (d.rows() != x.rows())
    {
        throw Error
        (
            "greedy selection: " + std::to_string(d.rows()) + " displacements"
            " for " + std::to_string(x.rows()) + " candidate points"
        );
    }
    const std::vector<Eigen::Index> counts = comm.allGather(x.rows());
    start_.assign(1, 0);
    for (const Eigen::Index n : counts) start_.push_back(start_.back() + n);
}


CandidateRows::CandidateRows(const Points& x, const Values& d)
:
    CandidateRows(SerialCollective::instance(), x, d)
{}


int CandidateRows::owner(Eigen::Index i) const
{
    // the last rank whose block starts at or before i (empty blocks skipped)
    const auto it = std::upper_bound(start_.begin(), start_.end() - 1, i);
    return int(it - start_.begin()) - 1;
}


CandidateRows::Best CandidateRows::argmax
(
    double value,
    Eigen::Index localIndex
) const
{
    const double none = -std::numeric_limits<double>::infinity();
    const double best = comm_->max(localIndex >= 0 ? value : none);
    if (best == none)
    {
        return {best, -1};
    }
    // the lowest global index holding it: the largest negated index (exact
    // in a double below 2^53)
    const bool mine = localIndex >= 0 && value == best;
    const double negated = comm_->max(mine ? -double(begin() + localIndex) : none);
    return {best, Eigen::Index(-negated)};
}


void CandidateRows::fetch
(
    Eigen::Index i,
    const double* extra,
    Eigen::Index n,
    double* out
) const
{
    const Eigen::Index l = local(i);
    if (l >= 0)
    {
        for (int k = 0; k < 3; ++k)
        {
            out[k] = (*x_)(l, k);
            out[3 + k] = (*d_)(l, k);
        }
        std::copy(extra, extra + n, out + 6);
    }
    comm_->broadcast(out, 6 + n, owner(i));
}

} // namespace dcprbf
