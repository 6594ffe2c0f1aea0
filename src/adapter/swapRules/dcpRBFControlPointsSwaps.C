/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFControlPoints, continued: the swaps of swapRule nearest and the
    trial swaps of swapRule errorGuided (propose, keep, undo), the start
    and end of their blend.
\*---------------------------------------------------------------------------*/

#include "dcpRBFControlPoints.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFControlPoints::swapsBeforeSolve() const
{
    const dcpRBFSelectionSettings& s = settings_.selection();
    return
        s.selection == dcpRBFSelectionSettings::mode::dynamic
     && s.swapRule == dcpRBFSelectionSettings::rule::nearest;
}


void Foam::dcpRBFControlPoints::swap
(
    const dcpRBFQualityRegion::summary& q,
    label& nAdded,
    label& nRemoved
)
{
    nAdded = 0;
    nRemoved = 0;
    const dcpRBFSelectionSettings& s = settings_.selection();
    if (s.selection != dcpRBFSelectionSettings::mode::dynamic || s.swapRule != dcpRBFSelectionSettings::rule::nearest)
    {
        return;
    }
    const auto leaveNear = [&](const dcpRBFRankedCell& c)
    {
        if (set_.removeNearest(c.centre()) < 0) return false;
        updated_ = true;
        return true;
    };
    const label n = min(s.nSwap, min(q.worst.size(), q.best.size()));
    for (label k = 0; k < n; ++k)
    {
        if (set_.size() < s.maxPoints)
        {
            nAdded += addNear(q.worst[k]);
            nRemoved += leaveNear(q.best[k]);
        }
        else if
        (
            // at maxPoints: both in one update, at constant size
            set_.swapNearest
            (
                q.worst[k].centre(), q.best[k].centre()
            )
        )
        {
            ++nAdded;
            ++nRemoved;
            updated_ = true;
        }
    }
}


bool Foam::dcpRBFControlPoints::canTrial(const bool rescue) const
{
    const dcpRBFSelectionSettings& s = settings_.selection();
    return
        ready_ && (rescue || (!blend_.active() && !schedule_.waiting())) && s.nSwap > 0
     && s.selection == dcpRBFSelectionSettings::mode::dynamic
     && s.swapRule == dcpRBFSelectionSettings::rule::errorGuided;
}


bool Foam::dcpRBFControlPoints::proposeSwap
(
    const dcpRBFRankedCell& worst,
    const dcprbf::Values& d,
    const label skip
)
{
    // Joining: near the worst cell, among the joinNeighbours nearest
    // candidates, the one of largest error / distance
    static const int joinNeighbours = 8;
    const scalar dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    const Eigen::Index in = set_.mostInaccurateNear(worst.centre(), d, joinNeighbours, 1e-9*dMax);
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
    std::unique_ptr<dcprbf::DynamicControlSet::State> before
    (
        new dcprbf::DynamicControlSet::State(set_.state())
    );
    label skipped = 0;
    for (const Eigen::Index out : order)
    {
        if (skipped++ < skip)
        {
            continue;
        }
        if (set_.swap(in, out))
        {
            // where the interpolant loses a centre: its reach is the
            // distance to the nearest remaining control point
            leaving_ = boundary_.points().row(out);
            leavingReach_ = GREAT;
            for (const Eigen::Index j : set_.indices())
            {
                leavingReach_ = min
                (
                    leavingReach_,
                    (boundary_.points().row(j) - leaving_).norm()
                );
            }
            if (!stepFrom_)
            {
                stepFrom_.reset(new dcprbf::DynamicControlSet::State(*before));
                nKept_ = 0;
            }
            trialFrom_ = std::move(before);
            return true;
        }
    }
    return false;
}


void Foam::dcpRBFControlPoints::keepSwap()
{
    trialFrom_.reset();
    ++nKept_;
    updated_ = true;
}


void Foam::dcpRBFControlPoints::undoSwap(const dcprbf::Values& d)
{
    set_.restore(*trialFrom_);
    trialFrom_.reset();
    solve(d);
}


Foam::label Foam::dcpRBFControlPoints::endTrials
(
    const dcprbf::Values& d,
    const bool blend
)
{
    if (!stepFrom_)
    {
        return 0;
    }
    const label kept = nKept_;
    nKept_ = 0;
    if (kept == 0)
    {
        // the set fits the motion: try again later, less often while it does
        stepFrom_.reset();
        schedule_.backOff();
        return 0;
    }
    // stepFrom_ stays until endStep() (the swaps confirmed: the back-off
    // starts over) or abandonSwaps()
    if (blend && settings_.selection().swapBlendSteps > 1)
    {
        blend_.start(*stepFrom_);
        solve(d);
    }
    return kept;
}


void Foam::dcpRBFControlPoints::abandonSwaps(const dcprbf::Values& d)
{
    if (!stepFrom_)
    {
        return;
    }
    set_.restore(*stepFrom_);
    stepFrom_.reset();
    blend_.stop();
    updated_ = true;
    schedule_.backOff();
    solve(d);
}


Foam::dcpRBFControlPoints::blendState
Foam::dcpRBFControlPoints::finishBlend(const dcprbf::Values& d)
{
    blendState b(blend_.take());
    updated_ = true;
    solve(d);
    return b;
}


void Foam::dcpRBFControlPoints::resumeBlend
(
    blendState&& b,
    const dcprbf::Values& d
)
{
    blend_.resume(std::move(b));
    updated_ = true;
    solve(d);
}


// ************************************************************************* //
