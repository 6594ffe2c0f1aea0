// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
#include "TrialSwaps.hpp"

#include <limits>
#include <utility>

namespace dcprbf
{

TrialSwaps::TrialSwaps(DynamicControlSet& set)
:
    set_(set),
    trial_(set),
    step_(set),
    nKept_(0),
    leaving_(Eigen::RowVector3d::Zero()),
    leavingReach_(0)
{}


bool TrialSwaps::propose
(
    const Eigen::RowVector3d& worstCentre,
    const Values& d,
    int skip
)
{
    // Joining: near the worst cell, among the joinNeighbours nearest
    // candidates, the one of largest error / distance
    const double dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    const Eigen::Index in =
        set_.mostInaccurateNear(worstCentre, d, joinNeighbours, 1e-9*dMax);
    if (in < 0)
    {
        return false;
    }

    // Leaving: the moving control point whose removal costs least (the
    // errors first: the state a trial undone returns to keeps what they
    // took, for the next trial on the same set)
    const std::vector<Eigen::Index> order
    (
        set_.removalOrder(set_.leaveOneOutErrors(d))
    );
    DynamicControlSet::State before(set_.state());
    int skipped = 0;
    for (const Eigen::Index out : order)
    {
        if (skipped++ < skip || !set_.swap(in, out))
        {
            continue;
        }
        // where the interpolant loses a centre: its reach is the distance
        // to the nearest remaining control point (the set is not empty: in
        // has joined)
        const Points& candidates = set_.candidates();
        leaving_ = candidates.row(out);
        leavingReach_ = std::numeric_limits<double>::max();
        for (const Eigen::Index j : set_.indices())
        {
            // the smaller as OpenFOAM's min() takes it (the same bits)
            const double r = (candidates.row(j) - leaving_).norm();
            leavingReach_ = leavingReach_ < r ? leavingReach_ : r;
        }
        if (!step_.open())
        {
            step_.begin(before);
            nKept_ = 0;
        }
        trial_.begin(std::move(before));
        return true;
    }
    return false;
}


void TrialSwaps::keep()
{
    trial_.commit();
    ++nKept_;
}


void TrialSwaps::undo()
{
    trial_.rollBack();
}


int TrialSwaps::end()
{
    const int kept = nKept_;
    nKept_ = 0;
    if (kept == 0 && step_.open())
    {
        step_.commit();
    }
    return kept;
}

} // namespace dcprbf
