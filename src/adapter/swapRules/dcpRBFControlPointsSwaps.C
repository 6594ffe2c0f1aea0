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
    return trials_.propose(worst, d, skip);
}


void Foam::dcpRBFControlPoints::keepSwap()
{
    trials_.keep();
    updated_ = true;
}


void Foam::dcpRBFControlPoints::undoSwap(const dcprbf::Values& d)
{
    trials_.undo();
    solve(d);
}


Foam::label Foam::dcpRBFControlPoints::endTrials
(
    const dcprbf::Values& d,
    const bool blend
)
{
    if (!trials_.started())
    {
        return 0;
    }
    const label kept = trials_.end();
    if (kept == 0)
    {
        // the set fits the motion: try again later, less often while it does
        schedule_.backOff();
        return 0;
    }
    // the trials stay started until endStep() (the swaps confirmed: the
    // back-off starts over) or abandonSwaps()
    if (blend && settings_.selection().swapBlendSteps > 1)
    {
        blend_.start(trials_.stepStart());
        solve(d);
    }
    return kept;
}


void Foam::dcpRBFControlPoints::abandonSwaps(const dcprbf::Values& d)
{
    if (!trials_.started())
    {
        return;
    }
    trials_.abandon();
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
