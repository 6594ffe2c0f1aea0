/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFNearestSwaps.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dcpRBFNearestSwaps, 0);
    addNamedToRunTimeSelectionTable
    (
        dcpRBFSwapRule, dcpRBFNearestSwaps, context, nearest
    );

    defineTypeNameAndDebug(dcpRBFNearestSettings, 0);
    addToRunTimeSelectionTable
    (
        dcpRBFSwapRuleSettings, dcpRBFNearestSettings, dictionary
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFNearestSwaps::dcpRBFNearestSwaps
(
    const dcpRBFContext& context,
    dcpRBFControlPoints& controlPoints,
    dcpRBFQualityMeasurement& quality,
    dcpRBFInterpolation& interpolation
)
:
    dcpRBFSwapRule(context, controlPoints, quality, interpolation)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dcpRBFNearestSwaps::swapAt
(
    const dcpRBFRankedCell& worst,
    const dcpRBFRankedCell& best,
    dcpRBFStepState& step
)
{
    dcprbf::DynamicControlSet& set = controlPoints_.set();
    if (set.size() < context_.settings().selection().maxPoints)
    {
        step.nAdded += controlPoints_.addNear(worst);
        if (set.removeNearest(best.centre()) >= 0)
        {
            controlPoints_.setChanged();
            ++step.nRemoved;
        }
    }
    else if (set.swapNearest(worst.centre(), best.centre()))
    {
        // at maxPoints: both in one update, at constant size
        ++step.nAdded;
        ++step.nRemoved;
        controlPoints_.setChanged();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::dcpRBFNearestSwaps::lowestCells(const label) const
{
    return -1;
}


void Foam::dcpRBFNearestSwaps::beforeSolve(dcpRBFStepState& step)
{
    if (!controlPoints_.ready())
    {
        return;
    }
    const dcpRBFQualityRegion::summary& q = quality_.current();
    if (q.minQuality >= 1 - 1e-12)
    {
        return;
    }
    const label n =
        min
        (
            context_.settings().selection().nSwap,
            min(q.worst.size(), q.best.size())
        );
    for (label k = 0; k < n; ++k)
    {
        swapAt(q.worst[k], q.best[k], step);
    }
}


// ************************************************************************* //
