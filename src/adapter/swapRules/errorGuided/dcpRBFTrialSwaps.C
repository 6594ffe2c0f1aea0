/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFTrialSwaps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFTrialSwaps::dcpRBFTrialSwaps(dcprbf::DynamicControlSet& set)
:
    set_(set),
    nKept_(0),
    leaving_(Eigen::RowVector3d::Zero()),
    leavingReach_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dcpRBFTrialSwaps::propose
(
    const dcpRBFRankedCell& worst,
    const dcprbf::Values& d,
    const label skip
)
{
    // Joining: near the worst cell, among the joinNeighbours nearest
    // candidates, the one of largest error / distance
    const scalar dMax = d.rows() ? d.rowwise().norm().maxCoeff() : 0;
    const Eigen::Index in =
        set_.mostInaccurateNear(worst.centre(), d, joinNeighbours, 1e-9*dMax);
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
    std::unique_ptr<setState> before(new setState(set_.state()));
    label skipped = 0;
    for (const Eigen::Index out : order)
    {
        if (skipped++ < skip || !set_.swap(in, out))
        {
            continue;
        }
        // where the interpolant loses a centre: its reach is the distance
        // to the nearest remaining control point
        const dcprbf::Points& candidates = set_.candidates();
        leaving_ = candidates.row(out);
        leavingReach_ = GREAT;
        for (const Eigen::Index j : set_.indices())
        {
            leavingReach_ =
                min(leavingReach_, (candidates.row(j) - leaving_).norm());
        }
        if (!stepFrom_)
        {
            stepFrom_.reset(new setState(*before));
            nKept_ = 0;
        }
        trialFrom_ = std::move(before);
        return true;
    }
    return false;
}


void Foam::dcpRBFTrialSwaps::keep()
{
    trialFrom_.reset();
    ++nKept_;
}


void Foam::dcpRBFTrialSwaps::undo()
{
    set_.restore(*trialFrom_);
    trialFrom_.reset();
}


Foam::label Foam::dcpRBFTrialSwaps::end()
{
    const label kept = nKept_;
    nKept_ = 0;
    if (kept == 0)
    {
        stepFrom_.reset();
    }
    return kept;
}


void Foam::dcpRBFTrialSwaps::abandon()
{
    set_.restore(*stepFrom_);
    stepFrom_.reset();
}


// ************************************************************************* //
