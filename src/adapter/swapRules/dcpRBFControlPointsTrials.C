/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFControlPoints, continued: the trial swaps of swapRule errorGuided
    (propose, keep, undo) and the start and end of their blend.
\*---------------------------------------------------------------------------*/

#include "dcpRBFControlPoints.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFControlPoints::canTrial(const bool rescue) const
{
    const dcpRBFSelectionSettings& s = settings_.selection();
    return
        ready_ && (rescue || (!blendFrom_ && trialWait_ == 0)) && s.nSwap > 0
     && s.selection == dcpRBFSelectionSettings::mode::dynamic
     && s.swapRule == dcpRBFSelectionSettings::rule::errorGuided;
}


bool Foam::dcpRBFControlPoints::endWaitIfWorse(const scalar minQuality)
{
    if
    (
        trialWait_ > 0
     && trialQuality_ - minQuality > settings_.selection().trialQualityDrop
    )
    {
        // the mesh has got worse since the set was found to fit it
        trialWait_ = 0;
        return true;
    }
    return false;
}


bool Foam::dcpRBFControlPoints::proposeSwap
(
    const dcpRBFQualityRegion::rankedCell& worst,
    const dcprbf::Values& d,
    const label skip
)
{
    // Joining: near the worst cell, among the joinNeighbours nearest
    // candidates, the one of largest error / distance
    static const int joinNeighbours = 8;
    const scalar dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    const Eigen::RowVector3d x(worst[1], worst[2], worst[3]);
    const Eigen::Index in = set_.mostInaccurateNear(x, d, joinNeighbours, 1e-9*dMax);
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
        backOff();
        return 0;
    }
    // stepFrom_ stays until endStep() (the swaps confirmed: the back-off
    // starts over) or abandonSwaps()
    if (blend && settings_.selection().swapBlendSteps > 1)
    {
        blendFrom_.reset(new dcprbf::DynamicControlSet::State(*stepFrom_));
        blendStep_ = 1;
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
    blendFrom_.reset();
    updated_ = true;
    backOff();
    solve(d);
}


Foam::dcpRBFControlPoints::blendState
Foam::dcpRBFControlPoints::finishBlend(const dcprbf::Values& d)
{
    blendState b;
    b.from = std::move(blendFrom_);
    b.step = blendStep_;
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
    blendFrom_ = std::move(b.from);
    blendStep_ = b.step;
    updated_ = true;
    solve(d);
}


void Foam::dcpRBFControlPoints::backOff()
{
    trialWait_ = trialBackoff_;
    backedOff_ = true;
    trialBackoff_ =
        min(2*trialBackoff_, dcpRBFSelectionSettings::maxTrialWait);
}

// ************************************************************************* //
